package org.tensim.solver.prefactored;

import edu.emory.mathcs.csparsej.tdouble.Dcs_chol;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcs;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcsn;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcss;
import edu.emory.mathcs.csparsej.tdouble.Dcs_compress;
import edu.emory.mathcs.csparsej.tdouble.Dcs_dupl;
import edu.emory.mathcs.csparsej.tdouble.Dcs_schol;
import edu.emory.mathcs.csparsej.tdouble.Dcs_util;
import org.tensim.solver.NodeLoops;

/**
 * A sparse Cholesky factor {@code P A P^T = L L^T} of a symmetric positive definite
 * n x n matrix, from CSparseJ (Tim Davis's CSparse in Java) with its AMD fill-reducing
 * ordering P. The symbolic analysis (ordering, elimination tree, column counts) is made
 * once per sparsity pattern ({@link Pattern}) and shared by every numeric factorisation of
 * that pattern: a change of stiffness or time step only refactors numerically.
 *
 * <p>{@link #solve3} solves the three coordinates of a node-based system at once, with one
 * pass over L for all three (the coordinates share the scalar matrix, as in Liu et al. 2013);
 * it only reads the factor, allocates nothing, and may run while another factor is being
 * computed on another thread.
 *
 * <p>Why columns are solved in pairs: the solves were 40 % of a bdf2 step on the default diaphragm,
 * bound by the work per nonzero (an index, a value, three gathers and three updates), not by the
 * factor's size. Two consecutive columns j, j + 1 whose patterns below row j + 1 are the same (a
 * supernode of the factor; on that mesh the columns come in supernodes of 3.5 on average and
 * nearly every nonzero lies in one) share each row's index and its three entries of x, which
 * saves about a third of that work. The forward solve does the same operations in the same order
 * as the column loop of cs_lsolve (the same bits); the backward solve sums a column's products in
 * another order than cs_ltsolve (round-off).
 *
 * <p>L's entries stay in double: keeping them as floats made the solves about a tenth cheaper and the bdf2
 * step no measurably cheaper, and was removed (docs/performance.md, "Tried and removed").
 */
public final class SparseCholesky {
    private final int n;
    private final int[] pinv; // original index k sits at pinv[k] in the permuted system
    private final int[] lp;
    private final int[] li;
    private final double[] lx;
    private final int[] blockStart; // first column of each block of one or two columns; blockStart[blocks] = n
    private final int blocks;
    /** The two-thread form of the solves, null below {@link #MIN_SPLIT_ENTRIES}. */
    private final SubtreeSolve split;

    /**
     * Entries of L from which the solves are split between two threads: below, the two dispatches of a split
     * solve (about a microsecond each, more when the second core is busy) cost more than half the solve.
     */
    public static final int MIN_SPLIT_ENTRIES = 20_000;

    /**
     * The symbolic analysis of a sparsity pattern, built from the matrix's entries in
     * triplet form (duplicates summed).
     */
    public static final class Pattern {
        final int n;
        final Dcss symbolic;

        private Pattern(int n, Dcss symbolic) {
            this.n = n;
            this.symbolic = symbolic;
        }

        /** Matrix order. */
        public int size() {
            return n;
        }

        /** Nonzeros of L predicted by the analysis. */
        public int factorNonZeros() {
            return symbolic.lnz;
        }
    }

    private SparseCholesky(int n, int[] pinv, Dcs l) {
        this.n = n;
        this.pinv = pinv;
        this.lp = l.p;
        this.li = l.i;
        this.lx = l.x;
        int[] starts = new int[n + 1];
        int b = 0;
        for (int j = 0; j < n; j++) {
            starts[b++] = j;
            if (j + 1 < n && pairs(j)) {
                j++;
            }
        }
        starts[b] = n;
        blocks = b;
        blockStart = java.util.Arrays.copyOf(starts, b + 1);
        split = lp[n] < MIN_SPLIT_ENTRIES ? null : new SubtreeSolve(n, lp, li, lx, blockStart, blocks, pinv);
    }

    /**
     * Whether column j + 1 of L has column j's pattern without its first two rows (diagonal, then
     * row j + 1), in the same order: the two can be solved together.
     */
    private boolean pairs(int j) {
        final int a = lp[j];
        final int b = lp[j + 1];
        final int len = b - a;
        if (len < 2 || li[a] != j || li[a + 1] != j + 1 || li[b] != j + 1 || lp[j + 2] - b != len - 1) {
            return false;
        }
        for (int k = 2; k < len; k++) {
            if (li[a + k] != li[b + k - 1]) {
                return false;
            }
        }
        return true;
    }

    /** Columns solved two at a time (for tests and the docs' profile). */
    int pairedColumns() {
        return 2 * (n - blocks);
    }

    /**
     * Compresses triplets (row, column, value; both triangles given, duplicates summed) into
     * a compressed-column matrix.
     */
    static Dcs compress(int n, int[] rows, int[] cols, double[] vals, int count) {
        Dcs t = Dcs_util.cs_spalloc(n, n, Math.max(1, count), true, true);
        System.arraycopy(rows, 0, t.i, 0, count);
        System.arraycopy(cols, 0, t.p, 0, count);
        System.arraycopy(vals, 0, t.x, 0, count);
        t.nz = count;
        Dcs a = Dcs_compress.cs_compress(t);
        Dcs_dupl.cs_dupl(a);
        return a;
    }

    /** The AMD ordering and symbolic factorisation of a pattern given as triplets. */
    public static Pattern analyse(int n, int[] rows, int[] cols, double[] vals, int count) {
        Dcss s = Dcs_schol.cs_schol(1, compress(n, rows, cols, vals, count));
        if (s == null) {
            throw new IllegalStateException("symbolic analysis of the " + n + " x " + n + " matrix failed");
        }
        return new Pattern(n, s);
    }

    /**
     * Numeric factorisation of the matrix given as triplets, whose pattern must be that of
     * {@code pattern}.
     *
     * @param what names the matrix in the error message
     * @throws NotPositiveDefiniteException when a pivot is not positive (the matrix is not
     *         symmetric positive definite)
     */
    public static SparseCholesky factor(Pattern pattern, int[] rows, int[] cols, double[] vals, int count,
            String what) {
        Dcs a = compress(pattern.n, rows, cols, vals, count);
        Dcsn num = Dcs_chol.cs_chol(a, pattern.symbolic);
        if (num == null) {
            throw new NotPositiveDefiniteException("sparse Cholesky factorisation of " + what + " (" + pattern.n
                    + " x " + pattern.n + ", " + a.p[pattern.n] + " nonzeros) failed: the matrix is not positive"
                    + " definite (a free node without mass, a negative stiffness or damping, or a non-finite value)");
        }
        return new SparseCholesky(pattern.n, pattern.symbolic.pinv, num.L);
    }

    /** Matrix order. */
    public int size() {
        return n;
    }

    /** Nonzeros of the factor L. */
    public int factorNonZeros() {
        return lp[n];
    }

    /**
     * Solves {@code A y = b} for three right-hand sides at once, in place: {@code b[3k + c]}
     * holds coordinate c of unknown k (original numbering) on entry and the solution on
     * return. {@code work} has length 3n.
     */
    public void solve3(double[] b, double[] work) {
        final int[] pi = pinv;
        for (int k = 0; k < n; k++) {
            final int o = 3 * pi[k];
            work[o] = b[3 * k];
            work[o + 1] = b[3 * k + 1];
            work[o + 2] = b[3 * k + 2];
        }
        lowerSolve(work);
        upperSolve(work);
        for (int k = 0; k < n; k++) {
            final int o = 3 * pi[k];
            b[3 * k] = work[o];
            b[3 * k + 1] = work[o + 1];
            b[3 * k + 2] = work[o + 2];
        }
    }

    /**
     * As {@link #solve3(double[], double[])}, with two subtrees of the elimination tree solved at the same time
     * when {@code loops} has two threads or more ({@link SubtreeSolve}): the same bits as on one thread.
     */
    public void solve3(double[] b, double[] work, NodeLoops loops) {
        if (split == null || loops.threads() < 2) {
            solve3(b, work);
        } else {
            split.solve3(b, work, loops);
        }
    }

    /** The two-thread form of the solves, or null for a factor below {@link #MIN_SPLIT_ENTRIES} (for tests). */
    SubtreeSolve split() {
        return split;
    }

    /** L y = b, three interleaved columns (the column-oriented loop of cs_lsolve), by blocks. */
    private void lowerSolve(double[] x) {
        final int[] bs = blockStart;
        for (int b = 0; b < blocks; b++) {
            final int j = bs[b];
            lowerBlock(lp, li, lx, bs, x, b, lp[bs[b + 1] == j + 1 ? j + 1 : j + 2]);
        }
    }

    /**
     * The forward solve of block blk (one column, or two of a supernode: row j + 1 first, then the rows they
     * share), three interleaved right-hand sides in x, its updates stopped at entry {@code end} of its last
     * column (the column's end for the whole solve; {@link SubtreeSolve} stops earlier, where the top's rows
     * begin). The one kernel of both solvers, so that they give the same bits.
     */
    static void lowerBlock(int[] p, int[] ix, double[] v, int[] bs, double[] x, int blk, int end) {
        final int j = bs[blk];
        final int d = p[j];
        final double inv = 1 / v[d];
        final double x0 = x[3 * j] * inv;
        final double x1 = x[3 * j + 1] * inv;
        final double x2 = x[3 * j + 2] * inv;
        x[3 * j] = x0;
        x[3 * j + 1] = x1;
        x[3 * j + 2] = x2;
        if (bs[blk + 1] == j + 1) {
            for (int q = d + 1; q < end; q++) {
                final int r = 3 * ix[q];
                final double l = v[q];
                x[r] -= l * x0;
                x[r + 1] -= l * x1;
                x[r + 2] -= l * x2;
            }
            return;
        }
        final int e = p[j + 1];
        final double l = v[d + 1];
        final double inv1 = 1 / v[e];
        final double y0 = (x[3 * j + 3] - l * x0) * inv1;
        final double y1 = (x[3 * j + 4] - l * x1) * inv1;
        final double y2 = (x[3 * j + 5] - l * x2) * inv1;
        x[3 * j + 3] = y0;
        x[3 * j + 4] = y1;
        x[3 * j + 5] = y2;
        for (int qa = d + 2, q = e + 1; q < end; qa++, q++) {
            final int r = 3 * ix[q];
            final double la = v[qa];
            final double lb = v[q];
            x[r] = x[r] - la * x0 - lb * y0;
            x[r + 1] = x[r + 1] - la * x1 - lb * y1;
            x[r + 2] = x[r + 2] - la * x2 - lb * y2;
        }
    }

    /** L^T x = y, three interleaved columns (the loop of cs_ltsolve), by blocks from the last. */
    private void upperSolve(double[] x) {
        for (int b = blocks - 1; b >= 0; b--) {
            upperBlock(lp, li, lx, blockStart, x, b);
        }
    }

    /**
     * The backward solve of block blk (one column, or two of a supernode: column j + 1 complete over the shared
     * rows, then column j), three interleaved right-hand sides in x; the one kernel of this class's and
     * {@link SubtreeSolve}'s backward solves.
     */
    static void upperBlock(int[] p, int[] ix, double[] v, int[] bs, double[] x, int blk) {
        final int j = bs[blk];
        final int d = p[j];
        if (bs[blk + 1] == j + 1) {
            double x0 = x[3 * j];
            double x1 = x[3 * j + 1];
            double x2 = x[3 * j + 2];
            for (int q = d + 1, end = p[j + 1]; q < end; q++) {
                final int r = 3 * ix[q];
                final double l = v[q];
                x0 -= l * x[r];
                x1 -= l * x[r + 1];
                x2 -= l * x[r + 2];
            }
            final double inv = 1 / v[d];
            x[3 * j] = x0 * inv;
            x[3 * j + 1] = x1 * inv;
            x[3 * j + 2] = x2 * inv;
            return;
        }
        final int e = p[j + 1];
        double y0 = x[3 * j + 3];
        double y1 = x[3 * j + 4];
        double y2 = x[3 * j + 5];
        double s0 = 0;
        double s1 = 0;
        double s2 = 0;
        for (int qa = d + 2, q = e + 1, end = p[j + 2]; q < end; qa++, q++) {
            final int r = 3 * ix[q];
            final double la = v[qa];
            final double lb = v[q];
            final double r0 = x[r];
            final double r1 = x[r + 1];
            final double r2 = x[r + 2];
            y0 -= lb * r0;
            y1 -= lb * r1;
            y2 -= lb * r2;
            s0 += la * r0;
            s1 += la * r1;
            s2 += la * r2;
        }
        final double inv1 = 1 / v[e];
        y0 *= inv1;
        y1 *= inv1;
        y2 *= inv1;
        x[3 * j + 3] = y0;
        x[3 * j + 4] = y1;
        x[3 * j + 5] = y2;
        final double l = v[d + 1];
        final double inv = 1 / v[d];
        x[3 * j] = (x[3 * j] - l * y0 - s0) * inv;
        x[3 * j + 1] = (x[3 * j + 1] - l * y1 - s1) * inv;
        x[3 * j + 2] = (x[3 * j + 2] - l * y2 - s2) * inv;
    }
}
