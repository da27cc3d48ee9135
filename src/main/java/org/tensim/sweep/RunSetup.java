package org.tensim.sweep;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.TunableScenes;

/**
 * What every point of a sweep shares, sent as is to the workers (hence serializable,
 * with paths as strings): the scene and its geometry, the solver settings, the values
 * of the parameters that are not swept, and extra measures taken during each run
 * (calibration targets).
 *
 * @param scene       scene name, as in {@link org.tensim.tuning.TunableScenes} ({@code diaphragm} or {@code cube}),
 *                    or the absolute path of a scene file (docs/scenes.md)
 * @param diaphragm   the diaphragm's options as a command line gives them ({@link DiaphragmOptions}, e.g.
 *                    {@code ["--thorax", "/data/thorax", "--muscle-load", "pressure"]}); empty for the defaults
 *                    (the generated double dome at the GUI's resolution in the parametric cage) and for the cube
 * @param integrator  name of a setup in the integrator catalogue ({@link org.tensim.solver.integrators.Integrators}:
 *                    e.g. {@code rk2}, {@code implicit-euler-cg1e-3}, {@code bdf2-newton2})
 * @param dtS         time step, s; 0 for the scene's own (see {@link SceneRun})
 * @param seconds     simulated time of each run, s
 * @param fixed       values of parameters held fixed, by key (the others not swept keep their defaults)
 * @param measures    extra measures taken during each run; they add fields to the summary
 * @param overrides   for a scene file ({@code scene} its absolute path, {@link SceneFileRun}): the spec's
 *                    {@code overrides} as {@code --set} options ({@code NAME=VALUE} or {@code key.path=VALUE}),
 *                    applied before the point's values; empty for the built-in scenes
 */
public record RunSetup(String scene, List<String> diaphragm, String integrator, double dtS, double seconds,
        Map<String, Double> fixed, List<Measure> measures, List<String> overrides) implements Serializable {
    private static final long serialVersionUID = 3L;

    public RunSetup {
        diaphragm = List.copyOf(diaphragm);
        fixed = Collections.unmodifiableMap(new LinkedHashMap<>(fixed));
        measures = Collections.unmodifiableList(new ArrayList<>(measures));
        overrides = List.copyOf(overrides);
    }

    /** A setup of a built-in scene (no overrides). */
    public RunSetup(String scene, List<String> diaphragm, String integrator, double dtS, double seconds,
            Map<String, Double> fixed, List<Measure> measures) {
        this(scene, diaphragm, integrator, dtS, seconds, fixed, measures, List.of());
    }

    /** The same setup with other measures (calibration adds its targets'). */
    public RunSetup withMeasures(List<Measure> m) {
        return new RunSetup(scene, diaphragm, integrator, dtS, seconds, fixed, m, overrides);
    }

    /** The diaphragm's scene definition (meaningful for the diaphragm scene only). */
    public DiaphragmSpec diaphragmSpec() {
        return DiaphragmOptions.parse(diaphragm).spec(null, TunableScenes.defaultRings());
    }

    /** The diaphragm's muscle load, or null for a scene without a muscle. */
    public BoundaryConditions.MuscleLoad muscleLoad() {
        return scene.equals("diaphragm") ? diaphragmSpec().boundary().muscleLoad() : null;
    }

    /** One line describing the geometry, for logs and reports. */
    public String geometry() {
        if (SceneFileRun.isFile(scene)) {
            return "scene file " + scene + (overrides.isEmpty() ? "" : " with " + String.join(", ", overrides));
        }
        if (!scene.equals("diaphragm")) {
            return scene;
        }
        DiaphragmSpec s = diaphragmSpec();
        return "diaphragm " + s.mesh().describe() + ", " + s.cage().describe() + ", muscle load " + BoundaryConditions.name(muscleLoad());
    }
}
