package org.tensim.scene.tunable;

import java.util.List;
import org.tensim.model.Vec3;

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

    /**
     * Splits {@link #apply} in two for a change made while the scene runs: this call does
     * the costly part (e.g. rebuilding a scene with new constants) on a background
     * thread, while the simulation keeps stepping, and returns what is left to do on
     * the simulation thread between two steps (handing the new constants over). Calls
     * of prepare come from one thread at a time, in the order of the changes, and each
     * builds on the previous ones even before they are handed over. The default
     * prepares nothing: all of {@link #apply} is left for the simulation thread.
     *
     * @return the rest of the change, to run on the simulation thread
     * @throws IllegalArgumentException for an unknown key
     */
    default Runnable prepare(String key, double value) {
        return () -> apply(key, value);
    }

    /**
     * What the scene shows of its running state beside the positions (nodes marked in their own colours, readouts), or
     * null for nothing; a new object for each call's caller, measured on the simulation thread ({@link LiveState}).
     */
    default LiveState liveState() {
        return null;
    }

    /** The integrator the scene is meant to run with (an {@code Integrators} name), or null for the GUI's default. */
    default String defaultIntegrator() {
        return null;
    }

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

    /**
     * Whether springs and nodes are drawn at first. Default: only when no body has a
     * surface (a dense wireframe over a shaded surface hides it and slows drawing).
     */
    default boolean wireframeAtStart() {
        return bodies().stream().allMatch(b -> b.triangles().length == 0);
    }

    /** The scene's up direction, shown upwards in the home view. Default: +y. */
    default Vec3 up() {
        return new Vec3(0, 1, 0);
    }

    /** Direction from the scene's centre towards the eye in the home view. Default: front (+z), a little right and above. */
    default Vec3 viewFrom() {
        return new Vec3(0.2, 0.3, 0.933);
    }

    /**
     * What runs the mechanics against what is drawn: the nodes drawn and measured, the nodes that run the mechanics
     * (fewer in a mapped scene, whose drawn mesh is carried by a coarse model), the measured error of that choice
     * against the drawn resolution (relative RMS, a fraction; NaN when not measured) and one line saying so.
     */
    record Resolution(int drawnNodes, int mechanicalNodes, double error, String describe) {
    }

    /**
     * Indices of the bodies that are organs around the scene's own (the lungs and the liver about the diaphragm):
     * drawn translucent, in a layer of their own that is shown or hidden at once. Default: none.
     */
    default List<Integer> organBodies() {
        return List.of();
    }

    /** Nodes the organs add to the simulated state (their cost), 0 without organs. */
    default int organNodes() {
        return 0;
    }

    /** The scene's {@link Resolution}, or null when the question does not arise (the cube, a scene file). */
    default Resolution resolution() {
        return null;
    }
}
