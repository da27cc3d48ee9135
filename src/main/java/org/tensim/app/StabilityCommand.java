package org.tensim.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.knowm.xchart.XYChart;
import org.tensim.analysis.StabilityStudy;
import org.tensim.cli.OutFolderOption;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.stability.LinearStability;
import org.tensim.solver.stability.StabilityTheory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim stability}: the largest stable step of every integrator, measured against theory. */
@Command(name = "stability", mixinStandardHelpOptions = true,
        description = {"Finds by bisection the largest stable time step of every integrator on one spring, against"
            + " theory.",
            "A run is stable when it stays finite and its displacement over the last quarter of the run is at most"
                + " twice that over the first, over --periods periods. The search spans stiffness-to-mass ratios"
                + " (w = sqrt(k/m)) and damping ratios, against linear stability theory (docs/physics.md). Writes"
                + " stability.csv, stability-omega.png and stability-damping.png to --out.",
            "The last line is one JSON object with, per integrator, the measured `critical_omega_h` and the"
                + " `theory_omega_h` of the undamped spring (null: stable at every step tried, flagged by"
                + " `stable_at_every_step`)."})
public final class StabilityCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = {"--integrator", "--integrators"}, split = ",", paramLabel = "NAME[,NAME...]",
            hideParamSyntax = true,
            description = "Integrators, comma-separated (default: all of ${COMPLETION-CANDIDATES}).",
            completionCandidates = Integrators.Names.class)
    List<String> integrators = Integrators.names();

    @Option(names = "--omega", split = ",", paramLabel = "W[,W...]", hideParamSyntax = true,
            description = "Natural frequencies sqrt(k/m), rad/s, undamped (default: ${DEFAULT-VALUE}).")
    List<Double> omegas = List.of(1.0, 10.0, 100.0, 1000.0);

    @Option(names = "--zeta", split = ",", paramLabel = "Z[,Z...]", hideParamSyntax = true,
            description = "Damping ratios at w = 10 rad/s (default: ${DEFAULT-VALUE}).")
    List<Double> zetas = List.of(0.0, 0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0);

    @Option(names = "--periods", paramLabel = "P", description = "Periods per trial run (default: ${DEFAULT-VALUE}).")
    int periods = 50;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "stability"));

    private static final double REF_OMEGA = 10;
    private static final double TOL = 1e-4;

    @Override
    public Integer call() throws Exception {
        for (String i : integrators) {
            Integrators.create(i);
        }
        for (double w : omegas) {
            if (!(w > 0) || !Double.isFinite(w)) {
                throw new IllegalArgumentException("--omega values must be finite and > 0 rad/s, got " + w);
            }
        }
        for (double z : zetas) {
            if (!(z >= 0) || !Double.isFinite(z)) {
                throw new IllegalArgumentException("--zeta values must be finite and >= 0, got " + z);
            }
        }
        if (periods < 1) {
            throw new IllegalArgumentException("--periods must be at least 1, got " + periods);
        }
        return RunFolder.run(out.folder(spec), "stability", OUTPUTS, out.overwrite(), this::study);
    }

    /** The files this command writes into --out (docs/outputs.md). */
    static final List<String> OUTPUTS = List.of("stability.csv", "stability-omega.png", "stability-damping.png");

    private void study(RunFolder run) throws IOException {
        Path csv = run.dir().resolve("stability.csv");
        Map<String, Object> json = new LinkedHashMap<>();
        XYChart byOmega = Charts.lineChart("Largest stable step on an undamped spring (points: measured, "
                + "lines: theory)", "w = sqrt(k/m) (rad/s)", "critical time step h (s)", 900, 600);
        XYChart byZeta = Charts.lineChart("Stability map: largest stable w h against damping (points: measured, "
                + "dashed: theory)", "damping ratio zeta", "critical w h", 900, 600);
        Charts.logLog(byOmega);
        byZeta.getStyler().setYAxisLogarithmic(true);
        try (CsvWriter w = run.csv("stability.csv", List.of("integrator", "omega_rad_s", "zeta", "measured_omega_h",
                "theory_omega_h", "measured_h_s", "theory_h_s"), 1)) {
            for (String name : integrators) {
                // Theory from the method's own description; NaN (null in JSON) for a method without one.
                LinearStability st = Integrators.create(name).stability();
                List<double[]> om = new ArrayList<>();
                for (double omega : omegas) {
                    double m = StabilityStudy.criticalOmegaH(name, omega, 0, periods, TOL);
                    double th = st == null ? Double.NaN : StabilityTheory.criticalOmegaH(st, 0);
                    w.rowText(name, Double.toString(omega), "0", Double.toString(m), Double.toString(th),
                            Double.toString(m / omega), Double.toString(th / omega));
                    om.add(new double[] {omega, m, th});
                    System.out.println(String.format("%-16s w = %8.1f rad/s  zeta = 0     critical w h: measured %8.4f, "
                            + "theory %8.4f", name, omega, m, th));
                }
                List<double[]> zs = new ArrayList<>();
                for (double zeta : zetas) {
                    double m = StabilityStudy.criticalOmegaH(name, REF_OMEGA, zeta, periods, TOL);
                    double th = st == null ? Double.NaN : StabilityTheory.criticalOmegaH(st, zeta);
                    w.rowText(name, Double.toString(REF_OMEGA), Double.toString(zeta), Double.toString(m),
                            Double.toString(th), Double.toString(m / REF_OMEGA), Double.toString(th / REF_OMEGA));
                    zs.add(new double[] {zeta, m, th});
                    System.out.println(String.format("%-16s w = %8.1f rad/s  zeta = %-5.2f critical w h: measured %8.4f, "
                            + "theory %8.4f", name, REF_OMEGA, zeta, m, th));
                }
                java.awt.Color color = Charts.color(Integrators.names().indexOf(name));
                plot(byOmega, name, om, true, color);
                plot(byZeta, name, zs, false, color);
                double measured = StabilityStudy.criticalOmegaH(name, REF_OMEGA, 0, periods, TOL);
                double theory = st == null ? Double.NaN : st.undampedLimit();
                Map<String, Object> e = new LinkedHashMap<>();
                e.put("critical_omega_h", finite(measured));
                e.put("theory_omega_h", finite(theory));
                e.put("stable_at_every_step", measured == Double.POSITIVE_INFINITY);
                json.put(name, e);
            }
        }
        Charts.savePng(byOmega, run.file("stability-omega.png"));
        Charts.savePng(byZeta, run.file("stability-damping.png"));
        System.out.println("wrote " + csv + ", " + run.dir().resolve("stability-omega.png") + ", "
                + run.dir().resolve("stability-damping.png") + " (implicit Euler, stable at every step tried, is not"
                + " drawn)");
        run.finish(RunStatus.OK, json);
        System.out.println(Json.line(json));
    }

    /** Measured points and the theory line of one integrator; only finite, positive values can be drawn. */
    private static void plot(XYChart chart, String name, List<double[]> rows, boolean asStep, java.awt.Color color) {
        List<double[]> meas = new ArrayList<>();
        List<double[]> theo = new ArrayList<>();
        for (double[] r : rows) {
            double scale = asStep ? r[0] : 1;
            if (r[1] > 0 && Double.isFinite(r[1])) {
                meas.add(new double[] {r[0], r[1] / scale});
            }
            if (r[2] > 0 && Double.isFinite(r[2])) {
                theo.add(new double[] {r[0], r[2] / scale});
            }
        }
        if (!meas.isEmpty()) {
            var m = chart.addSeries(name + " measured", meas.stream().mapToDouble(p -> p[0]).toArray(),
                    meas.stream().mapToDouble(p -> p[1]).toArray());
            m.setXYSeriesRenderStyle(org.knowm.xchart.XYSeries.XYSeriesRenderStyle.Scatter);
            m.setMarkerColor(color);
            chart.getStyler().setMarkerSize(8);
        }
        if (!theo.isEmpty()) {
            var s = chart.addSeries(name + " theory", theo.stream().mapToDouble(p -> p[0]).toArray(),
                    theo.stream().mapToDouble(p -> p[1]).toArray());
            s.setMarker(org.knowm.xchart.style.markers.SeriesMarkers.NONE);
            s.setLineColor(color);
            s.setLineStyle(new java.awt.BasicStroke(1.5f, java.awt.BasicStroke.CAP_BUTT,
                    java.awt.BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f));
        }
    }

    private static Double finite(double v) {
        return Double.isFinite(v) ? Math.round(v * 1e5) / 1e5 : null;
    }
}
