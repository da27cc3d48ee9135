package org.tensim.solver;

/** The named stages of one simulation step, in order; each is timed by {@link StepProfile}. */
public enum Stage {
    /** Stage 1: the integrator's unconstrained step of m a = f (spring forces, RK2 stages). */
    INTEGRATE,
    /** Stage 2: the rigid-link projection (Gauss-Seidel sweeps). */
    PROJECT,
    /** Stage 3: new velocities from the corrected positions. */
    VELOCITY,
    /** Divergence check: non-finite positions or velocities stop the run. */
    CHECK,
    /** Listeners (scene graph, recorders) notified. */
    NOTIFY
}
