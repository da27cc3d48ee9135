package org.tensim.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.knowm.xchart.XYChart;
import org.tensim.analysis.AccuracyScenes;
import org.tensim.analysis.AccuracyStudy;
import org.tensim.analysis.ShellStudy;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.OutFolderOption;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.shell.TissueModel;
import org.tensim.solver.integrators.Integrators;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim accuracy}: work-precision of every integrator on named scenes. */
@Command(name = "accuracy", mixinStandardHelpOptions = true,
        description = {"Measures the error, wall time and force evaluations of every integrator over a ladder of time"
            + " steps.",
            "Each step of the ladder is half the previous. The error is the largest node position error at the end"
                + " time against a reference (exact; Hipparchus Dormand-Prince 8(5,3); or, with rigid links, RK4 at"
                + " the finest step). Writes per scene to --out: accuracy-SCENE.csv, SCENE-work-precision.png (error"
                + " against wall time), SCENE-evaluations.png (error against force evaluations) and"
                + " SCENE-convergence.png (error against dt), and prints the measured order of each method.",
            "Then the shell's statics against element size (--shell): the patch test and the clamped circular plate"
                + " against Kirchhoff, in shell-MODEL.csv and shell-MODEL-convergence.png, with the measured orders.",
            "The last line is one JSON object with, per integrator, `order` (first scene), `expected_order` and"
                + " `order_by_scene`, and `shell` (the static section)."})
public final class AccuracyCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--scene", split = ",", paramLabel = "NAME[,NAME...]", hideParamSyntax = true,
            description = "Scenes, comma-separated (default: all of ${COMPLETION-CANDIDATES}).",
            completionCandidates = SceneNames.class)
    List<String> scenes = AccuracyScenes.names();

    @Option(names = {"--integrator", "--integrators"}, split = ",", paramLabel = "NAME[,NAME...]",
            hideParamSyntax = true,
            description = "Integrators, comma-separated (default: all of ${COMPLETION-CANDIDATES}).",
            completionCandidates = Integrators.Names.class)
    List<String> integrators = Integrators.names();

    @Option(names = "--dt", paramLabel = "S",
            description = "Largest time step of the ladder, s (default: the scene's).")
    Double largestDt;

    @Option(names = "--rungs", paramLabel = "N",
            description = "Number of time steps in the ladder (default: the scene's).")
    Integer rungs;

    @Option(names = "--shell", paramLabel = "MODEL",
            description = "Tissue model of the shell statics section: material, springs, paper or none"
                    + " (default: ${DEFAULT-VALUE}).")
    String shell = "material";

    @Option(names = "--shell-rings", split = ",", paramLabel = "N[,N...]", hideParamSyntax = true,
            description = "Ring counts of the clamped plate, coarsest first (default: 6,10,14,20,28,43; 43 is the "
                    + "default diaphragm's element size).")
    int[] shellRings = ShellStudy.PLATE_RINGS;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "accuracy"));

    /** Scene names for the help text. */
    static final class SceneNames extends ArrayList<String> {
        SceneNames() {
            super(AccuracyScenes.names());
        }
    }

    @Override
    public Integer call() throws Exception {
        for (String s : scenes) {
            AccuracyScenes.get(s); // fail on a bad name before any work
        }
        for (String i : integrators) {
            Integrators.create(i);
        }
        if (largestDt != null && !(largestDt > 0)) {
            throw new IllegalArgumentException("--dt must be a number > 0 s, got " + largestDt);
        }
        TissueModel shellModel = "none".equalsIgnoreCase(shell) ? null : TissueModel.parse(shell);
        for (int n : shellRings) {
            if (n < 2) {
                throw new IllegalArgumentException("--shell-rings must be at least 2, got " + n);
            }
        }
        if (rungs != null && rungs < 2) {
            throw new IllegalArgumentException("--rungs must be at least 2, got " + rungs);
        }
        if (largestDt != null) {
            for (String name : scenes) {
                OptionChecks.stepFits(spec, "--dt", largestDt, "the end time of scene " + name,
                        AccuracyScenes.get(name).endTimeS());
            }
        }
        return RunFolder.run(out.folder(spec), "accuracy", List.of(), out.overwrite(), run -> study(run, shellModel));
    }

    private void study(RunFolder run, TissueModel shellModel) throws IOException {
        Map<String, Map<String, Double>> byScene = new LinkedHashMap<>();
        for (String name : scenes) {
            var scene = AccuracyScenes.get(name);
            if (largestDt != null || rungs != null) {
                scene = scene.withLadder(largestDt != null ? largestDt : scene.largestDtS(),
                        rungs != null ? rungs : scene.rungs());
            }
            AccuracyStudy.Result r = AccuracyStudy.run(scene, integrators, System.out::println);
            write(r, run);
            byScene.put(name, r.measuredOrder());
            System.out.println(name + ": measured order (slope of log error against log dt, asymptotic range "
                    + String.format("%.1e", r.floorM()) + " to " + String.format("%.1e", r.ceilingM()) + " m):");
            for (String i : integrators) {
                System.out.println(String.format("  %-16s %6.3f   (theory %d)", i, r.measuredOrder().get(i),
                        r.expectedOrder().get(i)));
            }
        }
        Map<String, Object> json = new LinkedHashMap<>();
        for (String i : integrators) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("order", round(byScene.get(scenes.get(0)).get(i)));
            e.put("expected_order", Integrators.create(i).order());
            Map<String, Object> per = new LinkedHashMap<>();
            byScene.forEach((s, m) -> per.put(s, round(m.get(i))));
            e.put("order_by_scene", per);
            json.put(i, e);
        }
        if (shellModel != null) {
            json.put("shell", ShellAccuracyReport.run(ShellStudy.run(shellModel, shellRings, System.out::println),
                    run));
        }
        run.finish(RunStatus.OK, json);
        System.out.println(Json.line(json));
    }

    private static Double round(double v) {
        return Double.isFinite(v) ? Math.round(v * 1000) / 1000.0 : null;
    }

    private void write(AccuracyStudy.Result r, RunFolder folder) throws IOException {
        String name = r.scene().name();
        Path csv = folder.dir().resolve("accuracy-" + name + ".csv");
        List<String> header = List.of("integrator", "dt_s", "error_m", "wall_s", "force_evaluations",
                "cg_products", "steps", "beyond_critical_step", "diverged");
        try (CsvWriter w = folder.csv("accuracy-" + name + ".csv", header, 1)) {
            for (AccuracyStudy.Run run : r.runs()) {
                w.rowText(run.integrator(), Double.toString(run.dtS()), Double.toString(run.errorM()),
                        Double.toString(run.wallS()), Long.toString(run.forceEvaluations()),
                        Long.toString(run.linearProducts()), Long.toString(run.steps()),
                        Boolean.toString(run.beyondCriticalStep()), Boolean.toString(run.diverged()));
            }
        }
        XYChart work = Charts.lineChart("Work-precision: " + name + " (reference: " + r.reference() + ")",
                "wall time of the run (s)", "largest node position error at t = " + r.scene().endTimeS() + " s (m)",
                900, 600);
        XYChart conv = Charts.lineChart("Convergence: " + name + " (reference: " + r.reference() + ")",
                "time step dt (s)", "largest node position error (m)", 900, 600);
        XYChart evals = Charts.lineChart("Work-precision by force evaluations: " + name,
                "force evaluations (+ CG products for implicit Euler)", "largest node position error (m)", 900, 600);
        Charts.logLog(work);
        Charts.logLog(conv);
        Charts.logLog(evals);
        for (String i : integrators) {
            List<double[]> pts = new ArrayList<>();
            for (AccuracyStudy.Run run : r.runs()) {
                if (run.integrator().equals(i) && Double.isFinite(run.errorM()) && run.errorM() > 0) {
                    pts.add(new double[] {run.wallS(), run.dtS(), run.errorM(),
                        run.forceEvaluations() + run.linearProducts()});
                }
            }
            if (pts.isEmpty()) {
                continue;
            }
            double[] wall = pts.stream().mapToDouble(p -> Math.max(p[0], 1e-6)).toArray();
            double[] dt = pts.stream().mapToDouble(p -> p[1]).toArray();
            double[] err = pts.stream().mapToDouble(p -> p[2]).toArray();
            double[] cost = pts.stream().mapToDouble(p -> p[3]).toArray();
            String label = String.format("%s (order %.2f)", i, r.measuredOrder().get(i));
            java.awt.Color color = Charts.color(Integrators.names().indexOf(i));
            Charts.addLineWithMarkers(work, label, wall, err);
            Charts.addLineWithMarkers(conv, label, dt, err);
            Charts.addLineWithMarkers(evals, label, cost, err);
            for (XYChart c : List.of(work, conv, evals)) {
                var series = c.getSeriesMap().get(label);
                series.setLineColor(color);
                series.setMarkerColor(color);
            }
        }
        Charts.savePng(work, folder.file(name + "-work-precision.png"));
        Charts.savePng(conv, folder.file(name + "-convergence.png"));
        Charts.savePng(evals, folder.file(name + "-evaluations.png"));
        System.out.println("wrote " + csv + ", " + folder.dir().resolve(name + "-work-precision.png") + ", "
                + folder.dir().resolve(name + "-convergence.png"));
    }
}
