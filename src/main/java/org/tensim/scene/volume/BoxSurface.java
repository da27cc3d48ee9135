package org.tensim.scene.volume;

import java.util.HashMap;
import java.util.Map;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;

/**
 * The closed triangulated surface of a box [0, lx] x [0, ly] x [0, lz] (m), each face a grid of squares of about
 * the given spacing cut into two triangles, wound counter-clockwise seen from outside, vertices shared along edges:
 * the known-answer volumes' surface (cantilever, compressed block). A finer surface spreads a load applied on it.
 */
public final class BoxSurface {
    private BoxSurface() {
    }

    /**
     * @param spacingM the largest side of a face's squares, m (&gt; 0); each edge gets ceil(length / spacing) parts
     */
    public static TriangleMesh of(double lx, double ly, double lz, double spacingM) {
        double[] len = {Check.positive("box x side", "m", lx), Check.positive("box y side", "m", ly),
            Check.positive("box z side", "m", lz)};
        Check.positive("box surface spacing", "m", spacingM);
        int[] div = new int[3];
        for (int a = 0; a < 3; a++) {
            div[a] = (int) Math.max(1, Math.ceil(len[a] / spacingM * (1 - 1e-12)));
        }
        Map<Long, Integer> ids = new HashMap<>();
        java.util.List<double[]> xyz = new java.util.ArrayList<>();
        java.util.List<int[]> tri = new java.util.ArrayList<>();
        for (int a = 0; a < 3; a++) {
            int u = (a + 1) % 3;
            int v = (a + 2) % 3;
            for (int side = 0; side < 2; side++) {
                for (int i = 0; i < div[u]; i++) {
                    for (int j = 0; j < div[v]; j++) {
                        int[] q = new int[4];
                        int[][] uv = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                        for (int c = 0; c < 4; c++) {
                            int[] g = new int[3];
                            g[a] = side * div[a];
                            g[u] = uv[c][0];
                            g[v] = uv[c][1];
                            q[c] = vertex(g, div, len, ids, xyz);
                        }
                        if (side == 1) {
                            tri.add(new int[] {q[0], q[1], q[2]});
                            tri.add(new int[] {q[0], q[2], q[3]});
                        } else {
                            tri.add(new int[] {q[0], q[2], q[1]});
                            tri.add(new int[] {q[0], q[3], q[2]});
                        }
                    }
                }
            }
        }
        double[] x = new double[3 * xyz.size()];
        for (int p = 0; p < xyz.size(); p++) {
            System.arraycopy(xyz.get(p), 0, x, 3 * p, 3);
        }
        int[] t = new int[3 * tri.size()];
        for (int p = 0; p < tri.size(); p++) {
            System.arraycopy(tri.get(p), 0, t, 3 * p, 3);
        }
        return new TriangleMesh(x, t);
    }

    private static int vertex(int[] g, int[] div, double[] len, Map<Long, Integer> ids, java.util.List<double[]> xyz) {
        long key = ((long) g[0] * (div[1] + 1) + g[1]) * (div[2] + 1) + g[2];
        return ids.computeIfAbsent(key, k -> {
            // the far faces at exactly the side's length, so that a lattice of whole cells fits the box exactly
            xyz.add(new double[] {g[0] == div[0] ? len[0] : g[0] * len[0] / div[0],
                g[1] == div[1] ? len[1] : g[1] * len[1] / div[1], g[2] == div[2] ? len[2] : g[2] * len[2] / div[2]});
            return xyz.size() - 1;
        });
    }
}
