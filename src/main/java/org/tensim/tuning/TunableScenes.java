package org.tensim.tuning;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.tensim.experiment.diaphragm.ResolutionPick;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.model.Check;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.solver.integrators.Integrators;

/** The scenes the GUI can show, by name. */
public final class TunableScenes {
    private TunableScenes() {
    }

    /**
     * Where a scene's geometry comes from (the diaphragm's; the cube is built in).
     *
     * @param mesh        mesh file, or null for the generated double dome
     * @param units       units of the mesh file, {@code mm} or {@code m}
     * @param thicknessMm thickness given to a single-surface mesh, mm
     * @param rings       resolution of the generated double dome, rings per face
     * @param boxes       rib and sternum boxes file, or null for the project's parametric rib cage
     * @param muscleLoad  the diaphragm's muscle load model as on the command line ({@code fibres},
     *                    {@code pressure}, {@code paper-nodes}), or null for the default
     *                    ({@link BoundaryConditions#DEFAULT_MUSCLE_LOAD}, fibres)
     * @param thorax      a thorax folder (parts.json and bone surfaces), or null
     * @param labels      a label file of the mesh, or null
     * @param tendonRule  {@code plane} or {@code geodesic}, or null for the plane
     * @param model       {@code default} or {@code paper}, or null for the default
     */
    public record Source(Path mesh, String units, double thicknessMm, int rings, Path boxes, String muscleLoad,
            Path thorax, Path labels, String tendonRule, String model) {
        /** With the default muscle load. */
        public Source(Path mesh, String units, double thicknessMm, int rings, Path boxes) {
            this(mesh, units, thicknessMm, rings, boxes, null);
        }

        /** Without a thorax or labels. */
        public Source(Path mesh, String units, double thicknessMm, int rings, Path boxes, String muscleLoad) {
            this(mesh, units, thicknessMm, rings, boxes, muscleLoad, null, null, null, null);
        }

        /**
         * The defaults: the generated dome at the resolution the resolution study picked
         * ({@link ResolutionPick}, meshes/resolution-pick.json; the paper's 43 rings when there is none),
         * the project's parametric rib cage.
         */
        public static Source defaults() {
            return new Source(null, "mm", 2.5, ResolutionPick.read().rings(), null);
        }
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
     * The factory of a scene.
     *
     * @throws IllegalArgumentException for an unknown name, a mesh given to the cube, or a bad source
     */
    public static SceneFactory factory(String name, Source src) {
        switch (name) {
            case "cube":
                if (src.muscleLoad() != null) {
                    throw new IllegalArgumentException("--muscle-load " + src.muscleLoad() + ": the cube has no muscle;"
                            + " --muscle-load applies to the diaphragm");
                }
                if (src.mesh() != null) {
                    throw new IllegalArgumentException("--mesh " + src.mesh() + ": the cube scene is built in and reads"
                            + " no mesh; --mesh applies to the diaphragm");
                }
                return CubeViewScene.factory();
            case "diaphragm":
                if (src.mesh() != null && !Files.isRegularFile(src.mesh())) {
                    // A missing input file is a refused file (exit 1), not a usage error (docs/outputs.md).
                    String msg = "--mesh " + src.mesh() + ": no such file (expected an .obj, .stl"
                            + " or .off mesh of the diaphragm)";
                    throw new java.io.UncheckedIOException(msg, new java.io.FileNotFoundException(msg));
                }
                Check.atLeast("--resolution (rings per face of the generated dome)", src.rings(), 2);
                Check.positive("--thickness", "mm", src.thicknessMm());
                boolean paper = "paper".equals(src.model());
                if (src.model() != null && !paper && !"default".equals(src.model())) {
                    throw new IllegalArgumentException("--model must be default or paper, got '" + src.model() + "'");
                }
                DiaphragmSpec base = paper ? DiaphragmSpec.paper() : DiaphragmSpec.defaults();
                BoundaryConditions bc = base.boundary();
                if (src.muscleLoad() != null) {
                    try {
                        bc = bc.withMuscleLoad(BoundaryConditions.parse(BoundaryConditions.MuscleLoad.class,
                                src.muscleLoad()));
                    } catch (IllegalArgumentException e) {
                        throw new IllegalArgumentException("--muscle-load: " + e.getMessage(), e);
                    }
                }
                DiaphragmSpec.Mesh m = DiaphragmSpec.Mesh.defaults().withRings(src.rings())
                        .withOffsetThickness(src.thicknessMm() * 1e-3).withLabels(src.labels());
                DiaphragmSpec spec = base.withMesh(src.mesh() == null ? m
                        : m.withFile(src.mesh(), MeshUnits.parse(src.units()))).withBoundary(bc)
                        .withCage(base.cage().withBoxes(src.boxes()).withThorax(src.thorax()))
                        .withTendonRule(src.tendonRule() == null ? TendonRule.PLANE
                                : BoundaryConditions.parse(TendonRule.class, src.tendonRule()));
                return DiaphragmViewScene.factory(spec);
            default:
                throw new IllegalArgumentException("--scene '" + name + "' is not a scene; expected one of " + names());
        }
    }
}
