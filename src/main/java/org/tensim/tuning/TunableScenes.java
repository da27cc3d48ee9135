package org.tensim.tuning;

import java.nio.file.Files;
import java.util.List;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.solver.integrators.Integrators;

/** The scenes the GUI can show, by name. */
public final class TunableScenes {
    private TunableScenes() {
    }

    /**
     * Whether the scene opens with the large-step solver ({@link Integrators#REAL_TIME} at
     * {@link Integrators#REAL_TIME_STEP_S}) rather than the paper's RK2: the diaphragm, which RK2
     * runs at a few hundredths of real time at the paper's resolution (43 rings: 11,354 diaphragm nodes,
     * the mesh of {@code ./tensim diaphragm}). Last-used parameters and presets
     * still apply over it.
     */
    public static boolean opensInRealTime(String name) {
        return "diaphragm".equals(name);
    }

    /** Names accepted by {@code --scene}, the default first. */
    public static List<String> names() {
        return List.of("diaphragm", "cube");
    }

    /**
     * The factory of a scene: the cube, or the diaphragm these options describe (the generated double dome at
     * {@code --rings}, or {@link #defaultRings()}, when no mesh is given; {@link PickOption} sets the rings from a
     * resolution study's pick).
     *
     * @throws IllegalArgumentException for an unknown name, a diaphragm option given to the cube, or a bad option
     */
    public static SceneFactory factory(String name, DiaphragmOptions options) {
        switch (name) {
            case "cube":
                if (options.muscleLoad != null) {
                    throw new IllegalArgumentException("--muscle-load " + BoundaryConditions.name(options.muscleLoad) + ": the cube has no"
                            + " muscle; --muscle-load applies to the diaphragm");
                }
                if (options.mesh != null) {
                    throw new IllegalArgumentException("--mesh " + options.mesh + ": the cube scene is built in and"
                            + " reads no mesh; --mesh applies to the diaphragm");
                }
                return CubeViewScene.factory();
            case "diaphragm":
                if (options.mesh != null && !Files.isRegularFile(options.mesh)) {
                    // A missing input file is a refused file (exit 1), not a usage error (docs/outputs.md).
                    String msg = "--mesh " + options.mesh + ": no such file (expected an .obj, .stl"
                            + " or .off mesh of the diaphragm)";
                    throw new java.io.UncheckedIOException(msg, new java.io.FileNotFoundException(msg));
                }
                return DiaphragmViewScene.factory(options.spec(null, defaultRings()));
            default:
                throw new IllegalArgumentException("--scene '" + name + "' is not a scene; expected one of " + names());
        }
    }

    /**
     * Rings of the generated double dome in the GUI and specs when neither {@code --rings} nor {@code --pick} is
     * given: the paper's 43 (no pick is read unless named).
     */
    public static int defaultRings() {
        return DiaphragmSpec.PAPER_RINGS;
    }

    /**
     * Sets the diaphragm factory's mechanics to the pick {@link PickOption#choose} gives for its spec (the scene's
     * mechanics then run at the pick's rings, the spec's 43-ring mesh carried and drawn); nothing for another factory.
     *
     * @param note receives why the full model runs when the shipped pick does not match the scene
     * @return the pick used, or null for the full model
     */
    public static org.tensim.experiment.diaphragm.ResolutionPick mapMechanics(SceneFactory factory, PickOption pick,
            DiaphragmOptions options, java.util.function.Consumer<String> note) {
        if (!(factory instanceof org.tensim.scene.tunable.DiaphragmViewFactory f)) {
            return null;
        }
        org.tensim.experiment.diaphragm.ResolutionPick p = pick.choose(options, f.spec(), note);
        if (p != null) {
            f.mapMechanics(new org.tensim.scene.tunable.DiaphragmViewFactory.Mechanics(p.rings(), p.error(),
                    p.source()));
        }
        return p;
    }
}
