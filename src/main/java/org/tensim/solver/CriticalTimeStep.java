package org.tensim.solver;

import java.util.Random;

/**
 * Estimate of the highest natural frequency w_max (rad/s) of a compiled state,
 * and from it the critical time step of explicit integrators: h_crit = 2 / w_max
 * for the leapfrog family (symplectic Euler, velocity Verlet), and in general
 * {@code limit / w_max} for a method bounded on an undamped spring up to
 * {@code w h = limit} ({@link Integrator#undampedStabilityLimit()}).
 *
 * <p>Linearised at the rest positions {@code x0}: the stiffness of a spring of
 * stiffness k along unit vector u is {@code k u u^T} on the relative displacement
 * of its ends (the transverse term vanishes at rest length). Fixed and driven
 * nodes are clamped (their rows and columns dropped). Rigid links and damping are
 * ignored: links remove frequencies, damping only helps.
 *
 * <ul>
 * <li>Gershgorin (a safe bound, w_max never larger): on the symmetric form
 * M^-1/2 K M^-1/2, block row i gives
 * {@code w_max^2 <= max_i (sum_j k_ij / m_i + sum_{j free} k_ij / sqrt(m_i m_j))},
 * at most {@code 2 sum_j k_ij / m_i} (PHYSICS.md).</li>
 * <li>Power iteration on M^-1/2 K M^-1/2 from a seeded random vector: the
 * Rayleigh quotient converges to w_max^2 from below, so this is the sharper
 * estimate but may lie slightly under the true w_max (and h slightly over the
 * true limit) when the top frequencies are clustered.</li>
 * </ul>
 *
 * @param omegaMaxGershgorin  upper bound on w_max, rad/s
 * @param omegaMaxPower       power-iteration estimate of w_max, rad/s
 * @param iterations          power iterations made
 */
public record CriticalTimeStep(double omegaMaxGershgorin, double omegaMaxPower, int iterations) {
    /** Default cap on power iterations. */
    public static final int DEFAULT_MAX_ITERATIONS = 300;
    /** Relative change of the Rayleigh quotient at which the iteration stops. */
    public static final double DEFAULT_TOLERANCE = 1e-7;

    /** Leapfrog critical step from the power estimate, 2 / w_max, s (infinite when nothing oscillates). */
    public double stepSeconds() {
        return forLimit(2);
    }

    /** The Gershgorin (conservative) leapfrog critical step, 2 / w_max, s. */
    public double gershgorinStepSeconds() {
        return omegaMaxGershgorin > 0 ? 2 / omegaMaxGershgorin : Double.POSITIVE_INFINITY;
    }

    /** Critical step of a method stable up to {@code w h = omegaH}, from the power estimate, s. */
    public double forLimit(double omegaH) {
        return omegaMaxPower > 0 ? omegaH / omegaMaxPower : Double.POSITIVE_INFINITY;
    }

    /**
     * The step beyond which an integrator is expected to be unstable on this state,
     * s: its undamped limit over w_max; for methods whose undamped limit is 0
     * (forward Euler, RK2, which grow at any step unless damped) the real-axis limit
     * 2 / w_max, the most that damping can buy them; infinite for implicit methods.
     */
    public double forIntegrator(Integrator integrator) {
        if (!integrator.explicit()) {
            return Double.POSITIVE_INFINITY;
        }
        double limit = integrator.undampedStabilityLimit();
        return forLimit(limit > 0 ? limit : 2);
    }

    /** Estimates with the default iteration cap and tolerance. */
    public static CriticalTimeStep estimate(SystemState s) {
        return estimate(s, DEFAULT_MAX_ITERATIONS, DEFAULT_TOLERANCE);
    }

    /**
     * Estimates w_max of state s at its rest positions.
     *
     * @param maxIterations cap on power iterations (>= 1)
     * @param tolerance     relative change of the Rayleigh quotient that stops the iteration
     */
    public static CriticalTimeStep estimate(SystemState s, int maxIterations, double tolerance) {
        final int n = s.nodeCount;
        final double[] im = s.invMass;
        final double[] m = s.mass;
        double[] row = new double[n];
        for (int i = 0; i < s.springCount(); i++) {
            int a = s.springA[i];
            int b = s.springB[i];
            double k = s.springK[i];
            boolean fa = im[a] != 0;
            boolean fb = im[b] != 0;
            double off = fa && fb ? k / Math.sqrt(m[a] * m[b]) : 0;
            if (fa) {
                row[a] += k / m[a] + off;
            }
            if (fb) {
                row[b] += k / m[b] + off;
            }
        }
        double gersh = 0;
        for (double r : row) {
            gersh = Math.max(gersh, r);
        }

        // Power iteration on A = M^-1/2 K M^-1/2 over free coordinates.
        double[] u = unitDirections(s);
        double[] z = new double[3 * n];
        double[] y = new double[3 * n];
        Random rnd = new Random(12345);
        for (int k = 0; k < 3 * n; k++) {
            z[k] = im[k / 3] == 0 ? 0 : rnd.nextDouble() - 0.5;
        }
        normalise(z);
        double lambda = 0;
        int it = 0;
        while (it < maxIterations) {
            multiply(s, u, z, y);
            double rq = dot(z, y);
            it++;
            double norm = Math.sqrt(dot(y, y));
            if (norm == 0) {
                lambda = 0;
                break;
            }
            for (int k = 0; k < y.length; k++) {
                z[k] = y[k] / norm;
            }
            boolean done = Math.abs(rq - lambda) <= tolerance * Math.abs(rq);
            lambda = rq;
            if (done) {
                break;
            }
        }
        return new CriticalTimeStep(Math.sqrt(gersh), Math.sqrt(Math.max(0, lambda)), it);
    }

    private static double[] unitDirections(SystemState s) {
        double[] u = new double[3 * s.springCount()];
        double[] x = s.x0;
        for (int i = 0; i < s.springCount(); i++) {
            int a = 3 * s.springA[i];
            int b = 3 * s.springB[i];
            double dx = x[b] - x[a];
            double dy = x[b + 1] - x[a + 1];
            double dz = x[b + 2] - x[a + 2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (len > 0) {
                u[3 * i] = dx / len;
                u[3 * i + 1] = dy / len;
                u[3 * i + 2] = dz / len;
            }
        }
        return u;
    }

    /** y = M^-1/2 K M^-1/2 z on free coordinates. */
    private static void multiply(SystemState s, double[] u, double[] z, double[] y) {
        final double[] im = s.invMass;
        java.util.Arrays.fill(y, 0);
        for (int i = 0; i < s.springCount(); i++) {
            int a = s.springA[i];
            int b = s.springB[i];
            double sa = Math.sqrt(im[a]);
            double sb = Math.sqrt(im[b]);
            double ux = u[3 * i];
            double uy = u[3 * i + 1];
            double uz = u[3 * i + 2];
            double d = ux * (sb * z[3 * b] - sa * z[3 * a]) + uy * (sb * z[3 * b + 1] - sa * z[3 * a + 1])
                    + uz * (sb * z[3 * b + 2] - sa * z[3 * a + 2]);
            double g = s.springK[i] * d;
            y[3 * a] -= sa * g * ux;
            y[3 * a + 1] -= sa * g * uy;
            y[3 * a + 2] -= sa * g * uz;
            y[3 * b] += sb * g * ux;
            y[3 * b + 1] += sb * g * uy;
            y[3 * b + 2] += sb * g * uz;
        }
    }

    private static void normalise(double[] z) {
        double n = Math.sqrt(dot(z, z));
        if (n > 0) {
            for (int k = 0; k < z.length; k++) {
                z[k] /= n;
            }
        }
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int k = 0; k < a.length; k++) {
            s += a[k] * b[k];
        }
        return s;
    }
}
