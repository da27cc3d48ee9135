package org.tensim.solver;

import java.util.Arrays;
import org.tensim.model.Check;

/**
 * A partition of the membrane triangles of a {@link SystemState} for lock-free passes on several
 * threads: the nodes the triangles use are cut into {@code blocks} slabs along x (equal counts, by
 * rest position); a triangle whose six nodes (the two of each midpoint corner) all lie in one slab
 * belongs to it, the others form the seam. Slabs have disjoint node sets, so they can add into one
 * force (or product) array at the same time; the seam (a few percent) is added afterwards by one
 * thread. The partition depends on the rest positions only, never on the thread count, so every
 * node sums its triangles in the same order with one thread or several.
 */
public final class TriangleSlabs {
    private TriangleSlabs() {
    }

    /**
     * The block of every triangle: its slab in {@code [0, blocks)}, or {@code blocks} for the seam.
     *
     * @param blocks number of slabs, >= 1
     */
    public static int[] blockOf(SystemState s, int blocks) {
        return blockOf(s, nodeSlabs(s, blocks), blocks);
    }

    /**
     * The block of every triangle for the node slabs {@code slab} of {@link #nodeSlabs}: the slab of
     * its nodes when they share one, else {@code blocks} (the seam).
     */
    public static int[] blockOf(SystemState s, int[] slab, int blocks) {
        int[] block = new int[s.triangleCount()];
        for (int e = 0; e < block.length; e++) {
            int b = slab[s.triP[3 * e]];
            for (int k = 0; k < 3; k++) {
                if (slab[s.triP[3 * e + k]] != b || slab[s.triQ[3 * e + k]] != b) {
                    b = blocks; // the seam
                }
            }
            block[e] = b;
        }
        return block;
    }

    /**
     * The slab of each node used by a triangle, in {@code [0, blocks)} (x-quantiles of the rest
     * positions: equal counts), -1 for the nodes no triangle uses.
     *
     * @param blocks number of slabs, >= 1
     */
    public static int[] nodeSlabs(SystemState s, int blocks) {
        Check.atLeast("triangle slabs", blocks, 1);
        int[] slab = new int[s.nodeCount];
        Arrays.fill(slab, -1);
        boolean[] used = new boolean[s.nodeCount];
        int n = 0;
        for (int k = 0; k < s.triP.length; k++) {
            for (int node : new int[] {s.triP[k], s.triQ[k]}) {
                if (!used[node]) {
                    used[node] = true;
                    n++;
                }
            }
        }
        Integer[] order = new Integer[n];
        for (int i = 0, j = 0; i < s.nodeCount; i++) {
            if (used[i]) {
                order[j++] = i;
            }
        }
        Arrays.sort(order, (a, b) -> Double.compare(s.x0[3 * a], s.x0[3 * b]));
        for (int j = 0; j < n; j++) {
            slab[order[j]] = (int) ((long) j * blocks / n);
        }
        return slab;
    }
}
