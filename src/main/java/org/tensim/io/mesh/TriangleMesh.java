package org.tensim.io.mesh;

import java.util.Arrays;

/**
 * An indexed triangle mesh in metres: vertex coordinates (3 doubles per vertex,
 * interleaved) and triangles (3 vertex indices each, counter-clockwise seen from
 * the side the normal points to). Immutable once built: arrays are copied in and
 * out.
 */
public final class TriangleMesh {
    private final double[] xyz;
    private final int[] tri;

    /**
     * @param xyzMetres vertex coordinates, m, length 3 * vertices, all finite
     * @param triangles vertex indices, length 3 * triangles, each in range
     */
    public TriangleMesh(double[] xyzMetres, int[] triangles) {
        if (xyzMetres.length % 3 != 0 || triangles.length % 3 != 0) {
            throw new IllegalArgumentException("mesh arrays must hold whole triples, got " + xyzMetres.length
                    + " coordinates and " + triangles.length + " indices");
        }
        for (int i = 0; i < xyzMetres.length; i++) {
            if (!Double.isFinite(xyzMetres[i])) {
                throw new IllegalArgumentException("mesh vertex " + i / 3 + " has a non-finite coordinate "
                        + xyzMetres[i]);
            }
        }
        int nv = xyzMetres.length / 3;
        for (int i = 0; i < triangles.length; i++) {
            if (triangles[i] < 0 || triangles[i] >= nv) {
                throw new IllegalArgumentException("mesh triangle " + i / 3 + " refers to vertex " + triangles[i]
                        + ": expected 0 <= index < " + nv);
            }
        }
        this.xyz = xyzMetres.clone();
        this.tri = triangles.clone();
    }

    public int vertexCount() {
        return xyz.length / 3;
    }

    public int triangleCount() {
        return tri.length / 3;
    }

    /** Coordinate {@code axis} (0 x, 1 y, 2 z) of vertex v, m. */
    public double coord(int v, int axis) {
        return xyz[3 * v + axis];
    }

    /** Vertex index {@code corner} (0..2) of triangle t. */
    public int corner(int t, int corner) {
        return tri[3 * t + corner];
    }

    /** A copy of the coordinates, m. */
    public double[] coordinates() {
        return xyz.clone();
    }

    /** A copy of the triangle indices. */
    public int[] triangles() {
        return tri.clone();
    }

    /** Axis-aligned bounds {min x, min y, min z, max x, max y, max z}, m. */
    public double[] bounds() {
        double[] b = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int v = 0; v < vertexCount(); v++) {
            for (int a = 0; a < 3; a++) {
                b[a] = Math.min(b[a], xyz[3 * v + a]);
                b[a + 3] = Math.max(b[a + 3], xyz[3 * v + a]);
            }
        }
        return b;
    }

    /** Area of triangle t, m^2. */
    public double area(int t) {
        double[] n = new double[3];
        normal(t, n);
        return 0.5 * Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }

    /** Writes the unnormalised normal (b - a) x (c - a) of triangle t (length = twice the area) into n. */
    public void normal(int t, double[] n) {
        int a = 3 * tri[3 * t];
        int b = 3 * tri[3 * t + 1];
        int c = 3 * tri[3 * t + 2];
        double ux = xyz[b] - xyz[a];
        double uy = xyz[b + 1] - xyz[a + 1];
        double uz = xyz[b + 2] - xyz[a + 2];
        double vx = xyz[c] - xyz[a];
        double vy = xyz[c + 1] - xyz[a + 1];
        double vz = xyz[c + 2] - xyz[a + 2];
        n[0] = uy * vz - uz * vy;
        n[1] = uz * vx - ux * vz;
        n[2] = ux * vy - uy * vx;
    }

    /** Total area, m^2. */
    public double totalArea() {
        double s = 0;
        for (int t = 0; t < triangleCount(); t++) {
            s += area(t);
        }
        return s;
    }

    /** Edges used by exactly one triangle (the rims of holes); 0 for a closed surface. */
    public int boundaryEdgeCount() {
        java.util.Map<Long, Integer> uses = new java.util.HashMap<>();
        for (int t = 0; t < triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                long a = corner(t, k);
                long c = corner(t, (k + 1) % 3);
                uses.merge(Math.min(a, c) << 32 | Math.max(a, c), 1, Integer::sum);
            }
        }
        int open = 0;
        for (int u : uses.values()) {
            open += u == 1 ? 1 : 0;
        }
        return open;
    }

    /**
     * The volume the triangles enclose by the divergence theorem, {@code sum_t a . (b x c) / 6}, m^3: positive for a
     * closed surface wound counter-clockwise seen from outside, negative when wound inwards; for an open surface it
     * depends on the origin and means little.
     */
    public double signedVolume() {
        double v = 0;
        for (int t = 0; t < triangleCount(); t++) {
            int a = 3 * tri[3 * t];
            int b = 3 * tri[3 * t + 1];
            int c = 3 * tri[3 * t + 2];
            v += xyz[a] * (xyz[b + 1] * xyz[c + 2] - xyz[b + 2] * xyz[c + 1])
                    - xyz[a + 1] * (xyz[b] * xyz[c + 2] - xyz[b + 2] * xyz[c])
                    + xyz[a + 2] * (xyz[b] * xyz[c + 1] - xyz[b + 1] * xyz[c]);
        }
        return v / 6;
    }

    @Override
    public String toString() {
        return "TriangleMesh[" + vertexCount() + " vertices, " + triangleCount() + " triangles, bounds (m) "
                + Arrays.toString(bounds()) + "]";
    }
}
