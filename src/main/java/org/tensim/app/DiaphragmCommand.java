package org.tensim.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.cli.OutFolderOption;
import org.tensim.cli.ThreadsOption;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.experiment.diaphragm.RealTimeSetting;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.tuning.DiaphragmOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim diaphragm}: the paper's second experiment, headless. */
@Command(name = "diaphragm", mixinStandardHelpOptions = true,
        subcommands = {DiaphragmResolutionCommand.class, DiaphragmRealtimeStudyCommand.class},
        description = {"Runs the paper's diaphragm (section 3.2) headless for some breathing cycles.",
            "The muscle is a mass-spring, the central tendon a tensegrity, driven by the ribs (finite helical axes)"
                + " and the muscle's action. Writes PNG displacement slices, displacements.csv, probe.csv, a VTK"
                + " series and summary.json to --out and prints the summary as the last line (JSON). Model:"
                + " docs/diaphragm.md.",
            "Its studies are subcommands: resolution-study and realtime-study."})
public final class DiaphragmCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @picocli.CommandLine.Mixin
    DiaphragmOptions scene = new DiaphragmOptions();

    @picocli.CommandLine.Mixin
    org.tensim.tuning.PickOption pick = new org.tensim.tuning.PickOption();

    @picocli.CommandLine.Mixin
    DiaphragmSolverOptions solver = new DiaphragmSolverOptions();

    @Option(names = "--seconds", paramLabel = "S", description = "Simulated time, s; the breathing figures need one"
            + " inspiration (1.33 s at the default cycle) (default: ${DEFAULT-VALUE}).")
    double seconds = 4;

    @picocli.CommandLine.Mixin
    ThreadsOption threads = new ThreadsOption();

    @Option(names = "--realtime",
            description = "Run the real-time setting (bdf2 at 25 ms with the fibres' load: the real-time study's"
                    + " choice on the default mesh, its error against RK2 in docs/performance.md; in a thorax "
                    + "bdf2-contact-realtime, docs/thorax.md), on all cores; on the default scene the mechanics run at"
                    + " the rings of the shipped resolution pick (or --pick's), the 43-ring mesh carried by them and"
                    + " measured; the summary names both (realtime_setting, resolution_pick).")
    boolean realtime;

    @Option(names = "--coarse-edge", paramLabel = "MM",
            description = "Run the mechanics on the mesh decimated by quadric edge collapse to about this edge length,"
                    + " mm, carrying the mesh given (drawn, measured, exported; with a thorax, the contact is on it"
                    + " and passes to the coarse nodes through the mapping's transpose); needs --mesh, not with"
                    + " --pick or --labels. The error of a coarse edge against the full mesh is measured, not"
                    + " assumed: docs/thorax.md, \"Mapped mechanics\".")
    Double coarseEdgeMm;

    @Option(names = "--cluster-cell", paramLabel = "MM",
            description = "Run the mesh simplified by vertex clustering in cubes of this size, mm, as the scene itself"
                    + " (drawn, measured and exported as it is: no mapping back to the mesh given); needs --mesh, not"
                    + " with --coarse-edge, --pick, --realtime or --labels. A cheaper stand-in for a long run, such"
                    + " as the thorax with the lungs (docs/lungs.md); its error against the full mesh is the user's"
                    + " to measure.")
    Double clusterCellMm;

    @Option(names = "--vtk-per-cycle", paramLabel = "N",
            description = "VTK frames per breathing cycle, 0 for none (default: ${DEFAULT-VALUE}).")
    int vtkPerCycle = 8;

    @Option(names = "--vector-scale", paramLabel = "X",
            description = "Scale of the mid-inspiration displacement vectors (default: ${DEFAULT-VALUE}, as Fig. 5).")
    double vectorScale = 100;

    @Option(names = "--csv-times", paramLabel = "S[,S...]", split = ",", hideParamSyntax = true,
            description = "Times of displacements.csv, s (default: end-inspiration and end of the last cycle).")
    double[] csvTimes;

    @Option(names = "--lungs", description = "With --thorax: build the thorax's lungs into the run, sliding on the"
            + " pleura carried by the diaphragm and the ribs (docs/lungs.md); writes lung-points.csv. The muscle's"
            + " default fibre stress is then 36000 Pa (it carries the lungs' recoil); --muscle-action overrides it."
            + " Runs bdf2 at " + DiaphragmSolverOptions.ORGANS_DT_S + " s unless --integrator or --dt is given.")
    boolean lungs;

    @Option(names = "--liver", negatable = true, description = "With --lungs: also the liver as a volume pushed by"
            + " the diaphragm, held at its bare area and on the abdomen below, the rigid support kept (default: on"
            + " with --lungs; --no-liver leaves it out; docs/lungs.md).")
    Boolean liver;

    @Option(names = "--liver-abdomen", paramLabel = "PA_PER_M", description = "With --liver: stiffness per unit area"
            + " of the abdomen's elastic support under the liver's lower half, Pa/m; 0 turns it off (default: "
            + org.tensim.scene.lungs.ThoraxOrgans.Options.ABDOMEN_PA_PER_M + ").")
    Double liverAbdomenPaPerM;

    @Option(names = "--lung-probe", paramLabel = "X,Y,Z", split = ";", hideParamSyntax = true,
            description = "With --lungs: a point to follow in a lung, mm in the thorax's frame (repeatable).")
    String[] lungProbes;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "diaphragm"));

    /** What --lungs chose for the integrator and step when none was given (null: the user's), for the summary. */
    private String organsSolver;

    /** The studies' former mode flags, kept to say where the studies went. */
    @Option(names = "--resolution-study", hidden = true)
    boolean formerResolutionFlag;

    @Option(names = "--realtime-study", hidden = true)
    boolean formerRealtimeFlag;

    @Override
    public Integer call() throws Exception {
        var pr = spec.commandLine().getParseResult();
        for (String flag : new String[] {"--resolution-study", "--realtime-study"}) {
            if (pr.hasMatchedOption(flag)) {
                throw usage(flag + " is now a subcommand: tensim diaphragm " + flag.substring(2) + " [options]"
                        + " (tensim diaphragm " + flag.substring(2) + " --help)");
            }
        }
        // Options are checked before the mesh is read, which takes seconds.
        final DiaphragmSpec given = CommandChecks.scene(spec, scene,
                // --rings (or the pick's) asks for the generated dome at those rings, not the committed 43-ring mesh.
                !scene.ringsGiven() && Files.isRegularFile(DiaphragmSetup.DEFAULT_MESH) ? DiaphragmSetup.DEFAULT_MESH
                        : null,
                DiaphragmSpec.PAPER_RINGS);
        // With the lungs the muscle also carries their recoil: its default stress is the one measured with them.
        final DiaphragmSpec sceneSpec = lungs ? org.tensim.scene.lungs.LungsMuscle.applyTo(given) : given;
        organsSolver = lungs && !realtime ? solver.defaultForOrgans(spec) : null;
        if (organsSolver != null) {
            System.out.println(organsSolver);
        }
        solver.check(spec, sceneSpec, seconds);
        // --pick, or --realtime on the default scene: the mechanics at the pick's rings, the 43-ring mesh carried
        org.tensim.experiment.diaphragm.ResolutionPick picked = null;
        if (pick.file() != null || realtime) {
            try {
                picked = pick.choose(scene, sceneSpec, note -> System.out.println("realtime: " + note));
            } catch (IllegalArgumentException e) {
                throw usage(e.getMessage());
            }
        }
        final org.tensim.experiment.diaphragm.ResolutionPick mappedAt = picked;
        if (coarseEdgeMm != null && (scene.mesh == null || pick.file() != null || !(coarseEdgeMm > 0))) {
            throw usage("--coarse-edge " + coarseEdgeMm + ": expected a positive edge length in mm with --mesh, and"
                    + " without --pick (a pick is a resolution of the generated double dome)");
        }
        if (clusterCellMm != null && (scene.mesh == null || coarseEdgeMm != null || picked != null || realtime
                || sceneSpec.mesh().labels() != null || !(clusterCellMm > 0 && Double.isFinite(clusterCellMm)))) {
            throw usage("--cluster-cell " + clusterCellMm + ": expected a positive cube size in mm with --mesh, and"
                    + " without --coarse-edge, --pick, --realtime or --labels");
        }
        if (lungs && (sceneSpec.cage().thorax() == null || picked != null || coarseEdgeMm != null)) {
            throw usage("--lungs needs --thorax DIR (the organs' meshes) and runs the built mesh itself: leave out"
                    + " --pick, --realtime and --coarse-edge");
        }
        if ((liver != null || lungProbes != null) && !lungs) {
            throw usage("--liver, --no-liver and --lung-probe go with --lungs");
        }
        if (liverAbdomenPaPerM != null && (!withLiver() || !(liverAbdomenPaPerM >= 0 && liverAbdomenPaPerM < 1e12))) {
            throw usage("--liver-abdomen " + liverAbdomenPaPerM + ": expected a stiffness of 0 or more in Pa/m,"
                    + " with the liver (leave out --no-liver)");
        }
        org.tensim.solver.Integrator chosen = solver.create(sceneSpec);
        double dt = solver.dt();
        int threadCount = threads.threads(spec);
        Path folder = out.folder(spec);
        CommandChecks.positive(spec, "--seconds", seconds, "s");
        RealTimeSetting setting = null;
        if (realtime) {
            if (dt != 0 || solver.cgTolerance != null || !solver.integratorName().equals("rk2")) {
                throw usage("--realtime chooses the integrator and the step itself: leave out --integrator, --dt and"
                        + " --cg-tolerance");
            }
            try {
                setting = RealTimeSetting.forScene(sceneSpec.boundary().muscleLoad(),
                        sceneSpec.cage().thorax() != null);
            } catch (IllegalArgumentException e) {
                throw usage("--realtime: " + e.getMessage());
            }
            chosen = setting.newIntegrator();
            dt = setting.dtS();
        }
        DiaphragmReport.Options o = new DiaphragmReport.Options(seconds, dt, vtkPerCycle, vectorScale, 0.01, csvTimes);
        final org.tensim.solver.Integrator integratorUsed = chosen;
        final RealTimeSetting named = setting;
        return RunFolder.run(folder, "diaphragm", DiaphragmReport.OUTPUTS, out.overwrite(),
                run -> simulate(run, sceneSpec, o, integratorUsed, named, threadCount, mappedAt));
    }

    /** The organs' options from --liver and --lung-probe (mm, checked as numbers). */
    private org.tensim.scene.lungs.ThoraxOrgans.Options organOptions() {
        var o = org.tensim.scene.lungs.ThoraxOrgans.Options.defaults();
        if (withLiver()) {
            o = o.withLiver();
        }
        if (liverAbdomenPaPerM != null) {
            o = o.withAbdomen(liverAbdomenPaPerM);
        }
        String[] probes = lungProbes == null ? new String[0] : lungProbes;
        double[] m = new double[3 * probes.length];
        for (int i = 0; i < probes.length; i++) {
            String[] c = probes[i].split(",");
            if (c.length != 3) {
                throw usage("--lung-probe " + probes[i] + ": expected X,Y,Z in mm");
            }
            for (int a = 0; a < 3; a++) {
                try {
                    m[3 * i + a] = 1e-3 * Double.parseDouble(c[a].trim());
                } catch (NumberFormatException e) {
                    throw usage("--lung-probe " + probes[i] + ": '" + c[a] + "' is not a number; expected X,Y,Z in mm");
                }
            }
        }
        return o.withProbes(m);
    }

    /** The liver with the lungs: on unless --no-liver. */
    private boolean withLiver() {
        return lungs && (liver == null || liver);
    }

    private picocli.CommandLine.ParameterException usage(String message) {
        return new picocli.CommandLine.ParameterException(spec.commandLine(), message);
    }

    /** Refuses study ring counts that are not ascending or below 4. */
    static void checkRings(picocli.CommandLine.Model.CommandSpec spec, int[] rings) {
        if (rings == null) {
            return;
        }
        for (int i = 0; i < rings.length; i++) {
            if (rings[i] < 4 || (i > 0 && rings[i] <= rings[i - 1])) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--study-rings must be"
                        + " ascending ring counts of 4 or more, got " + java.util.Arrays.toString(rings));
            }
        }
    }

    private void simulate(RunFolder run, DiaphragmSpec sceneSpec, DiaphragmReport.Options o,
            org.tensim.solver.Integrator chosen, RealTimeSetting setting, int threads,
            org.tensim.experiment.diaphragm.ResolutionPick picked) throws Exception {
        DiaphragmSetup.Built built;
        org.tensim.scene.diaphragm.MappedDiaphragm decimated = null;
        if (coarseEdgeMm != null) {
            DiaphragmSetup.Inputs in = DiaphragmSetup.read(sceneSpec);
            built = DiaphragmSetup.build(in, sceneSpec, sceneSpec.newControls());
            decimated = org.tensim.scene.diaphragm.MappedDiaphragm.decimated(in, built.scene(), 1e-3 * coarseEdgeMm);
            System.out.println("mechanics on " + decimated.coarse().spec().mesh().describe() + " decimated to "
                    + coarseEdgeMm + " mm edges (" + decimated.mechanicalNodes() + " nodes), carrying the "
                    + decimated.drawnNodes() + " nodes of " + built.source());
        } else if (clusterCellMm != null) {
            DiaphragmSetup.Inputs in = DiaphragmSetup.read(sceneSpec);
            org.tensim.scene.shell.TwoSurfaces s = in.surfaces().surfaces().decimated(1e-3 * clusterCellMm);
            built = new DiaphragmSetup.Built(org.tensim.scene.diaphragm.DiaphragmScene.build(s, sceneSpec, in.boxes(),
                    in.bones(), null, sceneSpec.newControls()), in.report(), in.surfaces().mode(), in.source()
                    + ", clustered in " + clusterCellMm + " mm cubes");
            System.out.println("mechanics on " + built.source() + ": " + s.mesh().vertexCount() + " vertices of "
                    + in.surfaces().surfaces().mesh().vertexCount());
        } else {
            built = DiaphragmSetup.build(sceneSpec);
        }
        if (lungs) {
            org.tensim.experiment.lungs.ThoraxOrganRun.attach(built.scene(), sceneSpec.cage().thorax(), organOptions(),
                    System.out);
        }
        Map<String, Object> fields = report(run, built, o, chosen, setting, threads, scene.mesh, picked, decimated);
        if (organsSolver != null) {
            fields.put("dt_rule", organsSolver); // the report's rule would say "given (--dt)"
        }
        if (decimated != null) {
            fields.put("coarse_edge_mm", coarseEdgeMm);
        }
        if (clusterCellMm != null) {
            fields.put("cluster_cell_mm", clusterCellMm);
        }
        if (pick.file() != null) {
            fields.put("resolution_pick_file", pick.file().toString());
        }
        finish(spec, run, fields);
    }

    /**
     * Runs a built diaphragm into {@code run} as the command does (the mesh report and the real-time setting
     * printed, {@link DiaphragmReport#run} on {@code threads} threads, 0 for the automatic count) and returns the
     * summary's fields, not yet written.
     *
     * @param meshGiven the mesh file the user gave, null for the default (for the real-time setting's line)
     * @param picked    the resolution the mechanics run at, carrying the built mesh ({@link
     *                  org.tensim.scene.diaphragm.MappedDiaphragm}); null to run the built mesh itself
     */
    static Map<String, Object> report(RunFolder run, DiaphragmSetup.Built built, DiaphragmReport.Options o,
            org.tensim.solver.Integrator chosen, RealTimeSetting setting, int threads, Path meshGiven,
            org.tensim.experiment.diaphragm.ResolutionPick picked) throws Exception {
        return report(run, built, o, chosen, setting, threads, meshGiven, picked, null);
    }

    /** As above, the mechanics run by {@code premapped} when not null (a decimation carrying the built mesh). */
    static Map<String, Object> report(RunFolder run, DiaphragmSetup.Built built, DiaphragmReport.Options o,
            org.tensim.solver.Integrator chosen, RealTimeSetting setting, int threads, Path meshGiven,
            org.tensim.experiment.diaphragm.ResolutionPick picked,
            org.tensim.scene.diaphragm.MappedDiaphragm premapped) throws Exception {
        DiaphragmSpec sceneSpec = built.scene().spec();
        if (built.meshReport() != null) {
            System.out.println(built.meshReport().describe());
        }
        org.tensim.scene.diaphragm.MappedDiaphragm mapped = premapped;
        if (picked != null) {
            DiaphragmSpec coarse = sceneSpec.withMesh(sceneSpec.mesh().withFile(null, sceneSpec.mesh().units())
                    .withRings(picked.rings()));
            mapped = org.tensim.scene.diaphragm.MappedDiaphragm.of(DiaphragmSetup.build(coarse).scene(),
                    built.scene());
            System.out.println("mechanics at " + picked.describe() + ", carrying the " + mapped.drawnNodes()
                    + " nodes of " + built.source());
        }
        int n = threads > 0 ? threads
                : setting != null ? org.tensim.solver.parallel.Parallelism.availableCores()
                        : org.tensim.solver.parallel.Parallelism.automaticThreads((mapped != null ? mapped.coarse()
                                : built.scene()).topology().springs().size());
        if (setting != null) {
            System.out.println("realtime: " + setting.describe()
                    + (meshGiven == null ? ""
                            : setting.equals(RealTimeSetting.THORAX)
                                    ? "; measured on the shared BodyParts3D diaphragm (diaphragm realtime-study"
                                            + " --thorax measures this mesh)"
                                    : "; this mesh (" + meshGiven + ") was not measured"));
        }
        Map<String, Object> fields = mapped != null
                ? org.tensim.experiment.diaphragm.MappedRun.run(built, mapped, o, chosen, n, run, System.out)
                : DiaphragmReport.run(built, o, chosen, n, run, System.out);
        // muscle_force_pa is an active fibre stress or a pressure: the load says which.
        fields.put("muscle_load", BoundaryConditions.name(built.scene().spec().boundary().muscleLoad()));
        if (setting != null) {
            fields.put("realtime_setting", setting.toMap());
        }
        if (picked != null) {
            fields.put("resolution_pick", picked.toMap());
        }
        return fields;
    }

    /** Writes the summary (status diverged when the run diverged, said on standard error) and prints it. */
    static void finish(picocli.CommandLine.Model.CommandSpec spec, RunFolder run, Map<String, Object> fields)
            throws java.io.IOException {
        Map<String, Object> summary = run.finish(fields.containsKey("diverged") ? RunStatus.DIVERGED : RunStatus.OK,
                fields);
        if (fields.containsKey("diverged")) {
            spec.commandLine().getErr().println("tensim " + spec.name() + ": " + fields.get("diverged")
                    + " (outputs up to that step are in " + run.dir() + ", figures marked DIVERGED)");
        }
        System.out.println(Json.line(summary));
    }
}
