package org.tensim.view;

/** Area-weighted vertex normals of a triangle mesh, allocation-free. */
final class Normals {
    private Normals() {
    }

    /**
     * Writes unit normals into {@code out} (3 per vertex): the sum of the normals of
     * the triangles around each vertex, each weighted by its area (the cross product
     * is twice the area), normalised. Vertices in no triangle get (0, 0, 1).
     */
    static void compute(float[] p, int[] tri, float[] out) {
        java.util.Arrays.fill(out, 0f);
        for (int t = 0; t < tri.length; t += 3) {
            int a = 3 * tri[t];
            int b = 3 * tri[t + 1];
            int c = 3 * tri[t + 2];
            float ux = p[b] - p[a];
            float uy = p[b + 1] - p[a + 1];
            float uz = p[b + 2] - p[a + 2];
            float vx = p[c] - p[a];
            float vy = p[c + 1] - p[a + 1];
            float vz = p[c + 2] - p[a + 2];
            float nx = uy * vz - uz * vy;
            float ny = uz * vx - ux * vz;
            float nz = ux * vy - uy * vx;
            add(out, a, nx, ny, nz);
            add(out, b, nx, ny, nz);
            add(out, c, nx, ny, nz);
        }
        normalise(out);
    }

    private static void add(float[] out, int v, float nx, float ny, float nz) {
        out[v] += nx;
        out[v + 1] += ny;
        out[v + 2] += nz;
    }

    private static void normalise(float[] out) {
        for (int v = 0; v < out.length; v += 3) {
            float len = (float) Math.sqrt(out[v] * out[v] + out[v + 1] * out[v + 1] + out[v + 2] * out[v + 2]);
            if (len > 0) {
                out[v] /= len;
                out[v + 1] /= len;
                out[v + 2] /= len;
            } else {
                out[v + 2] = 1;
            }
        }
    }
}
