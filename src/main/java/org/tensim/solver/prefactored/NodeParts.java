package org.tensim.solver.prefactored;

import java.util.Arrays;

/**
 * The free nodes of an implicit step (compact numbering) cut into parts that own disjoint node sets, for
 * products on several threads with the one-thread bits (owner computes, as the force pass's
 * {@code ParallelSpringPass}): part k writes only the nodes it owns and goes through the elements that touch
 * them in the global order, so each node receives its elements' terms in the order and with the operations of
 * the one-thread loop. An element two parts touch is computed by both, each keeping its own nodes.
 *
 * <p>The nodes are cut by their rest x into slabs of equal work (given per node), so that few elements cross
 * a cut. Arrays allocated once.
 */
final class NodeParts {
    /** Per free node (compact index): its part. */
    final int[] owner;
    private final int parts;

    /**
     * @param restX per free node (compact index): its rest x, m
     * @param work  per free node: the work of its share of a product (any unit; e.g. the elements' nodes at it)
     * @param parts parts, >= 1
     */
    NodeParts(double[] restX, long[] work, int parts) {
        int n = restX.length;
        Integer[] order = new Integer[n];
        for (int j = 0; j < n; j++) {
            order[j] = j;
        }
        Arrays.sort(order, (a, b) -> Double.compare(restX[a], restX[b]));
        long total = 0;
        for (long w : work) {
            total += w;
        }
        owner = new int[n];
        long sum = 0;
        for (int j : order) {
            owner[j] = (int) Math.min(parts - 1, sum * parts / Math.max(1, total));
            sum += work[j];
        }
        this.parts = parts;
    }

    /** Parts. */
    int parts() {
        return parts;
    }
}
