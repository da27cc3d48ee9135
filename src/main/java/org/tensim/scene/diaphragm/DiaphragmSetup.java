package org.tensim.scene.diaphragm;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.tensim.io.BoxesJson;
import org.tensim.io.ProjectFolder;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshReport;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * From files to a {@link DiaphragmScene}: reads and cleans the mesh, finds its two
 * boundary surfaces (a thin closed shell is split; a single surface is offset by
 * the thickness), takes the rib cage (the project's parametric one, or boxes read
 * from a file), builds the scene. Shared by the command, the GUI, the tests and the
 * studies. A boxes file of null everywhere below means the parametric cage,
 * {@link ParametricRibCage#adult()}.
 */
public final class DiaphragmSetup {
    /** The project's default mesh, relative to the project folder. */
    public static final Path DEFAULT_MESH = ProjectFolder.resolve("meshes", "diaphragm-default.obj");
    /**
     * BodyParts3D's rib and sternum boxes beside the project (optional: {@code --boxes} this file;
     * the default cage is {@link ParametricRibCage}).
     */
    public static final Path BODYPARTS3D_BOXES = ProjectFolder.resolve("..", "shared", "meshes", "bodyparts3d",
            "rib-sternum-bounds-mm.json");
    /**
     * Default peak muscle pressure, Pa, for {@link BoundaryConditions.MuscleLoad#PRESSURE} and
     * {@link BoundaryConditions.MuscleLoad#PAPER_NODES} (docs/diaphragm.md: gives a quiet-breathing dome excursion).
     * Not the default load's: see {@link #defaultMusclePa()}.
     */
    public static final double DEFAULT_MUSCLE_PA = 2600;
    /**
     * Default peak active fibre stress, Pa, for {@link BoundaryConditions.MuscleLoad#FIBRES} (docs/diaphragm.md,
     * "Active fibre tension": with the force-length relation and the default geodesic tendon, 17.4 mm of dome
     * excursion on the default mesh at 19 kPa; 18 kPa gave it with the paper's plane tendon). Within the 10-20 kPa
     * that Laplace's law gives from quiet breathing's 0.5-1 kPa.
     */
    public static final double DEFAULT_FIBRE_STRESS_PA = 19_000;

    /** The default muscle amplitude of the default muscle load ({@link BoundaryConditions#defaults()}), Pa. */
    public static double defaultMusclePa() {
        return defaultMusclePa(BoundaryConditions.defaults().muscleLoad());
    }

    /** The default muscle amplitude of a muscle-load model, Pa: an active stress for fibres, else a pressure. */
    public static double defaultMusclePa(BoundaryConditions.MuscleLoad model) {
        return model == BoundaryConditions.MuscleLoad.FIBRES ? DEFAULT_FIBRE_STRESS_PA : DEFAULT_MUSCLE_PA;
    }

    /**
     * Builds the scene a spec defines: reads and cleans its mesh (or generates the double dome), takes its
     * cage or thorax, builds the scene with new live controls at the spec's starting values. The one way
     * from a definition to a scene (command line, GUI, sweeps, calibration, tests).
     */
    public static Built build(DiaphragmSpec spec) throws IOException, MeshFormatException {
        return build(spec, spec.newControls());
    }

    /** As {@link #build(DiaphragmSpec)} with given live controls (a GUI's, kept across rebuilds). */
    public static Built build(DiaphragmSpec spec, DiaphragmControls controls) throws IOException, MeshFormatException {
        return build(read(spec), spec, controls);
    }

    /**
     * What a spec's files give, read once: its mesh's two surfaces, the cage's boxes or the thorax's bones, and
     * the mesh's labels. Scenes that differ only in constants are built from one reading ({@link #build(Inputs,
     * DiaphragmSpec, DiaphragmControls)}); a thorax's bones keep their signed distances across them.
     *
     * @param boxes  the cage's rib and sternum boxes, m (empty with a thorax)
     * @param bones  the thorax's bones, the cage's swept into surfaces ({@code --cage surfaces}), or null
     * @param labels per vertex, the label file's labels, or null
     */
    public record Inputs(Surfaces surfaces, MeshReport report, Map<String, double[]> boxes, Bones bones,
            org.tensim.io.mesh.VertexLabel[] labels, String source) {
    }

    /** Reads what a spec names: the mesh (or generates it), the cage's boxes or the thorax, the labels. */
    public static Inputs read(DiaphragmSpec spec) throws IOException, MeshFormatException {
        DiaphragmSpec.Mesh m = spec.mesh();
        MeshReport report = null;
        Surfaces s;
        if (m.generated()) {
            s = new Surfaces(generatedSurfaces(m.rings()), SurfaceMode.SHELL);
        } else {
            MeshCleaner.Result r = read(m.file(), m.units(), m.cleaning());
            report = r.report();
            s = surfaces(r.mesh(), m.offsetThicknessM());
        }
        org.tensim.io.mesh.VertexLabel[] labels = m.labels() == null ? null
                : org.tensim.io.mesh.VertexLabelsFile.read(m.labels(), s.surfaces().mesh().vertexCount());
        DiaphragmSpec.Cage cage = spec.cage();
        Map<String, double[]> boxes = cage.thorax() == null ? boxes(cage.boxes()) : Map.of();
        Bones bones = cage.thorax() != null ? ThoraxBones.load(cage.thorax())
                : cage.surfaces() ? ParametricBones.forBoxes(boxes) : null;
        return new Inputs(s, report, boxes, bones, labels, m.describe() + ", " + cage.describe());
    }

    /** Builds a spec's scene from its inputs, read once ({@link #read}), with the live controls given. */
    public static Built build(Inputs in, DiaphragmSpec spec, DiaphragmControls controls) {
        return new Built(DiaphragmScene.build(in.surfaces().surfaces(), spec, in.boxes(), in.bones(), in.labels(),
                controls), in.report(), in.surfaces().mode(), in.source());
    }

    /** How the two boundary surfaces were obtained. */
    public enum SurfaceMode { SHELL, OFFSET }

    /**
     * A built scene and where it came from.
     *
     * @param meshReport what the mesh cleaner found (null for a generated mesh)
     */
    public record Built(DiaphragmScene scene, MeshReport meshReport, SurfaceMode mode, String source) {
    }

    private DiaphragmSetup() {
    }

    /**
     * Reads a mesh and makes its two surfaces: split when it is a thin closed shell
     * (both sides found, thickness under 3 % of the size), else offset by
     * {@code offsetThicknessM}.
     */
    public static Built load(Path meshFile, MeshUnits units, double offsetThicknessM, Path boxesFile,
            DiaphragmParameters p, BreathingCycle cycle, DiaphragmControls controls)
            throws IOException, MeshFormatException {
        return load(meshFile, units, MeshCleaner.Options.defaults(), offsetThicknessM, null, boxesFile, p, cycle,
                controls);
    }

    /**
     * As {@link #load(Path, MeshUnits, double, Path, DiaphragmParameters, BreathingCycle, DiaphragmControls)}
     * with the mesh cleaner's settings (welding, small pieces kept or dropped) and the muscle's action lines
     * (null: the scene's default, one line through the top of each dome).
     */
    public static Built load(Path meshFile, MeshUnits units, MeshCleaner.Options cleaning, double offsetThicknessM,
            List<ActionLines.Line> lines, Path boxesFile, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls) throws IOException, MeshFormatException {
        return load(meshFile, units, cleaning, offsetThicknessM, lines, boxesFile, p, cycle, controls,
                BoundaryConditions.defaults());
    }

    /** As the overload above with the attachment and muscle-load models. */
    public static Built load(Path meshFile, MeshUnits units, MeshCleaner.Options cleaning, double offsetThicknessM,
            List<ActionLines.Line> lines, Path boxesFile, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls, BoundaryConditions bc) throws IOException, MeshFormatException {
        MeshCleaner.Result r = read(meshFile, units, cleaning);
        Surfaces s = surfaces(r.mesh(), offsetThicknessM);
        return new Built(DiaphragmScene.build(s.surfaces(), boxes(boxesFile), p, cycle, controls, lines, bc), r.report(),
                s.mode(), meshFile + ", " + cage(boxesFile));
    }

    /**
     * The two surfaces of a mesh file, read and cleaned with the default settings, as {@link #load} builds
     * its scene on: for building many scenes from one reading ({@link DiaphragmScene#build}).
     */
    public static Surfaces loadSurfaces(Path meshFile, MeshUnits units, double offsetThicknessM)
            throws IOException, MeshFormatException {
        return surfaces(read(meshFile, units, MeshCleaner.Options.defaults()).mesh(), offsetThicknessM);
    }

    private static MeshCleaner.Result read(Path meshFile, MeshUnits units, MeshCleaner.Options cleaning)
            throws IOException, MeshFormatException {
        MeshCleaner.Result r = MeshLoader.load(meshFile, units, cleaning);
        org.tensim.io.mesh.MeshExtent.refuseImplausibleSize(r.mesh(), meshFile, units, "diaphragm",
                PLAUSIBLE_SIZE_M[0], PLAUSIBLE_SIZE_M[1]);
        return r;
    }

    /** A mesh's two boundary surfaces and how they were found. */
    public record Surfaces(TwoSurfaces surfaces, SurfaceMode mode) {
    }

    /**
     * The two surfaces of a mesh: split when it is a thin closed shell (both sides found,
     * thickness under 3 % of the size), else the mesh offset by {@code offsetThicknessM}.
     */
    public static Surfaces surfaces(TriangleMesh m, double offsetThicknessM) {
        TwoSurfaces split = TwoSurfaces.split(m);
        double[] b = m.bounds();
        double size = Math.sqrt(sq(b[3] - b[0]) + sq(b[4] - b[1]) + sq(b[5] - b[2]));
        boolean shell = split.lowerCount() > 0.3 * split.upperCount() && split.upperCount() > 0.3 * split.lowerCount()
                && split.thicknessM() < 0.03 * size;
        return shell ? new Surfaces(split, SurfaceMode.SHELL)
                : new Surfaces(TwoSurfaces.offset(m, offsetThicknessM), SurfaceMode.OFFSET);
    }

    /** The generated double dome at a resolution (rings per face), split into its two faces. */
    public static Built generated(int rings, Path boxesFile, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls) throws IOException {
        return generated(rings, null, boxesFile, p, cycle, controls);
    }

    /** As {@link #generated(int, Path, DiaphragmParameters, BreathingCycle, DiaphragmControls)} with action lines. */
    public static Built generated(int rings, List<ActionLines.Line> lines, Path boxesFile, DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls) throws IOException {
        return generated(rings, lines, boxesFile, p, cycle, controls, BoundaryConditions.defaults());
    }

    /** As the overload above with the attachment and muscle-load models. */
    public static Built generated(int rings, List<ActionLines.Line> lines, Path boxesFile, DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls, BoundaryConditions bc) throws IOException {
        return new Built(DiaphragmScene.build(generatedSurfaces(rings), boxes(boxesFile), p, cycle, controls, lines, bc),
                null, SurfaceMode.SHELL, "generated double dome, " + rings + " rings, " + cage(boxesFile));
    }

    /** The two faces of the generated double dome at a resolution (rings per face), as {@link #generated} uses. */
    public static TwoSurfaces generatedSurfaces(int rings) {
        return TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings)));
    }

    /**
     * Plausible largest side of a diaphragm's bounding box, m: an adult's is about 0.3 m
     * transversely (BodyParts3D: 0.27 m; the project's double dome: 0.28 m); 0.08 m admits
     * a newborn's, 1 m any adult's with room to spare. A mesh outside this range is read in the
     * wrong --units (a metre file read as mm measures 0.3 mm) or is not a diaphragm.
     */
    public static final double[] PLAUSIBLE_SIZE_M = {0.08, 1.0};

    /**
     * The rib and sternum boxes, metres: the project's parametric cage when {@code file} is null, else
     * the file's boxes (millimetres), with a message that says where to find them.
     */
    public static Map<String, double[]> boxes(Path file) throws IOException {
        if (file == null) {
            return ParametricRibCage.adult();
        }
        if (!Files.isRegularFile(file)) {
            throw new IOException(file + ": rib and sternum boxes not found; expected BodyParts3D's"
                    + " rib-sternum-bounds-mm.json or boxes of that form (or leave out --boxes for the project's"
                    + " parametric rib cage)");
        }
        return BoxesJson.read(file, 1e-3);
    }

    /** Which rib cage a boxes file (null: the parametric one) stands for, for summaries. */
    public static String cage(Path boxesFile) {
        return boxesFile == null ? "parametric rib cage" : "rib boxes " + boxesFile;
    }

    private static double sq(double x) {
        return x * x;
    }
}
