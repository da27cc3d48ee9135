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

    /** The muscle-load model this factory builds by default; null for a scene without a muscle. */
    default org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad muscleLoad() {
        return null;
    }

    /**
     * A new scene at rest with a muscle-load model, as {@link #create(boolean, Map)}: a change of the model
     * changes the loads' topology (the fibres' directions, the pressure's weights), so the scene is rebuilt.
     *
     * @param muscleLoad the model, or null for the factory's own ({@link #muscleLoad()})
     * @throws IllegalArgumentException for any model of a scene without a muscle
     */
    default ViewScene create(boolean tensegrityTendon, org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad
            muscleLoad, Map<String, Double> values) {
        if (muscleLoad != null && muscleLoad != muscleLoad()) {
            throw new IllegalArgumentException("muscle load '" + muscleLoad + "': scene '" + name()
                    + "' has no muscle load to choose");
        }
        return create(tensegrityTendon, values);
    }

    /**
     * The scene's parameters with a muscle-load model (their labels, defaults and descriptions depend on it: the
     * muscle action is an active stress with the fibres, a pressure otherwise), without building a scene.
     *
     * @param muscleLoad the model
     * @throws IllegalArgumentException for any model of a scene without a muscle
     */
    default java.util.List<TunableParameter> parameters(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad
            muscleLoad) {
        throw new IllegalArgumentException("muscle load '" + muscleLoad + "': scene '" + name()
                + "' has no muscle load to choose");
    }

    /** A new scene at rest with every parameter at its default. */
    default ViewScene create(boolean tensegrityTendon) {
        return create(tensegrityTendon, Map.of());
    }
}
