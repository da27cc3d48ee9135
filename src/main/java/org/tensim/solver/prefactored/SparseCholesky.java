package org.tensim.solver.prefactored;

import edu.emory.mathcs.csparsej.tdouble.Dcs_chol;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcs;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcsn;
import edu.emory.mathcs.csparsej.tdouble.Dcs_common.Dcss;
import edu.emory.mathcs.csparsej.tdouble.Dcs_compress;
import edu.emory.mathcs.csparsej.tdouble.Dcs_dupl;
import edu.emory.mathcs.csparsej.tdouble.Dcs_schol;
import edu.emory.mathcs.csparsej.tdouble.Dcs_util;

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
 */
public final class SparseCholesky {
    private final int n;
    private final int[] pinv; // original index k sits at pinv[k] in the permuted system
    private final int[] lp;
    private final int[] li;
    private final double[] lx;

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

    /** L y = b, three interleaved columns (the column-oriented loop of cs_lsolve). */
    private void lowerSolve(double[] x) {
        final int[] p = lp;
        final int[] ix = li;
        final double[] v = lx;
        for (int j = 0; j < n; j++) {
            final int d = p[j];
            final double inv = 1 / v[d];
            final double x0 = x[3 * j] * inv;
            final double x1 = x[3 * j + 1] * inv;
            final double x2 = x[3 * j + 2] * inv;
            x[3 * j] = x0;
            x[3 * j + 1] = x1;
            x[3 * j + 2] = x2;
            for (int q = d + 1, end = p[j + 1]; q < end; q++) {
                final int r = 3 * ix[q];
                final double l = v[q];
                x[r] -= l * x0;
                x[r + 1] -= l * x1;
                x[r + 2] -= l * x2;
            }
        }
    }

    /** L^T x = y, three interleaved columns (the loop of cs_ltsolve). */
    private void upperSolve(double[] x) {
        final int[] p = lp;
        final int[] ix = li;
        final double[] v = lx;
        for (int j = n - 1; j >= 0; j--) {
            final int d = p[j];
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
        }
    }
}
