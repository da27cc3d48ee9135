package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;

/** Test checks on a mesh's edges. */
public final class MeshEdges {
    private MeshEdges() {
    }

    /**
     * Directed edge uses: each directed edge at most once (consistent winding, at most two triangles per edge).
     * Returns {edges used once, edges used twice}; fails on anything else.
     */
    public static int[] manifold(TriangleMesh m) {
        Map<Long, Integer> directed = new HashMap<>();
        long n = m.vertexCount();
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                int a = m.corner(t, k);
                int b = m.corner(t, (k + 1) % 3);
                assertTrue(a != b, "triangle " + t + " is degenerate");
                Integer old = directed.put(a * n + b, t);
                assertTrue(old == null, "directed edge " + a + "-" + b + " in triangles " + old + " and " + t
                        + ": folded or inconsistently wound");
            }
        }
        int once = 0;
        int twice = 0;
        for (long e : directed.keySet()) {
            long a = e / n;
            long b = e % n;
            if (directed.containsKey(b * n + a)) {
                twice++;
            } else {
                once++;
            }
        }
        return new int[] {once, twice / 2};
    }
}
