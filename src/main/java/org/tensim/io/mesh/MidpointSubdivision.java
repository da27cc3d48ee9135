package org.tensim.io.mesh;

import java.util.HashMap;
import java.util.Map;

/**
 * Mesh refinement by midpoint subdivision: every triangle becomes four, through a new
 * vertex at the middle of each edge (shared by the edge's two triangles). The surface does
 * not move (no smoothing), so a refined model has exactly the geometry of the coarse one
 * and only the discretisation changes, which is what a convergence study needs. Edge
 * lengths halve; vertices grow about fourfold.
 */
public final class MidpointSubdivision {
    private MidpointSubdivision() {
    }

    /** The mesh subdivided {@code levels} times (0 returns it unchanged). */
    public static TriangleMesh refine(TriangleMesh m, int levels) {
        if (levels < 0) {
            throw new IllegalArgumentException("subdivision levels must be 0 or more, got " + levels);
        }
        TriangleMesh r = m;
        for (int i = 0; i < levels; i++) {
            r = once(r);
        }
        return r;
    }

    private static TriangleMesh once(TriangleMesh m) {
        int nv = m.vertexCount();
        int nt = m.triangleCount();
        double[] xyz = java.util.Arrays.copyOf(m.coordinates(), 3 * (nv + 3 * nt));
        Map<Long, Integer> mid = new HashMap<>();
        int[] tri = new int[12 * nt];
        int next = nv;
        int[] c = new int[3];
        int[] e = new int[3];
        for (int t = 0; t < nt; t++) {
            for (int k = 0; k < 3; k++) {
                c[k] = m.corner(t, k);
            }
            for (int k = 0; k < 3; k++) {
                int a = c[k];
                int b = c[(k + 1) % 3];
                long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                Integer v = mid.get(key);
                if (v == null) {
                    v = next++;
                    mid.put(key, v);
                    for (int x = 0; x < 3; x++) {
                        xyz[3 * v + x] = 0.5 * (m.coord(a, x) + m.coord(b, x));
                    }
                }
                e[k] = v; // midpoint of edge c[k] -> c[k+1]
            }
            // the corner triangles keep the winding; the middle one is (e0, e1, e2)
            int[] four = {c[0], e[0], e[2], c[1], e[1], e[0], c[2], e[2], e[1], e[0], e[1], e[2]};
            System.arraycopy(four, 0, tri, 12 * t, 12);
        }
        return new TriangleMesh(java.util.Arrays.copyOf(xyz, 3 * next), tri);
    }
}
