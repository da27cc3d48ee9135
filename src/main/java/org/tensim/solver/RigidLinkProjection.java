package org.tensim.solver;

import org.tensim.model.Check;

/**
 * Stage 2 of the paper's loop (section 2.2, Fig. 2, after Provot 1995): puts the
 * two ends of each rigid link back on the line A'B' so that |A1 B1| = L.
 *
 * <p>For a link (a, b) of length L with d = x_b - x_a and l = |d|, the correction
 * {@code delta = (l - L) / l * d} is shared in inverse proportion to the masses:
 * {@code x_a += w_a / (w_a + w_b) delta}, {@code x_b -= w_b / (w_a + w_b) delta},
 * with w the inverse masses (0 for fixed and driven nodes, which never move). This
 * leaves the total linear momentum unchanged (the mass-weighted corrections cancel).
 *
 * <p>Links that share nodes disturb each other, so the sweep is repeated
 * (Gauss-Seidel) until the largest relative length error |l - L| / L is at most
 * the tolerance or the cap on sweeps has been reached, both given with each call (a simulation's
 * {@link SolverSettings}, read every step). The result of the last call is kept in {@link #iterations()} and
 * {@link #maxRelativeError()}; {@link #converged()} says whether the tolerance
 * was met. Nothing is silently accepted: a caller can see the residual.
 */
public final class RigidLinkProjection {
    /** Default largest relative length error, dimensionless: 1e-9 ({@link SolverSettings}). */
    public static final double DEFAULT_TOLERANCE = SolverSettings.DEFAULTS.projectionTolerance();
    /** Default cap on Gauss-Seidel sweeps per step: 200 ({@link SolverSettings}). */
    public static final int DEFAULT_MAX_ITERATIONS = SolverSettings.DEFAULTS.projectionMaxIterations();

    private double tolerance = DEFAULT_TOLERANCE;
    private int iterations;
    private double maxRelativeError;
    private int worstLink = -1;
    private LinkSweeps sweeps;

    /** Sweeps made by the last call. */
    public int iterations() {
        return iterations;
    }

    /** Largest relative length error after the last call. */
    public double maxRelativeError() {
        return maxRelativeError;
    }

    /** Index of the link with the largest error after the last call (-1 if none). */
    public int worstLink() {
        return worstLink;
    }

    /** Whether the last call met its tolerance. */
    public boolean converged() {
        return maxRelativeError <= tolerance;
    }

    /**
     * Replaces the built-in sweep and measure loops (null restores them), e.g. by
     * parallel sweeps over link colours; the tolerance and cap still apply.
     */
    public RigidLinkProjection setSweeps(LinkSweeps replacement) {
        sweeps = replacement;
        return this;
    }

    /** The replacement loops in use, or null for the built-in ones. */
    public LinkSweeps sweeps() {
        return sweeps;
    }

    /**
     * Projects the positions {@code x} of state s onto the rigid links.
     *
     * @param relativeTolerance largest accepted relative length error |l - L| / L (dimensionless, > 0)
     * @param maxIterations     cap on Gauss-Seidel sweeps (>= 1)
     * @return true when the tolerance was met
     */
    public boolean project(SystemState s, double[] x, double relativeTolerance, int maxIterations) {
        tolerance = Check.positive("rigid link tolerance", "(relative length error)", relativeTolerance);
        Check.atLeast("rigid link iteration cap", maxIterations, 1);
        if (sweeps != null) {
            return projectWith(sweeps, s, x, maxIterations);
        }
        iterations = 0;
        maxRelativeError = measure(s, x);
        while (maxRelativeError > tolerance && iterations < maxIterations) {
            sweep(s, x);
            iterations++;
            maxRelativeError = measure(s, x);
        }
        return converged();
    }

    private boolean projectWith(LinkSweeps w, SystemState s, double[] x, int maxIterations) {
        iterations = 0;
        maxRelativeError = w.measure(s, x);
        while (maxRelativeError > tolerance && iterations < maxIterations) {
            w.sweep(s, x);
            iterations++;
            maxRelativeError = w.measure(s, x);
        }
        worstLink = w.worstLink();
        return converged();
    }

    private static void sweep(SystemState s, double[] x) {
        final int[] la = s.linkA;
        final int[] lb = s.linkB;
        final double[] ll = s.linkL;
        final double[] w = s.invMass;
        for (int i = 0; i < la.length; i++) {
            correct(x, 3 * la[i], 3 * lb[i], w[la[i]], w[lb[i]], ll[i]);
        }
    }

    /**
     * Restores one link's length: moves its ends (at offsets a3, b3 of x) along the
     * line joining them, in the ratio of their inverse masses wa, wb (1/kg).
     * Shared by the serial and the parallel sweeps, so both give the same bits.
     *
     * @return false when the link was left as it is: both ends immovable (wa + wb = 0),
     *         or coincident ends (direction undefined; the next sweep retries after
     *         neighbours move). The error stays visible to the measure.
     */
    public static boolean correct(double[] x, int a3, int b3, double wa, double wb, double length) {
        final double wsum = wa + wb;
        if (wsum == 0) {
            return false;
        }
        final double dx = x[b3] - x[a3];
        final double dy = x[b3 + 1] - x[a3 + 1];
        final double dz = x[b3 + 2] - x[a3 + 2];
        final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len == 0) {
            return false;
        }
        final double r = (len - length) / (len * wsum);
        final double ca = wa * r;
        final double cb = wb * r;
        x[a3] += ca * dx;
        x[a3 + 1] += ca * dy;
        x[a3 + 2] += ca * dz;
        x[b3] -= cb * dx;
        x[b3 + 1] -= cb * dy;
        x[b3 + 2] -= cb * dz;
        return true;
    }

    private double measure(SystemState s, double[] x) {
        double worst = 0;
        worstLink = -1;
        for (int i = 0; i < s.linkA.length; i++) {
            final int a3 = 3 * s.linkA[i];
            final int b3 = 3 * s.linkB[i];
            final double dx = x[b3] - x[a3];
            final double dy = x[b3 + 1] - x[a3 + 1];
            final double dz = x[b3 + 2] - x[a3 + 2];
            final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            final double e = Math.abs(len - s.linkL[i]) / s.linkL[i];
            if (!(e <= worst)) { // also catches NaN
                worst = e;
                worstLink = i;
            }
        }
        return worst;
    }
}
