package org.tensim.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.experiment.diaphragm.RealTimeSetting;
import org.tensim.experiment.diaphragm.RealTimeStudy;
import org.tensim.experiment.diaphragm.ResolutionPick;
import org.tensim.experiment.diaphragm.ResolutionStudy;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;
import org.tensim.tuning.DiaphragmOptions;
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

    @picocli.CommandLine.Mixin
    DiaphragmOptions scene = new DiaphragmOptions();

    @Option(names = "--seconds", paramLabel = "S", description = "simulated time, s; the breathing figures need one"
            + " inspiration (1.33 s at the default cycle) (default: ${DEFAULT-VALUE})")
    double seconds = 4;

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
                    + PrefactoredBdf2.DEFAULT_NEWTON_ITERATIONS + "; with --thorax: "
                    + PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS + ", docs/thorax.md)")
    Integer newton;

    @Option(names = "--cg-iterations", paramLabel = "N",
            description = "bdf2 only: cap on CG iterations per Newton iteration (default: "
                    + PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS + "; with --thorax: "
                    + PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS + ")")
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
        final DiaphragmSpec sceneSpec;
        try {
            sceneSpec = scene.spec(Files.isRegularFile(DiaphragmSetup.DEFAULT_MESH) ? DiaphragmSetup.DEFAULT_MESH
                    : null, DiaphragmSpec.PAPER_RINGS);
        } catch (IllegalArgumentException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        boolean inThorax = sceneSpec.cage().thorax() != null;
        org.tensim.solver.Integrator chosen = Integrators.create(integrator);
        if (cgTolerance != null && !(chosen instanceof ImplicitEuler)) {
            throw usage("--cg-tolerance applies to --integrator implicit-euler only, not " + integrator);
        }
        if ((newton != null || cgIterations != null) && !(chosen instanceof PrefactoredBdf2)) {
            throw usage("--newton and --cg-iterations apply to --integrator bdf2 only, not " + integrator);
        }
        try {
            configured(chosen, sceneSpec);
        } catch (IllegalArgumentException e) {
            throw usage(e.getMessage());
        }
        CommandChecks.threads(spec, "--threads", threads, true);
        CommandChecks.outFolder(spec, out);
        CommandChecks.positive(spec, "--seconds", seconds, "s");
        double period = sceneSpec.breathing().periodS();
        if (dt < 0 || dt > period) {
            throw usage("--dt must be > 0 s (or 0 for the recommended step) and at most one breathing period"
                    + " (--period " + period + " s), got " + dt + " s");
        }
        if (dt != 0) {
            CommandChecks.stepFits(spec, "--dt", dt, "--seconds", seconds);
        }
        RealTimeSetting setting = null;
        if (realtime) {
            if (dt != 0 || cgTolerance != null || !integrator.equals("rk2")) {
                throw usage("--realtime chooses the integrator and the step itself: leave out --integrator, --dt and"
                        + " --cg-tolerance");
            }
            if (inThorax) {
                throw usage("--realtime was measured on the double dome held by its band; its step drifts in a"
                        + " thorax (docs/thorax.md): use --integrator bdf2 --dt 0.0025 --newton 3 --cg-iterations 20"
                        + " with --thorax");
            }
            setting = RealTimeSetting.forMuscleLoad(sceneSpec.boundary().muscleLoad());
            chosen = setting.newIntegrator();
            dt = setting.dtS();
        }
        if (studyRings != null) {
            for (int i = 0; i < studyRings.length; i++) {
                if (studyRings[i] < 4 || (i > 0 && studyRings[i] <= studyRings[i - 1])) {
                    throw usage("--study-rings must be ascending ring counts of 4 or more, got "
                            + java.util.Arrays.toString(studyRings));
                }
            }
        }
        if (realtimeStudy) {
            return realtimeStudy(sceneSpec);
        }
        if (resolutionStudy) {
            return resolutionStudy(sceneSpec);
        }
        DiaphragmReport.Options o = new DiaphragmReport.Options(seconds, dt, vtkPerCycle, vectorScale, 0.01, csvTimes);
        final org.tensim.solver.Integrator integratorUsed = chosen;
        final RealTimeSetting named = setting;
        return RunFolder.run(out, "diaphragm", DiaphragmReport.OUTPUTS, run -> simulate(run, sceneSpec, o,
                integratorUsed, named));
    }

    private int realtimeStudy(DiaphragmSpec s) throws Exception {
        if (s.cage().thorax() != null || s.mesh().labels() != null) {
            throw usage("--thorax and --labels are not yet taken by --realtime-study");
        }
        java.util.regex.Pattern only;
        try {
            only = studyConfigs == null ? null : java.util.regex.Pattern.compile(studyConfigs);
        } catch (java.util.regex.PatternSyntaxException e) {
            throw usage("--study-configs is not a regular expression: " + e.getDescription() + " in '" + studyConfigs
                    + "'");
        }
        return RunFolder.run(out, "diaphragm --realtime-study", REALTIME_OUTPUTS, run -> {
            registerAll(run, REALTIME_OUTPUTS);
            Map<String, Object> r = RealTimeStudy.run(studyRings != null ? studyRings : RealTimeStudy.RINGS, only,
                    s.cage().boxes(), s.tissue(), s.boundary(), s.breathing().cycle(), s.newControls(), seconds, out,
                    System.out);
            System.out.println(Json.line(run.finish(RunStatus.OK, r)));
        });
    }

    private int resolutionStudy(DiaphragmSpec s) throws Exception {
        if (s.mesh().labels() != null) {
            throw usage("--labels cannot go with --resolution-study: a label file names the vertices of one mesh,"
                    + " and the study decimates it");
        }
        boolean ownMesh = scene.mesh != null;
        if (s.cage().thorax() != null && !ownMesh) {
            throw usage("--resolution-study with --thorax needs --mesh: the diaphragm registered to that thorax");
        }
        if (refine < 0 || cellsMm != null && java.util.Arrays.stream(cellsMm).anyMatch(c -> !(c > 0))) {
            throw usage("--refine must be 0 or more and --cells positive sizes in mm, got " + refine + " and "
                    + java.util.Arrays.toString(cellsMm));
        }
        ResolutionStudy.Thorax inThorax = s.cage().thorax() == null ? null : new ResolutionStudy.Thorax(s,
                DiaphragmSetup.read(s), () -> configured(Integrators.create(integrator), s), dt);
        ResolutionStudy.Setup rs;
        try {
            rs = new ResolutionStudy.Setup(DiaphragmSetup.boxes(s.cage().boxes()), s.tissue(), s.boundary(),
                    s.breathing().cycle(), s.newControls(), Math.min(seconds, s.breathing().cycle().inspirationS()),
                    tolerance, System.out, inThorax);
        } catch (IllegalArgumentException e) {
            throw usage("--tolerance: " + e.getMessage());
        }
        DiaphragmSpec.Mesh m = s.mesh();
        return RunFolder.run(out, "diaphragm --resolution-study", RESOLUTION_OUTPUTS, run -> {
            registerAll(run, RESOLUTION_OUTPUTS);
            Map<String, Object> r = ownMesh
                    ? ResolutionStudy.runMesh(m.file(), m.units(), m.cleaning(), m.offsetThicknessM(), cellsMm, refine,
                            rs, out)
                    : studyRings != null ? ResolutionStudy.runRings(rs, studyRings, out)
                    : ResolutionStudy.run(rs, out, noPick ? null : ResolutionPick.FILE);
            System.out.println(Json.line(run.finish(RunStatus.OK, r)));
        });
    }

    private picocli.CommandLine.ParameterException usage(String message) {
        return new picocli.CommandLine.ParameterException(spec.commandLine(), message);
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
    private org.tensim.solver.Integrator configured(org.tensim.solver.Integrator i, DiaphragmSpec s) {
        if (i instanceof PrefactoredBdf2 b) {
            if (s.cage().thorax() != null && s.cage().contact() && integrator.equals(PrefactoredBdf2.NAME)) {
                b.setNewtonIterations(PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS);
                b.setKrylovIterations(PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS);
            }
            if (newton != null) {
                b.setNewtonIterations(newton);
            }
            if (cgIterations != null) {
                b.setKrylovIterations(cgIterations);
            }
        }
        if (cgTolerance != null && i instanceof ImplicitEuler ie) {
            ie.setTolerance(cgTolerance);
        }
        return i;
    }

    private void simulate(RunFolder run, DiaphragmSpec sceneSpec, DiaphragmReport.Options o,
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
                    + (scene.mesh == null ? "" : "; this mesh (" + scene.mesh + ") was not measured"));
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
}
