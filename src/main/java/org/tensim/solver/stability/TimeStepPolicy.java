package org.tensim.solver.stability;

/**
 * The one place that recommends a time step, for any integrator and scene, and says
 * how it chose it ({@link TimeStep#reason()}).
 *
 * <ul>
 * <li>An explicit method on a damped scene: the largest step at which every mode
 * from {@code w_max / 1000} to {@code w_max} is stable (growth factor per step at
 * most 1 + 1e-12, from the method's {@link LinearStability#modeAmplification}),
 * found by bisection, times {@link #SAFETY}. A mode of frequency w has the
 * eigenvalues {@code w (-zeta +/- i sqrt(1 - zeta^2))} with zeta from
 * {@link ModalBounds#dampingRatio}. Without damping there is no stable step for RK2
 * (docs/physics.md); with {@code zeta(w_max) = 0.3} it is about {@code 1.5 / w_max}.</li>
 * <li>An explicit method on an undamped scene: its undamped limit over w_max (the
 * real-axis limit 2 / w_max for methods that grow at every step without damping),
 * times {@link #SAFETY}.</li>
 * <li>A method with no stability limit (implicit Euler): stability does not bound
 * the step, accuracy does; the policy gives the step of the paper's RK2
 * ({@link ButcherTableau#MIDPOINT}) on the same scene, so that results compare with
 * the paper's configuration. Larger steps are a choice for speed (the real-time
 * study, docs/diaphragm.md), made with an explicit step.</li>
 * </ul>
 */
public final class TimeStepPolicy {
    /** Factor applied to the stable step (the Gershgorin bound already overestimates w_max). */
    public static final double SAFETY = 0.8;

    private TimeStepPolicy() {
    }

    /**
     * The requested step when one is given (> 0), else the recommended one.
     *
     * @param requestedS  the step asked for, s; 0 for "recommend one"
     * @param option      how the request was made, for the reason (e.g. "--dt")
     * @param method      the integrator's name
     * @param stability   its linear stability, or null when it describes none
     * @param explicit    whether it is explicit (without a description: implicit means unbounded)
     * @param bounds      the scene's frequencies and damping
     * @throws IllegalArgumentException when requestedS is negative or not finite
     */
    public static TimeStep choose(double requestedS, String option, String method, LinearStability stability,
            boolean explicit, ModalBounds bounds) {
        if (!(requestedS >= 0) || !Double.isFinite(requestedS)) {
            throw new IllegalArgumentException(option + " must be a finite number >= 0 s (0: recommended), got "
                    + requestedS);
        }
        if (requestedS > 0) {
            return new TimeStep(requestedS, "given (" + option + ")");
        }
        return recommend(method, stability, explicit, bounds);
    }

    /** The recommended step of a method on a scene (see the class comment). */
    public static TimeStep recommend(String method, LinearStability stability, boolean explicit, ModalBounds m) {
        boolean unbounded = stability == null ? !explicit : stability.undampedLimit() == Double.POSITIVE_INFINITY;
        if (unbounded) {
            TimeStep rk2 = recommend("rk2", ButcherTableau.MIDPOINT, true, m);
            return new TimeStep(rk2.seconds(), method + " has no stability limit; the step is set by accuracy: that of"
                    + " the paper's RK2 on this scene (" + rk2.reason() + ")");
        }
        if (stability == null) {
            double h = 2 / m.omegaMax() * SAFETY;
            return new TimeStep(h, method + " describes no stability: the leapfrog limit 2 / w_max for w_max = "
                    + m.omegaMax() + " rad/s (" + m.source() + "), x" + SAFETY);
        }
        if (m.damped()) {
            double h = largestStableStep(stability, m);
            if (h > 0) {
                return new TimeStep(h * SAFETY, method + " stable step for every mode up to w_max = " + m.omegaMax()
                        + " rad/s (" + m.source() + ") with the Rayleigh damping, x" + SAFETY);
            }
        }
        double limit = stability.undampedLimit();
        double h = (limit > 0 ? limit : 2) / m.omegaMax() * SAFETY;
        return new TimeStep(h, method + (limit > 0 ? " undamped limit w h = " + limit
                : " grows at every step without damping; the real-axis limit w h = 2") + " for w_max = "
                + m.omegaMax() + " rad/s (" + m.source() + "), x" + SAFETY);
    }

    /** The largest stable h, s, for the modes of m (0 when no step is stable). */
    public static double largestStableStep(LinearStability method, ModalBounds m) {
        double omegaMax = m.omegaMax();
        double lo = 0;
        double hi = 4 / omegaMax;
        for (int grow = 0; grow < 20 && stableAt(method, hi, m); grow++) {
            lo = hi;
            hi *= 2; // a method stable beyond the paper's RK2 bracket
        }
        for (int it = 0; it < 60; it++) {
            double h = 0.5 * (lo + hi);
            if (stableAt(method, h, m)) {
                lo = h;
            } else {
                hi = h;
            }
        }
        return lo;
    }

    /** Whether every mode from w_max / 1000 to w_max (401 log-spaced) is stable at step h. */
    static boolean stableAt(LinearStability method, double h, ModalBounds m) {
        double omegaMax = m.omegaMax();
        for (int i = 0; i <= 400; i++) {
            double w = omegaMax * Math.pow(1e-3, 1 - i / 400.0);
            if (method.modeAmplification(h, w, m.dampingRatio(w)) > 1 + 1e-12) {
                return false;
            }
        }
        return true;
    }
}
