package org.tensim.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.experiment.diaphragm.RealTimeSetting;
import org.tensim.experiment.diaphragm.RealTimeStudy;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.experiment.diaphragm.ResolutionPick;
import org.tensim.experiment.diaphragm.ResolutionStudy;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.ActionLines;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.TissueModel;
import org.tensim.solver.integrators.Integrators;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim diaphragm}: the paper's second experiment, headless. */
@Command(name = "diaphragm", mixinStandardHelpOptions = true,
        description = {"The paper's diaphragm (section 3.2): muscle as mass-spring, central",
            "tendon as tensegrity, driven by ribs (finite helical axes) and action",
            "lines, for some breathing cycles. Writes PNG displacement slices,",
            "displacements.csv, probe.csv, a VTK series and summary.json to --out and",
            "prints the summary as the last line (JSON). Model: docs/diaphragm.md."})
public final class DiaphragmCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--mesh", paramLabel = "FILE",
            description = "diaphragm mesh (.obj, .stl, .off): a thin closed shell, or one surface to offset"
                    + " (default: ${DEFAULT-VALUE})")
    Path mesh = DiaphragmSetup.DEFAULT_MESH;

    @Option(names = "--units", paramLabel = "mm|m", description = "units of the mesh file (default: ${DEFAULT-VALUE})")
    String units = "mm";

    @Option(names = "--thickness", paramLabel = "MM",
            description = "thickness used when the mesh is a single surface, mm (default: ${DEFAULT-VALUE})")
    double thicknessMm = 2.5;

    @Option(names = "--boxes", paramLabel = "FILE",
            description = "rib and sternum boxes, mm, BodyParts3D frame, e.g. BodyParts3D's"
                    + " ../shared/meshes/bodyparts3d/rib-sternum-bounds-mm.json (default: the project's parametric"
                    + " rib cage, placed on the generated dome)")
    Path boxes;

    @Option(names = "--thorax", paramLabel = "DIR",
            description = "a thorax of bone surfaces: a folder with a parts.json and its OBJ parts in the mesh's frame,"
                    + " e.g. ../shared/meshes/thorax (ribs, cartilage, sternum and vertebrae; the diaphragm attached at"
                    + " its origins and sliding on the bones elsewhere) (default: the parametric rib cage)")
    Path thorax;

    @Option(names = "--labels", paramLabel = "FILE",
            description = "per-vertex labels of the mesh (tendon, muscle, origin-sternal, origin-costal,"
                    + " origin-lumbar; 'tensim-labels 1' format) (default: derived by rule)")
    Path labels;

    @Option(names = "--tendon-rule", paramLabel = "RULE",
            description = "how the central tendon is found without --labels: plane (the paper's: the cap above a"
                    + " plane, --tendon-fraction of the upper surface) or geodesic (the region nearest the two dome"
                    + " tops and their midpoint along the surface, the same share) (default: ${DEFAULT-VALUE})")
    String tendonRule = "plane";

    @Option(names = "--contact", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "with --thorax: the muscle slides on the bones, frictionless and one-sided, where it is"
                    + " not attached (default: on; --no-contact turns it off)")
    boolean contact = true;

    @Option(names = "--contact-stiffness", paramLabel = "PA_PER_M",
            description = "contact penalty stiffness per unit area of diaphragm, Pa/m (default: ${DEFAULT-VALUE})")
    double contactPaPerM = org.tensim.scene.diaphragm.DiaphragmSpec.Cage.DEFAULT_CONTACT_PA_PER_M;

    @Option(names = "--model", paramLabel = "NAME",
            description = "default (the material shell, the attachment band, the fibres' active tension) or paper"
                    + " (exactly the paper's section 3.2: its tissue springs, attachment by a distance threshold,"
                    + " vertical action lines with per-node forces); the paper's model sets --tissue-model,"
                    + " --attachment and --muscle-load, which must then be left out (default: ${DEFAULT-VALUE})")
    String model = "default";

    @Option(names = "--seconds", paramLabel = "S", description = "simulated time, s; the breathing figures need one"
            + " inspiration (1.33 s at the default cycle) (default: ${DEFAULT-VALUE})")
    double seconds = 4;

    @Option(names = "--rib-amplitude", paramLabel = "FACTOR",
            description = "rib rotation, times the quiet-breathing value, 0..3 (default: ${DEFAULT-VALUE})")
    double ribAmplitude = 1;

    @Option(names = "--muscle-force", paramLabel = "PA",
            description = "peak muscle action, Pa, 0..30000: active fibre stress (--muscle-load fibres, the default;"
                    + " default " + DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA + ") or force per unit area of diaphragm"
                    + " (pressure, paper-nodes; default " + DiaphragmSetup.DEFAULT_MUSCLE_PA + ")")
    Double musclePa;

    @Option(names = "--period", paramLabel = "S", description = "breathing period, s (default: ${DEFAULT-VALUE})")
    double period = 4;

    @Option(names = "--ie-ratio", paramLabel = "R",
            description = "expiration time over inspiration time, I:E = 1:R (default: ${DEFAULT-VALUE})")
    double ieRatio = 2;

    @Option(names = "--attach-threshold", paramLabel = "MM",
            description = "attach diaphragm nodes closer than this to ribs, cartilage or sternum, mm"
                    + " (default: ${DEFAULT-VALUE})")
    double attachMm = DiaphragmParameters.defaults().attachThresholdM() * 1e3;

    @Option(names = "--attachment", paramLabel = "MODEL",
            description = "band (elastic ties, a stiffness per unit area) or paper-threshold (the paper's: nodes"
                    + " within the threshold driven with the ribs) (default: ${DEFAULT-VALUE})")
    String attachment = "band";

    @Option(names = "--band-stiffness", paramLabel = "PA_PER_M",
            description = "attachment band stiffness per unit area of diaphragm, Pa/m (default: ${DEFAULT-VALUE})")
    double bandPaPerM = BoundaryConditions.DEFAULT_BAND_PA_PER_M;

    @Option(names = "--band-all-segments",
            description = "attachment band: attach to every cage segment within the threshold, not only to the"
                    + " diaphragm's origins (ribs 7-12 and their cartilages, the xiphoid, the spine)")
    boolean allSegments;

    @Option(names = "--muscle-load", paramLabel = "MODEL",
            description = "fibres (active tension along the fibres to the central tendon, 18 kPa of fibre stress),"
                    + " pressure (action-line traction integrated over the muscle's area, 2.6 kPa) or paper-nodes (the"
                    + " paper's per-node forces, 2.6 kPa) (default: ${DEFAULT-VALUE})")
    String muscleLoad = BoundaryConditions.DEFAULT_MUSCLE_LOAD;

    @Option(names = "--weld-tolerance", paramLabel = "MM",
            description = "mesh cleaning: vertices closer than this are merged, mm (default: ${DEFAULT-VALUE})")
    double weldMm = 1e3 * MeshCleaner.Options.defaults().weldToleranceM();

    @Option(names = "--min-piece-fraction", paramLabel = "F",
            description = "mesh cleaning: disconnected pieces with fewer than this fraction of the triangles are"
                    + " dropped; 0 keeps every piece (default: ${DEFAULT-VALUE})")
    double minPieceFraction = MeshCleaner.Options.defaults().minComponentFraction();

    @Option(names = "--tendon-normal", paramLabel = "X,Y,Z", split = ",",
            description = "normal of the muscle/tendon plane, pointing to the tendon (default: 0,0,1, superior)")
    double[] tendonNormal;

    @Option(names = "--tendon-point", paramLabel = "X,Y,Z", split = ",",
            description = "a point of the muscle/tendon plane, mm, mesh frame (default: placed so that the tendon"
                    + " has --tendon-fraction of the upper surface)")
    double[] tendonPointMm;

    @Option(names = "--tendon-fraction", paramLabel = "F",
            description = "share of the upper surface's area given to the tendon when no --tendon-point is given"
                    + " (default: ${DEFAULT-VALUE})")
    double tendonFraction = DiaphragmParameters.defaults().tendonAreaFraction();

    @Option(names = "--tissue-model", paramLabel = "NAME",
            description = "how the shell comes from the tissue: material (identified from E, nu and t: membrane"
                    + " triangles, Kirchhoff bending, rigid columns), springs (the same with edge springs only) or"
                    + " paper (the model the paper's figures were reproduced with) (default: ${DEFAULT-VALUE};"
                    + " docs/diaphragm.md)")
    String tissueModel = DiaphragmParameters.defaults().tissueModel().name().toLowerCase();

    @Option(names = "--action-line", paramLabel = "X,Y,R", converter = ActionLineConverter.class,
            description = "a vertical muscle action line through (X, Y) with radius of action R, mm; repeat for"
                    + " several (default: one through the top of each dome, R = 0.3 x the mesh width); for"
                    + " --muscle-load pressure and paper-nodes (the fibres' tension has no action lines)")
    List<ActionLines.Line> actionLines;

    @Option(names = "--integrator", paramLabel = "NAME", completionCandidates = Integrators.Names.class,
            description = "integrator: ${COMPLETION-CANDIDATES}; rk2 is the paper's (default: ${DEFAULT-VALUE})")
    String integrator = Integrators.DEFAULT;

    @Option(names = "--threads", paramLabel = "N",
            description = "threads that share each step; 0 = automatic: all cores from "
                    + org.tensim.solver.parallel.Parallelism.AUTO_PARALLEL_SPRINGS + " springs, else 1 (default: ${DEFAULT-VALUE})")
    int threads = 0;

    @Option(names = "--cg-tolerance", paramLabel = "R",
            description = "implicit-euler only: relative residual at which each step's CG solve stops"
                    + " (default: 1e-12)")
    Double cgTolerance;

    @Option(names = "--newton", paramLabel = "N",
            description = "bdf2 only: Newton iterations per step (default: "
                    + org.tensim.solver.prefactored.PrefactoredBdf2.DEFAULT_NEWTON_ITERATIONS + "; with --thorax: "
                    + org.tensim.solver.prefactored.PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS + ", docs/thorax.md)")
    Integer newton;

    @Option(names = "--cg-iterations", paramLabel = "N",
            description = "bdf2 only: cap on CG iterations per Newton iteration (default: "
                    + org.tensim.solver.prefactored.PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS + "; with --thorax: "
                    + org.tensim.solver.prefactored.PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS + ")")
    Integer cgIterations;

    @Option(names = "--dt", paramLabel = "S",
            description = "time step, s (default: the step the time-step policy recommends for the integrator on"
                    + " this scene; summary.json's dt_rule says how it was chosen)")
    double dt = 0;

    @Option(names = "--realtime",
            description = "run the fastest configuration the real-time study measured within 5 %% of RK2 on the"
                    + " default mesh, on all cores; the summary names it (realtime_setting)")
    boolean realtime;

    @Option(names = "--study-rings", split = ",", paramLabel = "N[,N...]",
            description = "--realtime-study, --resolution-study: ring counts, ascending (default: 10,14,20,28,43;"
                    + " given to the resolution study, the double domes only, the finest as reference, no pick)")
    int[] studyRings;

    @Option(names = "--study-configs", paramLabel = "REGEX",
            description = "--realtime-study only: run the configurations whose label this finds (RK2 on two threads,"
                    + " the reference of each resolution, always runs)")
    String studyConfigs;

    @Option(names = "--vtk-per-cycle", paramLabel = "N",
            description = "VTK frames per breathing cycle, 0 for none (default: ${DEFAULT-VALUE})")
    int vtkPerCycle = 8;

    @Option(names = "--vector-scale", paramLabel = "X",
            description = "scale of the mid-inspiration displacement vectors (default: ${DEFAULT-VALUE}, as Fig. 5)")
    double vectorScale = 100;

    @Option(names = "--csv-times", paramLabel = "S", split = ",",
            description = "times of displacements.csv, s (default: end-inspiration and end of the last cycle)")
    double[] csvTimes;

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default: ${DEFAULT-VALUE})")
    Path out = Path.of("out", "diaphragm");

    @Option(names = "--resolution-study",
            description = "run the resolution study instead (docs/diaphragm.md); uses --seconds per resolution")
    boolean resolutionStudy;

    @Option(names = "--tolerance", paramLabel = "E",
            description = "resolution study: relative RMS error under which a coarser model is accepted"
                    + " (default: ${DEFAULT-VALUE})")
    double tolerance = ResolutionStudy.TOLERANCE;

    @Option(names = "--cells", paramLabel = "MM", split = ",",
            description = "resolution study with --mesh: vertex-clustering cell sizes, mm (default: 4, 2.8 and 2"
                    + " times the mesh's mean edge length)")
    double[] cellsMm;

    @Option(names = "--refine", paramLabel = "N",
            description = "resolution study with --mesh: also the mesh refined 1..N times by midpoint subdivision"
                    + " (default: ${DEFAULT-VALUE})")
    int refine;

    @Option(names = "--no-pick", description = "resolution study: do not write the pick to meshes/"
            + "resolution-pick.json (it still goes to --out)")
    boolean noPick;

    @Option(names = "--realtime-study",
            description = "run the real-time study instead: 10 to 43 rings, RK2 (1 and 2 threads) and implicit Euler"
                    + " at 5, 10, 20 ms, one inspiration each, error against the paper's configuration vs speed"
                    + " (docs/diaphragm.md)")
    boolean realtimeStudy;

    @Override
    public Integer call() throws Exception {
        // Options are checked before the mesh is read, which takes seconds.
        org.tensim.solver.Integrator chosen = org.tensim.solver.integrators.Integrators.create(integrator);
        if (cgTolerance != null && !(chosen instanceof org.tensim.solver.integrators.ImplicitEuler)) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--cg-tolerance applies to --integrator implicit-euler only, not " + integrator);
        }
        if ((newton != null || cgIterations != null)
                && !(chosen instanceof org.tensim.solver.prefactored.PrefactoredBdf2)) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--newton and --cg-iterations apply to --integrator bdf2 only, not " + integrator);
        }
        try {
            configured(chosen);
        } catch (IllegalArgumentException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        CommandChecks.threads(spec, "--threads", threads, true);
        CommandChecks.outFolder(spec, out);
        CommandChecks.positive(spec, "--seconds", seconds, "s");
        if (dt < 0 || dt > period) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--dt must be > 0 s (or 0 for the"
                    + " recommended step) and at most one breathing period (--period " + period + " s), got " + dt
                    + " s");
        }
        if (dt != 0) {
            CommandChecks.stepFits(spec, "--dt", dt, "--seconds", seconds);
        }
        RealTimeSetting setting = null;
        if (realtime) {
            if (dt != 0 || cgTolerance != null || !integrator.equals("rk2")) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                        "--realtime chooses the integrator and the step itself: leave out --integrator, --dt and"
                                + " --cg-tolerance");
            }
            if (thorax != null) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--realtime was measured on the"
                        + " double dome held by its band; its step drifts in a thorax (docs/thorax.md): use"
                        + " --integrator bdf2 --dt 0.0025 --newton 3 --cg-iterations 20 with --thorax");
            }
            setting = RealTimeSetting.forMuscleLoad(muscleLoad);
            chosen = setting.newIntegrator();
            dt = setting.dtS();
        }
        if (studyRings != null) {
            for (int i = 0; i < studyRings.length; i++) {
                if (studyRings[i] < 4 || (i > 0 && studyRings[i] <= studyRings[i - 1])) {
                    throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--study-rings must be"
                            + " ascending ring counts of 4 or more, got " + java.util.Arrays.toString(studyRings));
                }
            }
        }
        java.util.regex.Pattern only;
        try {
            only = studyConfigs == null ? null : java.util.regex.Pattern.compile(studyConfigs);
        } catch (java.util.regex.PatternSyntaxException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--study-configs is not a regular expression: " + e.getDescription() + " in '" + studyConfigs
                            + "'");
        }
        MeshUnits u = MeshUnits.parse(units);
        DiaphragmParameters p = DiaphragmParameters.defaults().withAttachThreshold(attachMm * 1e-3)
                .withTendonAreaFraction(tendonFraction).withTissueModel(TissueModel.parse(tissueModel));
        if (tendonNormal != null || tendonPointMm != null) {
            Vec3 normal = tendonNormal == null ? p.tendonNormal() : vector("--tendon-normal", tendonNormal, 1);
            Vec3 point = tendonPointMm == null ? null : vector("--tendon-point", tendonPointMm, 1e-3);
            p = p.withTendonPlane(normal, point);
        }
        BoundaryConditions bc;
        try {
            bc = new BoundaryConditions(BoundaryConditions.parse(BoundaryConditions.Attachment.class, attachment),
                    bandPaPerM, BoundaryConditions.DEFAULT_TAPER_M,
                    BoundaryConditions.parse(BoundaryConditions.MuscleLoad.class, muscleLoad), !allSegments);
        } catch (IllegalArgumentException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--attachment, --band-stiffness,"
                    + " --muscle-load: " + e.getMessage());
        }
        if (actionLines != null && !actionLines.isEmpty() && bc.muscleLoad() == BoundaryConditions.MuscleLoad.FIBRES) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--action-line: the muscle load '"
                    + muscleLoad + "' (the active fibre tension) has no action lines; they place the traction of"
                    + " --muscle-load pressure or paper-nodes");
        }
        if (model.equals("paper")) {
            var pr = spec.commandLine().getParseResult();
            for (String o : new String[] {"--tissue-model", "--attachment", "--muscle-load"}) {
                if (pr.hasMatchedOption(o)) {
                    throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--model paper sets " + o
                            + " itself (the paper's); leave it out or use --model default");
                }
            }
            org.tensim.scene.diaphragm.DiaphragmSpec paper = org.tensim.scene.diaphragm.DiaphragmSpec.paper();
            p = p.withTissueModel(paper.tissue().tissueModel());
            bc = paper.boundary().withBandStiffness(bandPaPerM);
            if (musclePa == null) {
                musclePa = DiaphragmSetup.defaultMusclePa(bc.muscleLoad());
            }
        } else if (!model.equals("default")) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--model must be default or paper,"
                    + " got '" + model + "'");
        }
        MeshCleaner.Options cleaning = new MeshCleaner.Options(weldMm * 1e-3, minPieceFraction);
        List<ActionLines.Line> lines = actionLines == null || actionLines.isEmpty() ? null : actionLines;
        BreathingCycle cycle = new BreathingCycle(period, ieRatio);
        DiaphragmControls controls = new DiaphragmControls(ribAmplitude, musclePa != null ? musclePa
                : DiaphragmSetup.defaultMusclePa(bc.muscleLoad()));
        DiaphragmReport.Options o = new DiaphragmReport.Options(seconds, dt, vtkPerCycle, vectorScale, 0.01, csvTimes);
        final DiaphragmParameters params = p;
        final BoundaryConditions bcFinal = bc;
        org.tensim.scene.diaphragm.DiaphragmSpec.Mesh meshSpec = org.tensim.scene.diaphragm.DiaphragmSpec.Mesh.defaults()
                .withCleaning(cleaning).withOffsetThickness(thicknessMm * 1e-3).withLabels(labels);
        if (!(mesh.equals(DiaphragmSetup.DEFAULT_MESH) && !Files.isRegularFile(mesh))) {
            meshSpec = meshSpec.withFile(mesh, u);
        }
        final org.tensim.scene.diaphragm.DiaphragmSpec sceneSpec;
        try {
            sceneSpec = new org.tensim.scene.diaphragm.DiaphragmSpec(meshSpec, p, bc,
                    new org.tensim.scene.diaphragm.DiaphragmSpec.Breathing(period, ieRatio, ribAmplitude, musclePa),
                    new org.tensim.scene.diaphragm.DiaphragmSpec.Cage(boxes, thorax, contact, contactPaPerM), lines,
                    BoundaryConditions.parse(org.tensim.scene.diaphragm.TendonRule.class, tendonRule));
        } catch (IllegalArgumentException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        if (realtimeStudy && (thorax != null || labels != null)) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--thorax and --labels are not yet"
                    + " taken by --realtime-study");
        }
        if (resolutionStudy && labels != null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--labels cannot go with"
                    + " --resolution-study: a label file names the vertices of one mesh, and the study decimates it");
        }
        if (resolutionStudy && thorax != null && mesh.equals(DiaphragmSetup.DEFAULT_MESH)) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--resolution-study with --thorax"
                    + " needs --mesh: the diaphragm registered to that thorax");
        }
        if (realtimeStudy) {
            return RunFolder.run(out, "diaphragm --realtime-study", REALTIME_OUTPUTS, run -> {
                registerAll(run, REALTIME_OUTPUTS);
                Map<String, Object> s = RealTimeStudy.run(studyRings != null ? studyRings : RealTimeStudy.RINGS, only,
                        boxes, params, bcFinal, cycle, controls, seconds, out, System.out);
                System.out.println(Json.line(run.finish(RunStatus.OK, s)));
            });
        }
        if (resolutionStudy) {
            if (refine < 0 || cellsMm != null && java.util.Arrays.stream(cellsMm).anyMatch(c -> !(c > 0))) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                        "--refine must be 0 or more and --cells positive sizes in mm, got " + refine + " and "
                                + java.util.Arrays.toString(cellsMm));
            }
            ResolutionStudy.Thorax inThorax = thorax == null ? null : new ResolutionStudy.Thorax(sceneSpec,
                    DiaphragmSetup.read(sceneSpec),
                    () -> configured(org.tensim.solver.integrators.Integrators.create(integrator)), dt);
            ResolutionStudy.Setup rs;
            try {
                rs = new ResolutionStudy.Setup(DiaphragmSetup.boxes(boxes), p, bc, cycle, controls,
                        Math.min(seconds, cycle.inspirationS()), tolerance, System.out, inThorax);
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--tolerance: " + e.getMessage());
            }
            boolean ownMesh = !mesh.equals(DiaphragmSetup.DEFAULT_MESH);
            return RunFolder.run(out, "diaphragm --resolution-study", RESOLUTION_OUTPUTS, run -> {
                registerAll(run, RESOLUTION_OUTPUTS);
                Map<String, Object> s = ownMesh
                        ? ResolutionStudy.runMesh(mesh, u, cleaning, thicknessMm * 1e-3, cellsMm, refine, rs, out)
                        : studyRings != null ? ResolutionStudy.runRings(rs, studyRings, out)
                        : ResolutionStudy.run(rs, out, noPick ? null : ResolutionPick.FILE);
                System.out.println(Json.line(run.finish(RunStatus.OK, s)));
            });
        }
        final org.tensim.solver.Integrator integratorUsed = chosen;
        final RealTimeSetting named = setting;
        return RunFolder.run(out, "diaphragm", DiaphragmReport.OUTPUTS, run -> simulate(run, sceneSpec, o,
                integratorUsed, named));
    }

    /** Outputs of the studies, written by the study classes themselves into --out. */
    static final List<String> REALTIME_OUTPUTS = List.of("realtime.csv", "realtime.png", "realtime.json");
    static final List<String> RESOLUTION_OUTPUTS = List.of("resolution.csv", "resolution.png", "resolution.json",
            "resolution-pick.json");

    private static void registerAll(RunFolder run, List<String> names) throws java.io.IOException {
        for (String n : names) {
            run.file(n);
        }
    }

    /**
     * The integrator as the options configure it (the run's, and every model's of a study): a thorax's converged
     * {@code bdf2} step for plain {@code bdf2} (a named setup keeps its own iterations; docs/thorax.md), then
     * {@code --newton}, {@code --cg-iterations} and {@code --cg-tolerance}.
     */
    private org.tensim.solver.Integrator configured(org.tensim.solver.Integrator i) {
        if (i instanceof org.tensim.solver.prefactored.PrefactoredBdf2 b) {
            if (thorax != null && contact && integrator.equals(org.tensim.solver.prefactored.PrefactoredBdf2.NAME)) {
                b.setNewtonIterations(org.tensim.solver.prefactored.PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS);
                b.setKrylovIterations(org.tensim.solver.prefactored.PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS);
            }
            if (newton != null) {
                b.setNewtonIterations(newton);
            }
            if (cgIterations != null) {
                b.setKrylovIterations(cgIterations);
            }
        }
        if (cgTolerance != null && i instanceof org.tensim.solver.integrators.ImplicitEuler ie) {
            ie.setTolerance(cgTolerance);
        }
        return i;
    }

    private void simulate(RunFolder run, org.tensim.scene.diaphragm.DiaphragmSpec sceneSpec, DiaphragmReport.Options o,
            org.tensim.solver.Integrator chosen, RealTimeSetting setting) throws Exception {
        BoundaryConditions bc = sceneSpec.boundary();
        DiaphragmSetup.Built built = DiaphragmSetup.build(sceneSpec);
        if (built.meshReport() != null) {
            System.out.println(built.meshReport().describe());
        }
        int n = threads > 0 ? threads
                : setting != null ? org.tensim.solver.parallel.Parallelism.availableCores()
                        : org.tensim.solver.parallel.Parallelism.automaticThreads(
                                built.scene().topology().springs().size());
        if (setting != null) {
            System.out.println("realtime: " + setting.describe()
                    + (mesh.equals(DiaphragmSetup.DEFAULT_MESH) ? "" : "; this mesh (" + mesh + ") was not measured"));
        }
        Map<String, Object> fields = DiaphragmReport.run(built, o, chosen, n, run, System.out);
        // muscle_force_pa is an active fibre stress or a pressure: the load says which.
        fields.put("muscle_load", BoundaryConditions.name(bc.muscleLoad()));
        if (setting != null) {
            fields.put("realtime_setting", setting.toMap());
        }
        Map<String, Object> summary = run.finish(fields.containsKey("diverged") ? RunStatus.DIVERGED : RunStatus.OK,
                fields);
        if (fields.containsKey("diverged")) {
            spec.commandLine().getErr().println("tensim diaphragm: " + fields.get("diverged")
                    + " (outputs up to that step are in " + out + ", figures marked DIVERGED)");
        }
        System.out.println(Json.line(summary));
    }

    private Vec3 vector(String option, double[] v, double scale) {
        if (v.length != 3) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    option + " needs three numbers X,Y,Z, got " + v.length);
        }
        if (v[0] == 0 && v[1] == 0 && v[2] == 0 && option.equals("--tendon-normal")) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    option + " must not be the zero vector");
        }
        return new Vec3(scale * v[0], scale * v[1], scale * v[2]);
    }
}
