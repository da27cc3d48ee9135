package org.tensim.solver.prefactored;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Where {@link SubtreeSolve} cuts the elimination tree of a {@link SparseCholesky} factor: from the roots, the
 * heaviest subtree of the frontier (work = entries of L) is moved to the top and its children become frontier
 * subtrees, and the frontier is dealt into {@link SubtreeSolve#GROUPS} groups, the heaviest first to the lighter
 * group; of these steps, until the top alone weighs more than the best so far, the one with the least
 * {@code max(group) + top} is kept. A column that the factor's solves pair with its parent (a block of two) is
 * moved to the top with it, so that no pair straddles a subtree and the top.
 *
 * @param top   per column: whether it is in the top (the separators, solved by the calling thread)
 * @param group per column: its group, or -1 for a top column
 */
record TreeSplit(boolean[] top, int[] group) {
    /**
     * @param lp         the factor's column pointers (column j's entries are {@code lp[j] .. lp[j + 1] - 1}, its
     *                   diagonal first)
     * @param li         the entries' rows
     * @param blockStart the factor's blocks of one or two columns ({@code blockStart[blocks] = n})
     */
    static TreeSplit of(int n, int[] lp, int[] li, int[] blockStart, int blocks) {
        int[] blockOf = new int[n];
        for (int b = 0; b < blocks; b++) {
            for (int j = blockStart[b]; j < blockStart[b + 1]; j++) {
                blockOf[j] = b;
            }
        }
        int[] parent = new int[n];
        long[] sub = new long[n]; // work of the subtree of j
        int[] childCount = new int[n + 1];
        for (int j = 0; j < n; j++) {
            parent[j] = lp[j + 1] - lp[j] > 1 ? li[lp[j] + 1] : -1;
            sub[j] += lp[j + 1] - lp[j];
            if (parent[j] >= 0) {
                sub[parent[j]] += sub[j];
                childCount[parent[j]]++;
            }
        }
        int[] childStart = new int[n + 1];
        for (int j = 0; j < n; j++) {
            childStart[j + 1] = childStart[j] + childCount[j];
        }
        int[] children = new int[childStart[n]];
        int[] fill = Arrays.copyOf(childStart, n);
        for (int j = 0; j < n; j++) {
            if (parent[j] >= 0) {
                children[fill[parent[j]]++] = j;
            }
        }

        // Choose the frontier.
        boolean[] top = new boolean[n];
        List<Integer> frontier = new ArrayList<>();
        for (int j = 0; j < n; j++) {
            if (parent[j] < 0) {
                frontier.add(j);
            }
        }
        long topSum = 0;
        long bestCost = Long.MAX_VALUE;
        boolean[] bestTop = null;
        int[] bestFrontier = null;
        while (!frontier.isEmpty() && topSum < bestCost) {
            long[] load = deal(frontier, sub, null);
            long cost = cost(load) + topSum;
            if (cost < bestCost) {
                bestCost = cost;
                bestTop = top.clone();
                bestFrontier = frontier.stream().mapToInt(Integer::intValue).toArray();
            }
            int heaviest = 0;
            for (int f = 1; f < frontier.size(); f++) {
                if (sub[frontier.get(f)] > sub[frontier.get(heaviest)]) {
                    heaviest = f;
                }
            }
            topSum += expand(frontier.remove(heaviest), frontier, top, lp, children, childStart, blockOf);
        }
        top = bestTop;
        List<Integer> chosen = new ArrayList<>();
        for (int f : bestFrontier) {
            chosen.add(f);
        }
        int[] groupOfRoot = new int[n];
        deal(chosen, sub, groupOfRoot);
        int[] group = new int[n];
        for (int j = n - 1; j >= 0; j--) {
            group[j] = top[j] ? -1 : parent[j] < 0 || top[parent[j]] ? groupOfRoot[j] : group[parent[j]];
        }
        return new TreeSplit(top, group);
    }

    /**
     * Moves frontier subtree f to the top and its children to the frontier (a child solved in a pair with f
     * goes to the top too); returns the work moved to the top.
     */
    private static long expand(int f, List<Integer> frontier, boolean[] top, int[] lp, int[] children,
            int[] childStart, int[] blockOf) {
        top[f] = true;
        long moved = lp[f + 1] - lp[f];
        for (int c = childStart[f]; c < childStart[f + 1]; c++) {
            int child = children[c];
            if (blockOf[child] == blockOf[f]) {
                moved += expand(child, frontier, top, lp, children, childStart, blockOf);
            } else {
                frontier.add(child);
            }
        }
        return moved;
    }

    /**
     * The groups' time on two threads that claim them as they come (entries of L): at least half their work,
     * and at least the largest group.
     */
    private static long cost(long[] load) {
        long sum = 0;
        long max = 0;
        for (long l : load) {
            sum += l;
            max = Math.max(max, l);
        }
        return Math.max(max, (sum + 1) / 2);
    }

    /** Deals the subtrees to two groups, heaviest first to the lighter; returns the groups' work. */
    private static long[] deal(List<Integer> roots, long[] sub, int[] groupOf) {
        Integer[] order = roots.toArray(new Integer[0]);
        Arrays.sort(order, (a, b) -> Long.compare(sub[b], sub[a]));
        long[] load = new long[SubtreeSolve.GROUPS];
        for (int f : order) {
            int g = 0;
            for (int h = 1; h < load.length; h++) {
                if (load[h] < load[g]) {
                    g = h;
                }
            }
            load[g] += sub[f];
            if (groupOf != null) {
                groupOf[f] = g;
            }
        }
        return load;
    }
}
