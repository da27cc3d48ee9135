package org.tensim.sweep;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.diaphragm.BoundaryConditions;

/**
 * What every point of a sweep shares, sent as is to the workers (hence serializable,
 * with paths as strings): the scene and its geometry, the solver settings, the values
 * of the parameters that are not swept, and extra measures taken during each run
 * (calibration targets).
 *
 * @param scene       scene name, as in {@link org.tensim.tuning.TunableScenes} ({@code diaphragm} or {@code cube})
 * @param meshFile    diaphragm mesh file (.obj, .stl, .off), or null for the generated double dome
 * @param units       units of the mesh file, {@code mm} or {@code m}
 * @param thicknessMm thickness given to a single-surface mesh, mm
 * @param rings       rings per face of the generated double dome (when there is no mesh file)
 * @param boxesFile   rib and sternum boxes (millimetres, BodyParts3D frame), or null for the project's parametric
 *                    rib cage (the GUI's default)
 * @param muscleLoad  diaphragm muscle load model as on the command line ({@code fibres}, the default,
 *                    {@code pressure}, {@code paper-nodes}); null for the default, fibres
 * @param integrator  name of a setup in the integrator catalogue ({@link org.tensim.solver.integrators.Integrators}:
 *                    e.g. {@code rk2}, {@code implicit-euler-cg1e-3}, {@code bdf2-newton2})
 * @param dtS         time step, s; 0 for the scene's own (see {@link SceneRun})
 * @param seconds     simulated time of each run, s
 * @param fixed       values of parameters held fixed, by key (the others not swept keep their defaults)
 * @param measures    extra measures taken during each run; they add fields to the summary
 */
public record RunSetup(String scene, String meshFile, String units, double thicknessMm, int rings, String boxesFile,
        String muscleLoad, String integrator, double dtS, double seconds, Map<String, Double> fixed, List<Measure> measures)
        implements Serializable {
    private static final long serialVersionUID = 1L;

    public RunSetup {
        fixed = Collections.unmodifiableMap(new LinkedHashMap<>(fixed));
        measures = Collections.unmodifiableList(new ArrayList<>(measures));
    }

    /** The same setup with other measures (calibration adds its targets'). */
    public RunSetup withMeasures(List<Measure> m) {
        return new RunSetup(scene, meshFile, units, thicknessMm, rings, boxesFile, muscleLoad, integrator, dtS, seconds,
                fixed, m);
    }

    /** The same setup with more fixed values (they replace existing ones with the same key). */
    public RunSetup withFixed(Map<String, Double> more) {
        Map<String, Double> f = new LinkedHashMap<>(fixed);
        f.putAll(more);
        return new RunSetup(scene, meshFile, units, thicknessMm, rings, boxesFile, muscleLoad, integrator, dtS, seconds, f,
                measures);
    }

    /** One line describing the geometry, for logs and reports. */
    public String geometry() {
        if (!scene.equals("diaphragm")) {
            return scene;
        }
        String g = meshFile != null ? "diaphragm mesh " + meshFile : "generated double dome, " + rings + " rings";
        return g + ", muscle load " + (muscleLoad == null
                ? BoundaryConditions.DEFAULT_MUSCLE_LOAD + " (default)" : muscleLoad);
    }
}
