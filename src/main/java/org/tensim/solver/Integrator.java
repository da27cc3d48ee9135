package org.tensim.solver;

/**
 * Stage 1 of the paper's loop: advances positions and velocities of the free
 * nodes by one step of m a = f, as if there were no rigid links. Rigid links are
 * enforced afterwards by {@link RigidLinkProjection}, the same for every
 * integrator. Fixed nodes (inverse mass 0) do not move; driven nodes follow their
 * motions.
 *
 * <p>An implementation allocates its scratch arrays once, on the first step (or in
 * its constructor), and never per step.
 */
public interface Integrator {
    /** Short name used on command lines and in reports, e.g. {@code rk2}. */
    String name();

    /** Global order of accuracy on smooth problems. */
    int order();

    /** Force evaluations per step (the cost measure). */
    int forceEvaluationsPerStep();

    /**
     * Advances {@code model.state()} from time t to t + dt (s). On return
     * {@code state.x} and {@code state.v} hold the unconstrained new positions
     * and velocities.
     */
    void step(ForceModel model, double t, double dt);
}
