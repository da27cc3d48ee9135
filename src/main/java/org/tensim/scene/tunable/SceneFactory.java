package org.tensim.scene.tunable;

import java.util.Map;

/**
 * Makes fresh instances of one scene, for a start, a reset, or a change that
 * needs a new topology (the tendon's model). Creation may take time (mesh
 * loading): it is called on the simulation thread, never on the Swing thread.
 */
public interface SceneFactory {
    /** The scene's name, as {@link ViewScene#name()}. */
    String name();

    /**
     * Whether the tendon can be switched between mass-spring and tensegrity. False
     * for the cube, which shows both side by side.
     */
    boolean hasTendonChoice();

    /**
     * A new scene at rest. The values of parameters that need a new scene
     * ({@link TunableParameter#restarts()}) are taken from {@code values} here;
     * the others are applied afterwards through {@link ViewScene#apply}.
     *
     * @param tensegrityTendon true: the tendon has rigid links; ignored without a tendon choice
     * @param values           parameter values by key; missing keys take their defaults
     */
    ViewScene create(boolean tensegrityTendon, Map<String, Double> values);

    /** A new scene at rest with every parameter at its default. */
    default ViewScene create(boolean tensegrityTendon) {
        return create(tensegrityTendon, Map.of());
    }
}
