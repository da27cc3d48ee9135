package org.tensim.io.mesh;

import java.util.Arrays;

/** Growable vertex and triangle arrays used by the readers (package-private). */
final class MeshBuilder {
    private double[] xyz = new double[3 * 1024];
    private int nCoords;
    private int[] tri = new int[3 * 2048];
    private int nIdx;

    int vertexCount() {
        return nCoords / 3;
    }

    int triangleCount() {
        return nIdx / 3;
    }

    void vertex(double x, double y, double z) {
        if (nCoords + 3 > xyz.length) {
            xyz = Arrays.copyOf(xyz, 2 * xyz.length);
        }
        xyz[nCoords++] = x;
        xyz[nCoords++] = y;
        xyz[nCoords++] = z;
    }

    void triangle(int a, int b, int c) {
        if (nIdx + 3 > tri.length) {
            tri = Arrays.copyOf(tri, 2 * tri.length);
        }
        tri[nIdx++] = a;
        tri[nIdx++] = b;
        tri[nIdx++] = c;
    }

    /** The mesh with coordinates multiplied by {@code scale} (file units to metres). */
    TriangleMesh build(double scale) {
        double[] c = Arrays.copyOf(xyz, nCoords);
        for (int i = 0; i < c.length; i++) {
            c[i] *= scale;
        }
        return new TriangleMesh(c, Arrays.copyOf(tri, nIdx));
    }
}
