package org.tensim.io.mesh;

/** Flat test meshes whose integrals and interpolations are known exactly. */
public final class FlatMeshes {
    private FlatMeshes() {
    }

    /** The square [-l, l]^2 at z = 0 (m) cut into n x n squares, two counter-clockwise triangles each. */
    public static TriangleMesh square(double l, int n) {
        double[] xyz = new double[3 * (n + 1) * (n + 1)];
        int[] tri = new int[6 * n * n];
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                int v = i * (n + 1) + j;
                xyz[3 * v] = -l + 2 * l * j / n;
                xyz[3 * v + 1] = -l + 2 * l * i / n;
            }
        }
        for (int i = 0, k = 0; i < n; i++) {
            for (int j = 0; j < n; j++, k += 6) {
                int a = i * (n + 1) + j;
                System.arraycopy(new int[] {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1}, 0, tri, k, 6);
            }
        }
        return new TriangleMesh(xyz, tri);
    }
}
