package org.tensim.tuning;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad;

/**
 * A complete, validated set of tunable values: what a preset file holds and what
 * is restored at the next start.
 *
 * @param scene            scene name, e.g. {@code cube}
 * @param integrator       integrator name, e.g. {@code rk2}
 * @param tensegrityTendon true when the tendon has rigid links (ignored by scenes without the choice)
 * @param values           parameter key to value (in the unit its key names), time step included
 * @param muscleLoad       the diaphragm's muscle-load model; null for a scene without a muscle
 * @param sceneOptions     the diaphragm scene's other options in command-line form ({@link DiaphragmOptions}, the
 *                         muscle load left out: it is {@code muscleLoad}), e.g. {@code ["--rings", "20"]}; empty
 *                         for the default scene, null when not recorded (older presets, the cube)
 */
public record Settings(String scene, String integrator, boolean tensegrityTendon, Map<String, Double> values,
        MuscleLoad muscleLoad, List<String> sceneOptions) {
    public Settings {
        values = Collections.unmodifiableMap(new LinkedHashMap<>(values));
        sceneOptions = sceneOptions == null ? null : List.copyOf(sceneOptions);
    }

    /** Settings whose scene options are not recorded. */
    public Settings(String scene, String integrator, boolean tensegrityTendon, Map<String, Double> values,
            MuscleLoad muscleLoad) {
        this(scene, integrator, tensegrityTendon, values, muscleLoad, null);
    }

    /** Settings of a scene without a muscle. */
    public Settings(String scene, String integrator, boolean tensegrityTendon, Map<String, Double> values) {
        this(scene, integrator, tensegrityTendon, values, null);
    }
}
