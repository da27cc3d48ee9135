package org.tensim.solver;

import org.tensim.solver.stability.LinearStability;

/**
 * Stage 1 of the paper's loop: advances positions and velocities of the free
 * nodes by one step of m a = f, as if there were no rigid links. Rigid links are
 * enforced afterwards by {@link RigidLinkProjection}, the same for every
 * integrator. Fixed nodes (inverse mass 0) do not move; driven nodes follow their
 * motions.
 *
 * <p>An implementation runs its per-node loops through
 * {@link ForceModel#nodeLoops()}, so that one installed runner puts every
 * integrator on several threads. It allocates its scratch arrays once, on the first step (or in
 * its constructor), and never per step.
 */
public interface Integrator {
    /** Short name used on command lines and in reports, e.g. {@code rk2}. */
    String name();

    /** Global order of accuracy on smooth problems. */
    int order();

    /** Force evaluations per step (the cost measure): one unless the method says otherwise. */
    default int forceEvaluationsPerStep() {
        return 1;
    }

    /**
     * Advances {@code model.state()} from time t to t + dt (s). On return
     * {@code state.x} and {@code state.v} hold the unconstrained new positions
     * and velocities.
     */
    void step(ForceModel model, double t, double dt);

    /**
     * Whether the method is explicit, so that its step is bounded by the critical
     * time step ({@link CriticalTimeStep}); the simulation warns beyond it.
     */
    default boolean explicit() {
        return true;
    }

    /**
     * Takes the settings that concern the method (an implicit one: the tolerance and
     * iteration cap of its linear solves); called by {@link Simulation#apply}. Default:
     * none.
     */
    default void configure(SolverSettings settings) {
    }

    /**
     * How the method behaves on the linear test oscillator (its stability function
     * and step formula), for {@link org.tensim.solver.stability.StabilityTheory} and
     * {@link org.tensim.solver.stability.TimeStepPolicy}; null when the method does not
     * describe it (then it is taken as unconditionally stable if not
     * {@link #explicit()}).
     */
    default LinearStability stability() {
        return null;
    }

    /**
     * Theory: the largest {@code omega h} (dimensionless, omega = sqrt(k/m) in rad/s,
     * h in s) for which an undamped spring stays bounded. 0 when the method grows at
     * every step size (forward Euler, RK2), {@link Double#POSITIVE_INFINITY} when it
     * is unconditionally stable (implicit Euler). From {@link #stability()}; without
     * one, infinite for an implicit method and 2 (the leapfrog family's limit) for an
     * explicit one.
     */
    default double undampedStabilityLimit() {
        LinearStability s = stability();
        if (s != null) {
            return s.undampedLimit();
        }
        return explicit() ? 2 : Double.POSITIVE_INFINITY;
    }
}
