package org.tensim.scene.tunable;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.RibCage;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * The paper's diaphragm (section 3.2) for the GUI, over
 * {@link DiaphragmScene}: the diaphragm's two surfaces shaded, muscle red and
 * tendon pale, with the ribs, sternum and cartilage as lines; the dome apex is
 * the probe. The two control parameters of the paper (rib motion, muscle action)
 * act through the scene's {@link DiaphragmControls}; the breathing period is
 * fixed when a scene is built, so changing it restarts; its inspiration:expiration is the spec's (1:2 by default).
 *
 * <p><b>Tissue constants</b> go through the scene's own rules, those of
 * {@code tensim diaphragm}: a new tissue stiffness (the muscle's Young's modulus,
 * the tendon's kept in its ratio to it, {@link DiaphragmParameters#withTissueYoung}),
 * tissue damping (the damping ratio of the highest mode) or surrounding damping
 * (viscous, per second) makes new {@link DiaphragmParameters}; the scene is rebuilt
 * with them ({@link DiaphragmScene#rebuiltWith}) and the running simulation takes the
 * rebuilt scene's spring and damping constants
 * ({@link org.tensim.scene.diaphragm.LiveConstants#copy}), keeping its positions, velocities and time.
 * The recommended time step becomes the rebuilt scene's. A rebuild takes about 0.4 s at
 * the GUI's default resolution (20 rings, measured at a load average of 25): through
 * {@link #prepare} it is made on a background thread while the simulation keeps
 * stepping, and only the copy of the constants waits for a gap between two steps.
 *
 * <p>Tendon model: with rigid links (tensegrity, the paper's), or with every link
 * replaced by a spring ({@link RigidLinksAsSprings}) to compare.
 *
 * <p><b>Tendon boundary.</b> Without a label file, one more parameter moves the tendon's boundary: the plane's
 * height ({@link #TENDON_PLANE}, plane rule) or the area share ({@link #TENDON_SHARE}, geodesic rule). It changes
 * the topology (rigid links, fibres), so it restarts: the factory builds the scene from its spec with the boundary
 * moved ({@link #withTendonBoundary}). {@link #saveLabels} writes the labels of the scene on screen.
 *
 * <p><b>Live state</b> ({@link #liveState()}, {@link DiaphragmLiveState}): the nodes touching a bone, drawn blue over
 * their own colour, and the readouts (dome descent, contact area, penetration...), measured after every step.
 */
public final class DiaphragmViewScene implements ViewScene {
    public static final String RIB_AMPLITUDE = "ribAmplitudeFactor";
    public static final String MUSCLE_ACTION = "muscleActionPa";
    public static final String TISSUE_STIFFNESS = "tissueYoungPa";
    public static final String TISSUE_DAMPING = "tissueDampingRatio";
    public static final String SURROUNDING_DAMPING = "surroundingDampingPerS";
    public static final String BREATHING_PERIOD = "breathingPeriodS";
    /** The tendon's share of the upper surface (geodesic rule): moves the tendon's boundary; restarts. */
    public static final String TENDON_SHARE = "tendonAreaShare";
    /** The tendon plane's height from where the default share places it, mm (plane rule): moves it; restarts. */
    public static final String TENDON_PLANE = "tendonPlaneHeightMm";
    /** Range of {@link #TENDON_PLANE}, mm either way. */
    public static final double TENDON_PLANE_RANGE_MM = 40;
    /** Range of {@link #TENDON_SHARE}: a small cap to a large one (adults: 0.10-0.15). */
    public static final double[] TENDON_SHARE_RANGE = {0.03, 0.4};

    private static final DiaphragmParameters P = DiaphragmParameters.defaults();

    /**
     * The tunable parameters with the default muscle load (the sweep and calibration read their names and ranges
     * here; the ranges do not depend on the load).
     */
    public static final List<TunableParameter> PARAMETERS = parameters(BoundaryConditions.defaults().muscleLoad());

    /**
     * The tunable parameters of a scene with a muscle-load model: the muscle action's default and description are
     * the load's (an active fibre stress for fibres, a pressure for the others; {@link DiaphragmSetup#defaultMusclePa}).
     */
    public static List<TunableParameter> parameters(BoundaryConditions.MuscleLoad load) {
        return parameters(load, DiaphragmSpec.DEFAULT_TENDON_RULE, false);
    }

    /**
     * The tunable parameters of a scene with a muscle-load model and a tendon rule: with the plane rule the tendon
     * plane's height ({@link #TENDON_PLANE}), with the geodesic rule the tendon's area share ({@link #TENDON_SHARE});
     * neither when a label file sets the tendon ({@code labelled}).
     */
    public static List<TunableParameter> parameters(BoundaryConditions.MuscleLoad load, TendonRule rule,
            boolean labelled) {
        List<TunableParameter> l = new java.util.ArrayList<>(common(load));
        if (!labelled && rule == TendonRule.GEODESIC) {
            l.add(TunableParameter.linear(TENDON_SHARE, "Tendon area share", "", TENDON_SHARE_RANGE[0],
                    TENDON_SHARE_RANGE[1], P.tendonAreaFraction(), "Share of the upper surface's area that is central"
                            + " tendon, grown around the dome tops along the surface (geodesic rule; adults 0.10-0.15)."
                            + " Rebuilds the scene: the run restarts.").restarting());
        } else if (!labelled) {
            l.add(TunableParameter.linear(TENDON_PLANE, "Tendon plane height", "mm", -TENDON_PLANE_RANGE_MM,
                    TENDON_PLANE_RANGE_MM, 0, "Moves the plane above which the mesh is central tendon along its normal,"
                            + " from where the default area share (" + P.tendonAreaFraction() + ") places it: up gives"
                            + " less tendon. Rebuilds the scene: the run restarts.").restarting());
        }
        return List.copyOf(l);
    }

    private static List<TunableParameter> common(BoundaryConditions.MuscleLoad load) {
        String muscle = load == BoundaryConditions.MuscleLoad.FIBRES
                ? "Peak active stress of the muscle fibres along their meridians to the central tendon, at"
                        + " end-inspiration (muscle load: fibres)."
                : "Peak contraction force of the action lines per unit area of diaphragm, at end-inspiration (muscle"
                        + " load: " + BoundaryConditions.name(load) + ").";
        return List.of(
            TunableParameter.linear(RIB_AMPLITUDE, "Rib motion amplitude", "x quiet", 0,
                    DiaphragmControls.MAX_RIB_AMPLITUDE, 1,
                    "Rib rotation about each rib's helical axis, times quiet breathing (0: ribs still)."),
            TunableParameter.linear(MUSCLE_ACTION, load == BoundaryConditions.MuscleLoad.FIBRES
                    ? "Muscle fibre active stress" : "Muscle action pressure", "Pa", 0, DiaphragmControls.MAX_MUSCLE_PA,
                    DiaphragmSetup.defaultMusclePa(load), muscle),
            TunableParameter.log(TISSUE_STIFFNESS, "Tissue stiffness (muscle E)", "Pa", 4e3, 4e5, P.muscleYoungPa(),
                    "Young's modulus of the muscle; the tendon's springs keep their ratio to it. Stiffer: smaller"
                            + " deformation and a smaller stable time step."),
            TunableParameter.log(TISSUE_DAMPING, "Tissue damping ratio", "", 0.02, 1, P.highDampingRatio(),
                    "Damping ratio of the fastest mode from the springs' axial damping (RK2 needs some)."),
            TunableParameter.linear(SURROUNDING_DAMPING, "Surrounding damping", "1/s", 0, 200, P.viscousPerS(),
                    "Viscous drag per unit mass standing for the surrounding organs; damps the slow modes."),
            TunableParameter.linear(BREATHING_PERIOD, "Breathing period", "s", 2, 12, 4,
                    "Duration of one breath (inspiration:expiration 1:2). 4 s is 15 breaths per minute.")
                    .restarting());
    }

    private final boolean tensegrity;
    private final BoundaryConditions.MuscleLoad load;
    private List<TunableParameter> parameters;
    private org.tensim.scene.file.RunSettings fileRun; // the scene file's run when opened from one, else null
    private final Simulation sim;
    private List<Body> bodies;
    /** The scene whose constants the simulation runs with: the built one, or its latest rebuild. */
    private volatile DiaphragmScene scene;
    /** The scene with every change prepared so far, handed over or not (the preparing thread's). */
    private volatile DiaphragmScene prepared;

    /** Organs built into the scene's state, rebuilt into each rebuild of it; null for none. */
    private final DiaphragmOrgans organs;

    DiaphragmViewScene(DiaphragmScene scene, boolean tensegrity, BoundaryConditions.MuscleLoad load) {
        this(scene, tensegrity, load, null, null);
    }

    /**
     * With organs ({@code organs}, installed in {@code scene} as {@code built}): the mass-spring tendon's copy of the
     * topology runs their couplings too, and a tissue constant's rebuild builds them again (the same nodes and
     * springs), so that the running state takes its constants.
     */
    DiaphragmViewScene(DiaphragmScene scene, boolean tensegrity, BoundaryConditions.MuscleLoad load,
            DiaphragmOrgans organs, DiaphragmOrgans.Built built) {
        this.organs = organs;
        this.load = load;
        this.parameters = parameters(load, scene.spec().tendonRule(), scene.spec().mesh().labels() != null);
        this.scene = scene;
        this.prepared = scene;
        this.tensegrity = tensegrity;
        if (tensegrity) {
            sim = scene.newSimulation();
        } else {
            sim = Simulation.of(RigidLinksAsSprings.of(scene.topology()));
            if (built != null) {
                built.terms().forEach(sim.forces()::addTerm);
            }
        }
        SystemState s = sim.state();
        bodies = List.of(new Body("diaphragm apex", sim, scene.allTriangles(), colours(scene, s.nodeCount), Vec3.ZERO,
                scene.apexNode(), scene.simulatedNodes(), structure(scene)));
    }

    /** The cage's segments (ribs, sternum, cartilage) as node pairs, drawn as bone lines. */
    static int[] structure(DiaphragmScene scene) {
        List<RibCage.Segment> segments = scene.cage().segments();
        int[] structure = new int[2 * segments.size()];
        for (int i = 0; i < segments.size(); i++) {
            structure[2 * i] = segments.get(i).a();
            structure[2 * i + 1] = segments.get(i).b();
        }
        return structure;
    }

    /** The full model: every drawn node runs the mechanics; no error against itself at the paper's resolution. */
    @Override
    public Resolution resolution() {
        int nd = scene.diaphragmNodes();
        boolean paper = scene.spec().mesh().generated() && scene.spec().mesh().rings() == DiaphragmSpec.PAPER_RINGS;
        return new Resolution(nd, nd, paper ? 0 : Double.NaN, "full model, " + nd + " nodes, unmapped");
    }

    /** Colour of the muscle. */
    static final float[] MUSCLE_COLOUR = {0.78f, 0.23f, 0.2f};
    /** Colour of the central tendon. */
    static final float[] TENDON_COLOUR = {0.94f, 0.91f, 0.8f};
    /** Colour of the nodes attached at the diaphragm's origins. */
    static final float[] ATTACHED = {0.25f, 0.62f, 0.3f};
    /** Colour of the nodes touching a bone at the frame drawn ({@link DiaphragmLiveState#IN_CONTACT}). */
    static final float[] IN_CONTACT_COLOUR = {0.2f, 0.5f, 1f};

    /**
     * Each node's own colour (3 per node): muscle red, tendon pale, attached nodes green, ribs and spine bone, sternum
     * and cartilage blue-grey. The nodes touching a bone are marked over it frame by frame ({@link #liveState()}).
     */
    static float[] colours(DiaphragmScene scene, int nodes) {
        int[] labels = scene.labels();
        float[] c = new float[3 * nodes];
        for (int i = 0; i < nodes; i++) {
            float[] rgb = switch (i < labels.length ? labels[i] : -1) {
                case DiaphragmScene.MUSCLE -> MUSCLE_COLOUR;
                case DiaphragmScene.TENDON -> TENDON_COLOUR;
                case DiaphragmScene.RIB -> new float[] {0.93f, 0.89f, 0.76f};
                case DiaphragmScene.STERNUM_CARTILAGE -> new float[] {0.62f, 0.76f, 0.86f};
                default -> new float[] {0.5f, 0.5f, 0.5f};
            };
            if (i < scene.diaphragmNodes() && scene.isAttached(i)) {
                rgb = ATTACHED;
            }
            System.arraycopy(rgb, 0, c, 3 * i, 3);
        }
        return c;
    }

    /**
     * The scenes of a spec ({@link DiaphragmSpec}: mesh, cage or thorax, labels, tissue, boundary conditions), its
     * files read once; each scene takes the tuned values (rib amplitude, muscle action, breathing period) and
     * may switch the muscle load.
     */
    public static SceneFactory factory(DiaphragmSpec base) {
        return factory(base, null);
    }

    /**
     * As {@link #factory(DiaphragmSpec)} from inputs already read ({@link DiaphragmSetup#read} of {@code base}, or of
     * a spec that differs only in its label file, whose labels the inputs then carry); null to read them on first use.
     */
    public static DiaphragmViewFactory factory(DiaphragmSpec base, DiaphragmSetup.Inputs read) {
        return new DiaphragmViewFactory(base, read);
    }

    /**
     * Writes the labels of the scene on screen, one per mesh vertex ({@link DiaphragmScene#currentVertexLabels()}:
     * the tendon as now tuned, the origins), as a label file ({@link VertexLabelsFile}) that {@code --labels} reads
     * back; written to a temporary file beside it, then renamed over it.
     *
     * @param overwrite whether an existing file may be replaced
     * @return the number of vertices written
     * @throws java.nio.file.FileAlreadyExistsException when the file exists and {@code overwrite} is false
     */
    public int saveLabels(Path file, boolean overwrite) throws IOException {
        if (!overwrite && java.nio.file.Files.exists(file)) {
            throw new java.nio.file.FileAlreadyExistsException(file.toString(), null,
                    "exists; choose another name or confirm replacing it");
        }
        VertexLabel[] labels = scene.currentVertexLabels();
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        VertexLabelsFile.write(tmp, labels);
        try {
            java.nio.file.Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                    java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        } catch (java.nio.file.AtomicMoveNotSupportedException e) {
            java.nio.file.Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        return labels.length;
    }

    @Override
    public LiveState liveState() {
        return new DiaphragmLiveState(scene, sim.state().x0);
    }

    /** The underlying scene (for tests and reports): the built one, or its rebuild with the latest constants. */
    public DiaphragmScene scene() {
        return scene;
    }

    @Override
    public String name() {
        return "diaphragm";
    }

    @Override
    public String title() {
        return "Diaphragm: " + scene.diaphragmNodes() + " nodes, muscle (red) mass-spring, tendon (pale) "
                + (sim.state().linkCount() > 0 ? "tensegrity" : "mass-spring") + ", muscle load "
                + BoundaryConditions.name(load) + (scene.bones() == null ? "" : ", in " + scene.bones().source()
                + ": attached at the origins (green), touching a bone (blue)");
    }

    @Override
    public List<Body> bodies() {
        return bodies;
    }

    @Override
    public List<TunableParameter> parameters() {
        return parameters;
    }

    /** As a scene file opens it ({@link DiaphragmSceneFile}): its run's step, its values, the chart on its probe. */
    DiaphragmViewScene asFile(org.tensim.scene.file.RunSettings run, List<org.tensim.scene.file.SceneProbe> probes) {
        fileRun = run;
        parameters = DiaphragmSceneFile.startingAt(parameters, scene, load);
        bodies = DiaphragmSceneFile.charting(bodies, probes);
        return this;
    }

    @Override
    public String defaultIntegrator() {
        return fileRun == null ? null : DiaphragmSceneFile.integrator(fileRun, scene.spec());
    }

    @Override
    public double defaultTimeStep() { // the file's step unless it is dt: auto
        return fileRun == null || fileRun.autoStep() ? scene.recommendedTimeStep() : fileRun.dtS();
    }

    /** The vertical axis of the BodyParts3D frame (z, superior): the dome's excursion. */
    @Override
    public int defaultProbeAxis() {
        return 2;
    }

    /** As the paper's Fig. 5. */
    @Override
    public double displacementScale() {
        return 100;
    }

    /** z is superior in the BodyParts3D frame. */
    @Override
    public Vec3 up() {
        return new Vec3(0, 0, 1);
    }

    /** From the front (anterior is -y), a little to the patient's right, and above: the tendon shows. */
    @Override
    public Vec3 viewFrom() {
        return new Vec3(-0.3, -0.8, 0.55);
    }

    @Override
    public void apply(String key, double value) {
        prepare(key, value).run();
    }

    /** Rebuilds for a tissue constant here; the controls and the hand-over are left for the simulation thread. */
    @Override
    public Runnable prepare(String key, double value) {
        switch (key) {
            case RIB_AMPLITUDE -> {
                return () -> scene.controls().setRibAmplitude(value);
            }
            case MUSCLE_ACTION -> {
                return () -> scene.controls().setMuscleAmplitudePa(value);
            }
            case TISSUE_STIFFNESS -> {
                return retune(prepared.parameters().withTissueYoung(value));
            }
            case TISSUE_DAMPING -> {
                return retune(prepared.parameters().withDamping(value, prepared.parameters().viscousPerS()));
            }
            case SURROUNDING_DAMPING -> {
                return retune(prepared.parameters().withViscous(value));
            }
            case BREATHING_PERIOD -> throw new IllegalStateException(BREATHING_PERIOD
                    + " is fixed when the scene is built: make a new scene with it");
            default -> throw new IllegalArgumentException("diaphragm scene has no parameter '" + key + "'; known: "
                    + parameters.stream().map(TunableParameter::key).toList());
        }
    }

    /**
     * Rebuilds the scene with new constants and returns their hand-over to the running simulation;
     * nothing when they are the scene's already (a new scene is given every setting, mostly unchanged).
     */
    private Runnable retune(DiaphragmParameters p) {
        DiaphragmScene from = prepared;
        if (p.equals(from.parameters())) {
            return () -> { };
        }
        DiaphragmScene rebuilt = from.rebuiltWith(p);
        if (organs != null) {
            organs.build(rebuilt);
        }
        Topology constants = tensegrity ? rebuilt.topology() : RigidLinksAsSprings.of(rebuilt.topology());
        prepared = rebuilt;
        return () -> {
            org.tensim.scene.diaphragm.LiveConstants.copy(sim.state(), constants);
            scene = rebuilt;
        };
    }
}
