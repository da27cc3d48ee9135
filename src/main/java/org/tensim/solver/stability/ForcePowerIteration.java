package org.tensim.solver.stability;

import java.util.Random;

/**
 * The highest angular frequency of a whole force model about a configuration, measured rather than bounded: power
 * iteration on {@code A = M^-1/2 K M^-1/2} over the free coordinates, where {@code K = -df/dx} is applied
 * matrix-free by central differences of the forces themselves,
 * {@code K z ~ -(f(x + e z) - f(x - e z)) / (2 e)}.
 *
 * <p>Why: a Gershgorin bound sums each row's absolute entries, which is tight for a spring network but far from it
 * for a coupling that ties a node to a weighted combination of many others (a lung follower sliding on a pleura
 * carried by blended rib motions: every weight counts in full). The forces' own differences see every term a scene
 * adds, coupled as it is, at the cost of two force passes an iteration. The Rayleigh quotient approaches the largest
 * eigenvalue from below, so a caller uses it with a margin ({@link #estimate}'s {@code margin}).
 *
 * <p>Only what the forces do about {@code x} is seen: a contact not yet touching there adds nothing.
 */
public final class ForcePowerIteration {
    /** The forces of a model at positions x (m, 3 per node), written (not added) into f (N). */
    @FunctionalInterface
    public interface Forces {
        void at(double[] x, double[] f);
    }

    /**
     * The measured highest frequency.
     *
     * @param omegaMax   sqrt of the converged Rayleigh quotient, rad/s
     * @param iterations power iterations run
     * @param converged  whether the quotient's relative change fell below the tolerance before the cap
     */
    public record Estimate(double omegaMax, int iterations, boolean converged) {
    }

    private ForcePowerIteration() {
    }

    /**
     * Runs the iteration.
     *
     * @param forces        the model's forces (velocities held at zero by the caller, so damping adds nothing)
     * @param x             the configuration to linearise about, m (3 per node); not changed
     * @param invMass       inverse masses, 1/kg; 0 marks a node that is not free (driven or fixed), left out
     * @param displacementM the largest displacement of a node in a difference, m (> 0; small against the
     *                      elements, large against rounding: 1e-7 m on an organ of centimetres)
     * @param maxIterations cap on iterations (>= 1)
     * @param tolerance     relative change of the quotient that stops the iteration (> 0)
     * @param seed          the start vector's seed
     * @throws IllegalArgumentException naming a value out of range
     */
    public static Estimate estimate(Forces forces, double[] x, double[] invMass, double displacementM,
            int maxIterations, double tolerance, long seed) {
        if (x.length != 3 * invMass.length) {
            throw new IllegalArgumentException("positions must hold 3 per node: " + x.length + " for "
                    + invMass.length + " nodes");
        }
        if (!(displacementM > 0) || maxIterations < 1 || !(tolerance > 0)) {
            throw new IllegalArgumentException("displacement must be > 0 m, iterations >= 1 and tolerance > 0, got "
                    + displacementM + " m, " + maxIterations + ", " + tolerance);
        }
        int n3 = x.length;
        double[] z = new double[n3];
        double[] y = new double[n3];
        double[] xp = new double[n3];
        double[] fp = new double[n3];
        double[] fm = new double[n3];
        double[] sqrtInv = new double[n3];
        for (int k = 0; k < n3; k++) {
            sqrtInv[k] = Math.sqrt(invMass[k / 3]);
        }
        Random rnd = new Random(seed);
        for (int k = 0; k < n3; k++) {
            z[k] = sqrtInv[k] == 0 ? 0 : rnd.nextDouble() - 0.5;
        }
        if (normalise(z) == 0) {
            return new Estimate(0, 0, true);
        }
        double lambda = 0;
        for (int it = 1; it <= maxIterations; it++) {
            // dx = e M^-1/2 z, e chosen so that the largest node move is displacementM.
            double largest = 0;
            for (int k = 0; k < n3; k++) {
                largest = Math.max(largest, Math.abs(sqrtInv[k] * z[k]));
            }
            double e = displacementM / largest;
            for (int k = 0; k < n3; k++) {
                xp[k] = x[k] + e * sqrtInv[k] * z[k];
            }
            forces.at(xp, fp);
            for (int k = 0; k < n3; k++) {
                xp[k] = x[k] - e * sqrtInv[k] * z[k];
            }
            forces.at(xp, fm);
            for (int k = 0; k < n3; k++) {
                y[k] = -sqrtInv[k] * (fp[k] - fm[k]) / (2 * e);
            }
            double rq = dot(z, y);
            System.arraycopy(y, 0, z, 0, n3);
            if (normalise(z) == 0) {
                return new Estimate(0, it, true);
            }
            boolean done = Math.abs(rq - lambda) <= tolerance * Math.abs(rq);
            lambda = rq;
            if (done) {
                return new Estimate(Math.sqrt(Math.max(0, lambda)), it, true);
            }
        }
        return new Estimate(Math.sqrt(Math.max(0, lambda)), maxIterations, false);
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int k = 0; k < a.length; k++) {
            s += a[k] * b[k];
        }
        return s;
    }

    private static double normalise(double[] a) {
        double n = Math.sqrt(dot(a, a));
        if (n > 0) {
            for (int k = 0; k < a.length; k++) {
                a[k] /= n;
            }
        }
        return n;
    }
}
