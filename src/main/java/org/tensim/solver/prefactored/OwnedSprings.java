package org.tensim.solver.prefactored;

import java.util.Arrays;

/**
 * The springs of a {@link SpringJacobian}'s product cut among parts that own disjoint sets of free nodes, for
 * a product on several threads with the one-thread bits (owner computes, as the force pass's
 * {@code ParallelSpringPass}): part k writes only the nodes it owns, and goes through the springs that touch
 * them in the global order, so each node receives its springs' terms in the order and with the operations of
 * the one-thread loop. A spring whose ends two parts own is computed by both, each keeping its own end.
 *
 * <p>The nodes are cut by their rest x into slabs of equal work (springs' ends, plus one per node), so that
 * few springs cross a cut. Arrays allocated once.
 */
final class OwnedSprings {
    /** Per part: its nodes (compact index, increasing). */
    final int[][] nodes;
    /**
     * Per part: the springs it goes through, in increasing order, each as {@code 4 i + ends}: bit 0 of ends
     * set when the part owns end a, bit 1 when it owns end b.
     */
    final int[][] springs;

    /**
     * @param endA  per spring: 3 x compact index of end a, -1 when not free
     * @param endB  the same for end b
     * @param restX per free node (compact index): its rest x, m
     * @param parts parts, >= 1
     */
    OwnedSprings(int[] endA, int[] endB, double[] restX, int parts) {
        int n = restX.length;
        long[] work = new long[n];
        Arrays.fill(work, 1);
        for (int i = 0; i < endA.length; i++) {
            if (endA[i] >= 0) {
                work[endA[i] / 3]++;
            }
            if (endB[i] >= 0) {
                work[endB[i] / 3]++;
            }
        }
        Integer[] order = new Integer[n];
        for (int j = 0; j < n; j++) {
            order[j] = j;
        }
        Arrays.sort(order, (a, b) -> Double.compare(restX[a], restX[b]));
        long total = 0;
        for (long w : work) {
            total += w;
        }
        int[] owner = new int[n];
        long sum = 0;
        for (int j : order) {
            owner[j] = (int) Math.min(parts - 1, sum * parts / Math.max(1, total));
            sum += work[j];
        }
        nodes = new int[parts][];
        springs = new int[parts][];
        for (int k = 0; k < parts; k++) {
            int count = 0;
            for (int j = 0; j < n; j++) {
                if (owner[j] == k) {
                    count++;
                }
            }
            nodes[k] = new int[count];
            count = 0;
            for (int j = 0; j < n; j++) {
                if (owner[j] == k) {
                    nodes[k][count++] = j;
                }
            }
            int[] list = new int[endA.length];
            count = 0;
            for (int i = 0; i < endA.length; i++) {
                int ends = (endA[i] >= 0 && owner[endA[i] / 3] == k ? 1 : 0)
                        | (endB[i] >= 0 && owner[endB[i] / 3] == k ? 2 : 0);
                if (ends != 0) {
                    list[count++] = 4 * i + ends;
                }
            }
            springs[k] = Arrays.copyOf(list, count);
        }
    }

    /** Parts. */
    int parts() {
        return nodes.length;
    }

    /** Spring terms computed, over all parts (the springs with a free end, plus those computed twice). */
    int springTerms() {
        int sum = 0;
        for (int[] s : springs) {
            sum += s.length;
        }
        return sum;
    }
}
