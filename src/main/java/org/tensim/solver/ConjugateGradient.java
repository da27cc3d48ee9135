package org.tensim.solver;

/**
 * Preconditioned conjugate gradient, the one routine of the implicit integrators' linear solves: {@code A x = b}
 * for a symmetric positive definite A applied matrix-free, from a first guess, with a preconditioner; A and the
 * preconditioner may work in a subspace (e.g. the rigid links' tangent space, Baraff and Witkin 1998's filtered
 * CG), which the caller's {@link Problem} keeps. It stops when the residual has fallen by the tolerance, measured
 * in the norm {@link Stop} names, or after a cap on iterations; a product that is not positive (only p = 0 gets
 * there for a positive definite A) ends it too. Scratch arrays are allocated once, here; a solve allocates
 * nothing.
 */
public final class ConjugateGradient {
    /** The linear system, applied matrix-free. */
    public interface Problem {
        /** {@code out = A p}, within the problem's subspace. */
        void multiply(double[] p, double[] out);

        /** {@code z = C^-1 r} (the preconditioner), within the problem's subspace. */
        void precondition(double[] r, double[] z);
    }

    /** The norm in which the residual's fall is measured. */
    public enum Stop {
        /** |r| / |b|, b the right-hand side whose squared norm the caller gives. */
        RESIDUAL,
        /**
         * sqrt(r^T C^-1 r) relative to its value at the first guess: a norm that weighs light and heavy nodes
         * alike, unlike |r|.
         */
        PRECONDITIONED
    }

    private final double[] z;
    private final double[] p;
    private final double[] q;
    private int iterations;
    private double relativeResidual;

    /** Scratch for systems of n unknowns. */
    public ConjugateGradient(int n) {
        z = new double[n];
        p = new double[n];
        q = new double[n];
    }

    /**
     * Improves x, from the first guess it holds, towards the solution of {@code A x = b}.
     *
     * @param x             the first guess on entry, the solution on return
     * @param r             the residual {@code b - A x} of the first guess on entry (within the subspace), the
     *                      final residual on return
     * @param bNorm2        |b|^2, the reference of {@link Stop#RESIDUAL} (unused by the other)
     * @param tolerance     relative fall of the residual at which the solve stops
     * @param maxIterations cap on iterations
     * @return whether the tolerance was met
     */
    public boolean solve(Problem a, double[] x, double[] r, double bNorm2, double tolerance, int maxIterations,
            Stop stop) {
        final int n = z.length;
        final boolean residual = stop == Stop.RESIDUAL;
        final double stop2 = tolerance * tolerance * bNorm2;
        double rr = dot(r, r);
        a.precondition(r, z);
        double rz = dot(r, z);
        final double rz0 = rz;
        double relative = 1;
        int it = 0;
        if (residual ? rr > stop2 : rz0 > 0) {
            System.arraycopy(z, 0, p, 0, n);
            while (it < maxIterations) {
                a.multiply(p, q);
                double pq = dot(p, q);
                if (!(pq > 0)) {
                    break; // breakdown: A is positive definite in the subspace, so only p = 0 gets here
                }
                double alpha = rz / pq;
                rr = 0;
                for (int k = 0; k < n; k++) {
                    x[k] += alpha * p[k];
                    final double rk = r[k] - alpha * q[k];
                    r[k] = rk;
                    rr += rk * rk;
                }
                it++;
                if (residual && rr <= stop2) {
                    break;
                }
                if (it == maxIterations) {
                    break; // no preconditioner solve for a residual that nothing would use
                }
                a.precondition(r, z);
                double rzNew = dot(r, z);
                if (!residual) {
                    relative = Math.sqrt(Math.max(0, rzNew) / rz0);
                    if (relative <= tolerance) {
                        break;
                    }
                }
                double beta = rzNew / rz;
                rz = rzNew;
                for (int k = 0; k < n; k++) {
                    p[k] = z[k] + beta * p[k];
                }
            }
        }
        iterations = it;
        relativeResidual = residual ? (bNorm2 > 0 ? Math.sqrt(rr / bNorm2) : 0) : relative;
        return residual ? rr <= stop2 : relative <= tolerance;
    }

    /** Iterations of the last solve. */
    public int iterations() {
        return iterations;
    }

    /**
     * The last solve's final relative residual in its {@link Stop} norm (for {@link Stop#PRECONDITIONED}, as last
     * measured: the cap ends a solve without measuring).
     */
    public double relativeResidual() {
        return relativeResidual;
    }

    private static double dot(double[] a, double[] b) {
        double sum = 0;
        for (int k = 0; k < a.length; k++) {
            sum += a[k] * b[k];
        }
        return sum;
    }
}
