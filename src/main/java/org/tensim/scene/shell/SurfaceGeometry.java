package org.tensim.scene.shell;

import org.tensim.io.mesh.TriangleMesh;

/** Per-vertex geometry of triangle meshes: normals and area shares (package-private helpers). */
public final class SurfaceGeometry {
    private SurfaceGeometry() {
    }

    /** Area-weighted unit vertex normals (3 per vertex), following the triangles' winding. */
    public static double[] vertexNormals(TriangleMesh m) {
        double[] acc = new double[3 * m.vertexCount()];
        double[] n = new double[3];
        for (int t = 0; t < m.triangleCount(); t++) {
            m.normal(t, n); // length = twice the area: area weighting for free
            for (int k = 0; k < 3; k++) {
                int v = m.corner(t, k);
                acc[3 * v] += n[0];
                acc[3 * v + 1] += n[1];
                acc[3 * v + 2] += n[2];
            }
        }
        for (int v = 0; v < m.vertexCount(); v++) {
            double l = Math.sqrt(acc[3 * v] * acc[3 * v] + acc[3 * v + 1] * acc[3 * v + 1]
                    + acc[3 * v + 2] * acc[3 * v + 2]);
            if (l > 0) {
                acc[3 * v] /= l;
                acc[3 * v + 1] /= l;
                acc[3 * v + 2] /= l;
            }
        }
        return acc;
    }

    /** Each vertex's share of the area: a third of the area of every triangle it belongs to, m^2. */
    public static double[] vertexAreas(TriangleMesh m) {
        double[] a = new double[m.vertexCount()];
        for (int t = 0; t < m.triangleCount(); t++) {
            double third = m.area(t) / 3;
            for (int k = 0; k < 3; k++) {
                a[m.corner(t, k)] += third;
            }
        }
        return a;
    }
}
