package org.tensim.solver.stability;

import java.util.Random;

/**
 * Estimate of the highest natural frequency w_max (rad/s) of a compiled state,
 * and from it the critical time step of explicit integrators: h_crit = 2 / w_max
 * for the leapfrog family (symplectic Euler, velocity Verlet), and in general
 * {@code limit / w_max} for a method bounded on an undamped spring up to
 * {@code w h = limit} ({@link LinearStability#undampedLimit()}). The state's
 * arrays come in as they are compiled ({@code SystemState}); this package depends on
 * nothing else of the solver.
 *
 * <p>Linearised at the rest positions {@code x0}: the stiffness of a spring of
 * stiffness k along unit vector u is {@code k u u^T} on the relative displacement
 * of its ends (the transverse term vanishes at rest length); other elements (membrane
 * triangles) come in as an {@link ExtraStiffness}, their blocks in the Gershgorin sums and
 * their products in the power iteration. Fixed and driven
 * nodes are clamped (their rows and columns dropped). Rigid links and damping are
 * ignored: links remove frequencies, damping only helps.
 *
 * <ul>
 * <li>Gershgorin (a safe bound, w_max never larger), {@link #gershgorin}: on the
 * symmetric form M^-1/2 K M^-1/2.</li>
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
     * The step beyond which a method is expected to be unstable on this state, s: its
     * undamped limit over w_max; for methods whose undamped limit is 0 (forward Euler,
     * RK2, which grow at any step unless damped) the real-axis limit 2 / w_max, the
     * most that damping can buy them; infinite for implicit methods.
     *
     * @param explicit      whether the method is explicit (else the step is unbounded)
     * @param undampedLimit its largest stable w h on an undamped spring
     */
    public double forMethod(boolean explicit, double undampedLimit) {
        if (!explicit) {
            return Double.POSITIVE_INFINITY;
        }
        return forLimit(undampedLimit > 0 ? undampedLimit : 2);
    }

    /** Which Gershgorin bound: the two forms of the same eigenvalue problem K u = w^2 M u. */
    public enum Form {
        /**
         * Rows of M^-1 K: {@code w_max^2 <= max_i 2 sum_j k_ij / m_i} (docs/physics.md),
         * every spring of a free node counted, fixed ends included. Cruder; what the
         * diaphragm's damping design and time step use.
         */
        ROWS,
        /**
         * Block rows of the symmetric M^-1/2 K M^-1/2 with fixed nodes clamped:
         * {@code w_max^2 <= max_i (sum_j k_ij / m_i + sum_{j free} k_ij / sqrt(m_i m_j))},
         * at most the {@link #ROWS} bound, equal to it for equal masses and no fixed ends.
         */
        SYMMETRIC
    }

    /**
     * The Gershgorin bound on the highest angular frequency of a spring network,
     * rad/s: the one place where it is computed.
     *
     * @param n       node count
     * @param springA first node of each spring
     * @param springB second node of each spring
     * @param springK stiffness of each spring, N/m
     * @param springs number of springs (the first entries of the arrays)
     * @param mass    node masses, kg
     * @param free    whether each node is free (not fixed, not driven)
     */
    public static double gershgorin(int n, int[] springA, int[] springB, double[] springK, int springs, double[] mass,
            boolean[] free, Form form) {
        return gershgorin(n, springA, springB, springK, springs, mass, free, form, ExtraStiffness.NONE);
    }

    /** The Gershgorin bound of the springs and an {@link ExtraStiffness} together, rad/s. */
    public static double gershgorin(int n, int[] springA, int[] springB, double[] springK, int springs, double[] mass,
            boolean[] free, Form form, ExtraStiffness extra) {
        double[] row = new double[n];
        extra.addGershgorinRows(mass, free, form, row);
        for (int i = 0; i < springs; i++) {
            int a = springA[i];
            int b = springB[i];
            double k = springK[i];
            if (form == Form.ROWS) {
                row[a] += k;
                row[b] += k;
                continue;
            }
            boolean fa = free[a];
            boolean fb = free[b];
            double off = fa && fb ? k / Math.sqrt(mass[a] * mass[b]) : 0;
            if (fa) {
                row[a] += k / mass[a] + off;
            }
            if (fb) {
                row[b] += k / mass[b] + off;
            }
        }
        double w2 = 0;
        for (int i = 0; i < n; i++) {
            if (free[i]) {
                w2 = Math.max(w2, form == Form.ROWS ? 2 * row[i] / mass[i] : row[i]);
            }
        }
        return Math.sqrt(w2);
    }

    /** Estimates with the default iteration cap and tolerance (arrays as in {@link #estimate(int, int[], int[], double[], double[], double[], double[], int, double)}). */
    public static CriticalTimeStep estimate(int n, int[] springA, int[] springB, double[] springK, double[] mass,
            double[] invMass, double[] x0) {
        return estimate(n, springA, springB, springK, mass, invMass, x0, ExtraStiffness.NONE);
    }

    /** Estimates with the default cap and tolerance, the springs and {@code extra} together. */
    public static CriticalTimeStep estimate(int n, int[] springA, int[] springB, double[] springK, double[] mass,
            double[] invMass, double[] x0, ExtraStiffness extra) {
        return estimate(n, springA, springB, springK, mass, invMass, x0, DEFAULT_MAX_ITERATIONS, DEFAULT_TOLERANCE,
                extra);
    }

    /**
     * Estimates w_max of a spring network at its rest positions.
     *
     * @param n             node count
     * @param springA       first node of each spring
     * @param springB       second node of each spring
     * @param springK       stiffness of each spring, N/m
     * @param mass          node masses, kg
     * @param invMass       inverse masses, 1/kg (0 for fixed and driven nodes, which are clamped)
     * @param x0            rest positions, m (3 per node)
     * @param maxIterations cap on power iterations (>= 1)
     * @param tolerance     relative change of the Rayleigh quotient that stops the iteration
     */
    public static CriticalTimeStep estimate(int n, int[] springA, int[] springB, double[] springK, double[] mass,
            double[] invMass, double[] x0, int maxIterations, double tolerance) {
        return estimate(n, springA, springB, springK, mass, invMass, x0, maxIterations, tolerance, ExtraStiffness.NONE);
    }

    /** As {@link #estimate(int, int[], int[], double[], double[], double[], double[], int, double)}, plus {@code extra}. */
    public static CriticalTimeStep estimate(int n, int[] springA, int[] springB, double[] springK, double[] mass,
            double[] invMass, double[] x0, int maxIterations, double tolerance, ExtraStiffness extra) {
        final double[] im = invMass;
        boolean[] free = new boolean[n];
        for (int i = 0; i < n; i++) {
            free[i] = im[i] != 0;
        }
        double gersh = gershgorin(n, springA, springB, springK, springA.length, mass, free, Form.SYMMETRIC, extra);
        Springs s = new Springs(springA, springB, springK, invMass, extra, new double[3 * n], new double[3 * n]);

        // Power iteration on A = M^-1/2 K M^-1/2 over free coordinates.
        double[] u = unitDirections(s, x0);
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
        return new CriticalTimeStep(gersh, Math.sqrt(Math.max(0, lambda)), it);
    }

    /** The network as the power iteration reads it. */
    private record Springs(int[] springA, int[] springB, double[] springK, double[] invMass, ExtraStiffness extra,
            double[] scaled, double[] product) {
        int springCount() {
            return springA.length;
        }
    }

    private static double[] unitDirections(Springs s, double[] x0) {
        double[] u = new double[3 * s.springCount()];
        double[] x = x0;
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
    private static void multiply(Springs s, double[] u, double[] z, double[] y) {
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
        if (s.extra != ExtraStiffness.NONE) {
            for (int k = 0; k < z.length; k++) {
                s.scaled[k] = Math.sqrt(im[k / 3]) * z[k];
            }
            java.util.Arrays.fill(s.product, 0);
            s.extra.multiplyAdd(s.scaled, s.product);
            for (int k = 0; k < z.length; k++) {
                y[k] += Math.sqrt(im[k / 3]) * s.product[k];
            }
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
