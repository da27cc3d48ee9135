package org.tensim.view;

import java.util.List;

/**
 * A scene as the GUI sees it: the bodies to simulate and draw, and the
 * parameters a user may tune while it runs. A scene adds no physics: it wraps
 * the scenes of {@code org.tensim.scene} (cube, diaphragm) that the headless
 * commands use too.
 *
 * <p>Threading: a scene is created, stepped and tuned on the simulation thread
 * only; {@link #apply(String, double)} is called there between two steps, never
 * during one.
 */
public interface ViewScene {
    /** Short name used on the command line and in preset files, e.g. {@code cube}. */
    String name();

    /** One line shown in the window title. */
    String title();

    /** The bodies, stepped together in this order with the same time step. */
    List<Body> bodies();

    /** The tunable parameters of this scene (the time step is the GUI's, not listed here). */
    List<TunableParameter> parameters();

    /**
     * Applies a validated value of one of {@link #parameters()} to the running
     * simulations. Called on the simulation thread between steps.
     *
     * @throws IllegalArgumentException for an unknown key
     */
    void apply(String key, double value);

    /** The time step the scene is meant to run at, s. */
    double defaultTimeStep();

    /** Which component of the probe displacement is charted by default: 0 = x, 1 = y, 2 = z, 3 = magnitude. */
    default int defaultProbeAxis() {
        return 1;
    }

    /** Scale of the displacement vectors drawn (the paper's Fig. 5 uses 100). */
    default double displacementScale() {
        return 1;
    }
}
