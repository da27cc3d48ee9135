package org.tensim.solver.stability;

/**
 * What the time-step policy needs to know of a scene: the highest angular frequency
 * of its network and its Rayleigh damping, under which a mode of frequency w has the
 * damping ratio {@code zeta(w) = beta w / 2 + alpha / (2 w)}.
 *
 * @param omegaMax highest angular frequency (an upper bound), rad/s, > 0
 * @param beta     stiffness-proportional damping: axial damping {@code c = beta k} of every spring, s (>= 0)
 * @param alpha    mass-proportional damping: viscous damping {@code c_v = alpha m}, 1/s (>= 0)
 * @param source   where omegaMax comes from, for the reason of a step (e.g. "Gershgorin bound")
 */
public record ModalBounds(double omegaMax, double beta, double alpha, String source) {
    /** @throws IllegalArgumentException naming the value that is out of range */
    public ModalBounds {
        if (!(omegaMax > 0) || !Double.isFinite(omegaMax)) {
            throw new IllegalArgumentException("highest angular frequency must be finite and > 0 rad/s, got "
                    + omegaMax);
        }
        if (!(beta >= 0) || !(alpha >= 0) || !Double.isFinite(beta) || !Double.isFinite(alpha)) {
            throw new IllegalArgumentException("Rayleigh damping must be finite and >= 0, got beta = " + beta
                    + " s, alpha = " + alpha + " 1/s");
        }
    }

    /** Undamped bounds from a state's estimate (its power-iteration w_max). */
    public static ModalBounds undamped(CriticalTimeStep c) {
        return new ModalBounds(c.omegaMaxPower(), 0, 0, "power iteration");
    }

    /** The damping ratio of a mode of angular frequency w, rad/s. */
    public double dampingRatio(double w) {
        return beta * w / 2 + alpha / (2 * w);
    }

    public boolean damped() {
        return beta > 0 || alpha > 0;
    }
}
