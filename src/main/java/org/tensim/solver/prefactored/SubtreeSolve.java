package org.tensim.solver.prefactored;

import java.util.Arrays;
import org.tensim.solver.NodeLoops;

/**
 * The three-coordinate solves of a {@link SparseCholesky} factor on two threads, with the bits of the
 * one-thread column loops: the elimination tree of L is cut into two groups of disjoint subtrees, solved at
 * the same time, and the top of the tree above them (the separators), solved by the calling thread.
 *
 * <p>Why it is exact: in the forward solve {@code L y = b} column j updates only rows that are its ancestors
 * in the elimination tree, and in the backward solve {@code L^T x = y} it reads only those. Two disjoint
 * subtrees therefore do not touch each other's rows; they both touch the top's rows. So:
 *
 * <ol>
 *   <li>forward, the groups on the threads: each group's columns in increasing order, each updating only the
 *       rows of its own subtree (the column's rows below the top; its rows in the top come last, rows being
 *       sorted);
 *   <li>forward, the top rows' prefixes on the threads, in tasks of rows: each top row's right-hand side less
 *       its terms in the groups' columns that come before its first term in a top column, in the columns'
 *       order (the rows are independent of each other here);
 *   <li>forward, the caller: each top row in increasing order, as a row: the rest of its terms in the columns'
 *       order, then the division by its diagonal. The column loop subtracts the same products from row r in
 *       the same order (the columns'), so the bits are the same;
 *   <li>backward, the caller: the top's columns from the last, each reading only its ancestors (the top);
 *   <li>backward, the groups on the threads: their columns from the last, reading their subtree's rows and the
 *       top's, which are final.
 * </ol>
 *
 * Three dispatches per solve, whose tasks go to the threads as they come ({@link NodeLoops#runTasks}); the
 * permutation's scatter and gather are split the same way. Which subtrees: {@link TreeSplit}. On the default
 * diaphragm's factor (635,941 entries): groups of 223,702 and 185,135 entries, a top of 404 columns and 75,742 entries, and 151,362 entries of the groups' columns in top
 * rows, 115,170 of them in the rows' prefixes.
 * Arrays allocated once; a solve allocates nothing.
 */
final class SubtreeSolve {
    /** Tasks of the cut's prefixes (claimed by the threads as they come: a busy core takes fewer). */
    static final int CUT_TASKS = 8;
    /** Entries below which a task of the cut's prefixes is not worth its claim. */
    static final int MIN_CUT_TASK_ENTRIES = 4096;
    /** Groups of subtrees, one per thread of a two-thread solve. */
    static final int GROUPS = 2;

    private final int[] lp;
    private final int[] li;
    private final double[] lx;
    private final int[] bs; // blockStart of the factor
    private final int[] perm; // permuted column j holds original unknown perm[j]
    /** Per group: its blocks in increasing order, and per such block the end of its rows in the group. */
    private final int[][] groupBlocks;
    private final int[][] groupRowEnd;
    private final int[] topBlocks; // increasing
    private final int[] topColumns; // increasing
    private final int[] rowStart; // entries of top row t: [rowStart[t], rowStart[t + 1])
    private final int[] rowColumn; // 3 x column of the entry
    private final int[] rowEntry; // index of the entry in li / lx
    /** Per top row: the end of its entries before its first in a top column (the cut's prefix). */
    private final int[] prefixEnd;
    /** Top rows of the cut's tasks: task i has the rows [cutTaskStart[i], cutTaskStart[i + 1]). */
    private final int[] cutTaskStart;
    private final int cutTasks;
    private final int topWork;
    private final int[] groupWork = new int[GROUPS];
    private final int cutEntries;
    private final int total;

    private final NodeLoops.Body forward = this::forwardGroups;
    private final NodeLoops.Body backward = this::backwardGroups;
    private final NodeLoops.Body cut = this::cutRows;
    private double[] rhs; // during a solve only
    private double[] x;

    /**
     * @param blockStart the factor's blocks of one or two columns ({@code blockStart[blocks] = n})
     * @param pinv       original unknown k sits at column pinv[k]
     */
    SubtreeSolve(int n, int[] lp, int[] li, double[] lx, int[] blockStart, int blocks, int[] pinv) {
        this.lp = lp;
        this.li = li;
        this.lx = lx;
        this.bs = blockStart;
        perm = new int[n];
        for (int k = 0; k < n; k++) {
            perm[pinv[k]] = k;
        }
        TreeSplit split = TreeSplit.of(n, lp, li, blockStart, blocks);
        boolean[] top = split.top();
        int[] group = split.group();
        total = lp[n];

        // Blocks per group, with where their rows in the group end; the top's blocks and columns.
        int[] count = new int[GROUPS + 1];
        for (int b = 0; b < blocks; b++) {
            int g = group[blockStart[b]];
            for (int j = blockStart[b]; j < blockStart[b + 1]; j++) {
                if (group[j] != g) {
                    throw new IllegalStateException("a pair of columns straddles the split at column " + j);
                }
            }
            count[g < 0 ? GROUPS : g]++;
        }
        groupBlocks = new int[GROUPS][];
        groupRowEnd = new int[GROUPS][];
        for (int g = 0; g < GROUPS; g++) {
            groupBlocks[g] = new int[count[g]];
            groupRowEnd[g] = new int[count[g]];
        }
        topBlocks = new int[count[GROUPS]];
        int[] at = new int[GROUPS + 1];
        int cut = 0;
        for (int b = 0; b < blocks; b++) {
            int j = blockStart[b];
            int g = group[j];
            if (g < 0) {
                topBlocks[at[GROUPS]++] = b;
                continue;
            }
            int last = blockStart[b + 1] - 1; // the rows shared by a pair are those of its second column
            int q = lp[last] + 1;
            while (q < lp[last + 1] && !top[li[q]]) {
                q++;
            }
            for (int c = j; c <= last; c++) {
                for (int e = lp[c] + 1; e < lp[c + 1]; e++) {
                    if (top[li[e]]) {
                        cut++;
                    } else {
                        groupWork[g]++;
                    }
                }
                groupWork[g]++; // the diagonal
            }
            groupBlocks[g][at[g]] = b;
            groupRowEnd[g][at[g]++] = q;
        }
        cutEntries = cut;
        int tops = 0;
        int[] topIndex = new int[n];
        for (int j = 0; j < n; j++) {
            topIndex[j] = top[j] ? tops++ : -1;
        }
        topColumns = new int[tops];
        for (int j = 0; j < n; j++) {
            if (top[j]) {
                topColumns[topIndex[j]] = j;
            }
        }
        // The top rows' entries below their diagonal, by row, each row's in increasing column order.
        rowStart = new int[tops + 1];
        for (int j = 0; j < n; j++) {
            for (int q = lp[j] + 1; q < lp[j + 1]; q++) {
                if (top[li[q]]) {
                    rowStart[topIndex[li[q]] + 1]++;
                }
            }
        }
        for (int t = 0; t < tops; t++) {
            rowStart[t + 1] += rowStart[t];
        }
        rowColumn = new int[rowStart[tops]];
        rowEntry = new int[rowStart[tops]];
        int[] next = Arrays.copyOf(rowStart, tops);
        for (int j = 0; j < n; j++) {
            for (int q = lp[j] + 1; q < lp[j + 1]; q++) {
                if (top[li[q]]) {
                    int e = next[topIndex[li[q]]]++;
                    rowColumn[e] = 3 * j;
                    rowEntry[e] = q;
                }
            }
        }
        int tw = 0;
        for (int j : topColumns) {
            tw += lp[j + 1] - lp[j];
        }
        topWork = tw;
        // The cut's prefix of each top row: its entries before its first in a top column, all in the groups'
        // columns; the rows' prefixes are independent of each other, and split into tasks of about equal entries.
        prefixEnd = new int[tops];
        long prefixEntries = 0;
        for (int t = 0; t < tops; t++) {
            int q = rowStart[t];
            while (q < rowStart[t + 1] && !top[rowColumn[q] / 3]) {
                q++;
            }
            prefixEnd[t] = q;
            prefixEntries += q - rowStart[t];
        }
        cutTasks = (int) Math.max(1, Math.min(tops, Math.min(CUT_TASKS, prefixEntries / MIN_CUT_TASK_ENTRIES)));
        cutTaskStart = new int[cutTasks + 1];
        long acc = 0;
        int task = 1;
        for (int t = 0; t < tops && task < cutTasks; t++) {
            acc += prefixEnd[t] - rowStart[t];
            if (acc * cutTasks >= task * prefixEntries) {
                cutTaskStart[task++] = t + 1;
            }
        }
        while (task <= cutTasks) {
            cutTaskStart[task++] = tops;
        }
    }


    /** Entries of L in each group's columns and rows (diagonals included), for the docs' profile and tests. */
    int[] groupEntries() {
        return groupWork.clone();
    }

    /** Entries of the cut's prefixes (solved by the threads between the groups and the top). */
    int prefixEntries() {
        int sum = 0;
        for (int t = 0; t < prefixEnd.length; t++) {
            sum += prefixEnd[t] - rowStart[t];
        }
        return sum;
    }

    /** Entries of L in the top's columns. */
    int topEntries() {
        return topWork;
    }

    /** Entries of the groups' columns in top rows (solved by the caller in the forward solve). */
    int cutEntries() {
        return cutEntries;
    }

    /** Columns in the top. */
    int topColumns() {
        return topColumns.length;
    }

    /** Entries of L. */
    int entries() {
        return total;
    }

    /**
     * Solves {@code A y = b} as {@link SparseCholesky#solve3}, in place, the groups on two tasks of loops.
     */
    void solve3(double[] b, double[] work, NodeLoops loops) {
        rhs = b;
        x = work;
        try {
            loops.runTasks(GROUPS, forward);
            loops.runTasks(cutTasks, cut);
            topForward(work);
            for (int i = topBlocks.length - 1; i >= 0; i--) {
                upperBlock(work, topBlocks[i]);
            }
            final int[] pm = perm;
            for (int j : topColumns) {
                final int k = 3 * pm[j];
                b[k] = work[3 * j];
                b[k + 1] = work[3 * j + 1];
                b[k + 2] = work[3 * j + 2];
            }
            loops.runTasks(GROUPS, backward);
        } finally {
            rhs = null;
            x = null;
        }
    }

    /**
     * The top rows of the cut's tasks [from, to): each row's right-hand side less its prefix's terms, in the
     * column order (what the column loop has subtracted from the row when it reaches the row's first top
     * column).
     */
    private void cutRows(int from, int to) {
        final double[] b = rhs;
        final double[] w = x;
        final int[] pm = perm;
        final double[] v = lx;
        final int[] rc = rowColumn;
        final int[] re = rowEntry;
        for (int t = cutTaskStart[from]; t < cutTaskStart[to]; t++) {
            final int r = topColumns[t];
            final int k = 3 * pm[r];
            double s0 = b[k];
            double s1 = b[k + 1];
            double s2 = b[k + 2];
            for (int q = rowStart[t], end = prefixEnd[t]; q < end; q++) {
                final int c = rc[q];
                final double l = v[re[q]];
                s0 -= l * w[c];
                s1 -= l * w[c + 1];
                s2 -= l * w[c + 2];
            }
            w[3 * r] = s0;
            w[3 * r + 1] = s1;
            w[3 * r + 2] = s2;
        }
    }

    private void forwardGroups(int from, int to) {
        for (int g = from; g < to; g++) {
            final int[] blocks = groupBlocks[g];
            final int[] end = groupRowEnd[g];
            final double[] b = rhs;
            final double[] w = x;
            final int[] pm = perm;
            for (int blk : blocks) {
                for (int j = bs[blk]; j < bs[blk + 1]; j++) {
                    final int k = 3 * pm[j];
                    w[3 * j] = b[k];
                    w[3 * j + 1] = b[k + 1];
                    w[3 * j + 2] = b[k + 2];
                }
            }
            for (int i = 0; i < blocks.length; i++) {
                lowerBlock(w, blocks[i], end[i]);
            }
        }
    }

    private void backwardGroups(int from, int to) {
        for (int g = from; g < to; g++) {
            final int[] blocks = groupBlocks[g];
            final double[] b = rhs;
            final double[] w = x;
            final int[] pm = perm;
            for (int i = blocks.length - 1; i >= 0; i--) {
                upperBlock(w, blocks[i]);
            }
            for (int blk : blocks) {
                for (int j = bs[blk]; j < bs[blk + 1]; j++) {
                    final int k = 3 * pm[j];
                    b[k] = w[3 * j];
                    b[k + 1] = w[3 * j + 1];
                    b[k + 2] = w[3 * j + 2];
                }
            }
        }
    }

    /** The forward solve of block blk, stopped at entry {@code end} of its last column ({@link SparseCholesky#lowerBlock}). */
    private void lowerBlock(double[] x, int blk, int end) {
        SparseCholesky.lowerBlock(lp, li, lx, bs, x, blk, end);
    }

    /** The forward solve of the top's rows, each as a row (see the class comment), from its prefix on. */
    private void topForward(double[] x) {
        final int[] p = lp;
        final double[] v = lx;
        final int[] rc = rowColumn;
        final int[] re = rowEntry;
        for (int t = 0; t < topColumns.length; t++) {
            final int r = topColumns[t];
            double s0 = x[3 * r];
            double s1 = x[3 * r + 1];
            double s2 = x[3 * r + 2];
            for (int q = prefixEnd[t], end = rowStart[t + 1]; q < end; q++) {
                final int c = rc[q];
                final double l = v[re[q]];
                s0 -= l * x[c];
                s1 -= l * x[c + 1];
                s2 -= l * x[c + 2];
            }
            final double inv = 1 / v[p[r]];
            x[3 * r] = s0 * inv;
            x[3 * r + 1] = s1 * inv;
            x[3 * r + 2] = s2 * inv;
        }
    }

    /** The backward solve of block blk ({@link SparseCholesky#upperBlock}). */
    private void upperBlock(double[] x, int blk) {
        SparseCholesky.upperBlock(lp, li, lx, bs, x, blk);
    }
}
