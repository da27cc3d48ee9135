package org.tensim.experiment;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.Progress;
import org.tensim.io.RunFolder;
import org.tensim.io.RunSignals;
import org.tensim.io.RunStatus;
import org.tensim.scene.CubeParameters;
import org.tensim.solver.SimulationDivergedException;

/**
 * Runs the {@link CubeExperiment} and writes its outputs: {@code cube.csv} (time
 * and P's displacement in both cubes, every step, flushed as it goes),
 * {@code cube.png} (P's Y displacement against time, both cubes) and
 * {@code summary.json}, through a {@link RunFolder}.
 */
public final class CubeReport {
    private final Path csv;
    private final Path chart;
    private final Path summaryFile;
    private final Map<String, Object> summary;

    private CubeReport(Path dir, Map<String, Object> summary) {
        this.csv = dir.resolve("cube.csv");
        this.chart = dir.resolve("cube.png");
        this.summaryFile = dir.resolve("summary.json");
        this.summary = summary;
    }

    public Path csv() {
        return csv;
    }

    public Path chart() {
        return chart;
    }

    public Path summaryFile() {
        return summaryFile;
    }

    public Map<String, Object> summary() {
        return summary;
    }

    /** The summary as one line of JSON. */
    public String summaryLine() {
        return Json.line(summary);
    }

    /** The files the cube command writes into its folder (docs/outputs.md). */
    public static final List<String> OUTPUTS = List.of("cube.csv", "cube.png");

    /** As {@link #run(CubeParameters, String, RunFolder)} with the paper's RK2, in a run folder of its own. */
    public static CubeReport run(CubeParameters p, Path dir) throws Exception {
        CubeReport[] r = new CubeReport[1];
        RunFolder.run(dir, "cube", OUTPUTS, run -> r[0] = run(p, "rk2", run));
        return r[0];
    }

    /**
     * Runs the experiment with the named integrator and writes every output into the
     * run folder, then finishes it: status "ok", or "diverged" when a cube diverged
     * (the CSV then ends at the last finite step, the chart is marked DIVERGED and the
     * summary has the error, the step and the peaks up to it).
     */
    public static CubeReport run(CubeParameters p, String integrator, RunFolder run) throws IOException {
        CubeExperiment e = new CubeExperiment(p, integrator);
        List<double[]> series = new ArrayList<>();
        CubeExperiment.Result r = null;
        SimulationDivergedException diverged = null;
        double[] peaks = {0, 0};
        long[] count = {0};
        try (CsvWriter w = run.csv("cube.csv", List.of("t_s", "mss_dx_m", "mss_dy_m", "mss_dz_m",
                "ts_dx_m", "ts_dy_m", "ts_dz_m"), 1000)) {
            long every = Math.max(1, p.steps() / 4000);
            Progress progress = Progress.start("cube", p.durationS());
            r = e.run((t, m, s) -> {
                RunSignals.checkStop();
                w.row(t, m[0], m[1], m[2], s[0], s[1], s[2]);
                peaks[0] = Math.min(peaks[0], m[1]);
                peaks[1] = Math.min(peaks[1], s[1]);
                if (count[0]++ % every == 0) {
                    series.add(new double[] {t, m[1], s[1]});
                }
                progress.update(t);
            });
            progress.close();
        } catch (SimulationDivergedException ex) {
            diverged = ex;
        }
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("mss_peak_y_m", peaks[0]);
        s.put("ts_peak_y_m", peaks[1]);
        s.put("paper_mss_peak_y_m", CubeExperiment.PAPER_MSS_PEAK_Y_M);
        s.put("paper_ts_peak_y_m", CubeExperiment.PAPER_TS_PEAK_Y_M);
        double ratio = peaks[0] / peaks[1];
        s.put("peak_ratio_mss_over_ts", Double.isFinite(ratio) ? ratio : null);
        if (r != null) {
            s.put("ts_max_link_error_rel", r.tsMaxLinkError());
        }
        s.put("steps", r != null ? r.steps() : Math.max(0, count[0] - 1));
        s.put("dt_s", p.dtS());
        s.put("duration_s", p.durationS());
        s.put("integrator", integrator);
        if (r != null) {
            s.put("wall_s", r.wallS());
        }
        if (diverged != null) {
            s.put("diverged", diverged.getMessage());
            s.put("diverged_at_s", diverged.timeSeconds());
        }
        s.put("parameters", p);
        // The cubes are the scene file's: a summary names the file and its contents.
        s.put("scene", org.tensim.scene.file.CubeSceneFile.FILE.toString());
        s.put("scene_digest", org.tensim.io.FileDigest.of(List.of(org.tensim.scene.file.CubeSceneFile.FILE)));
        writeChart(series, run.file("cube.png"), diverged);
        Map<String, Object> written = run.finish(diverged == null ? RunStatus.OK : RunStatus.DIVERGED, s);
        return new CubeReport(run.dir(), written);
    }

    /** How the run ended. */
    public RunStatus status() {
        return RunStatus.valueOf(summary.get("status").toString().toUpperCase(java.util.Locale.ROOT));
    }

    private static void writeChart(List<double[]> series, Path png, SimulationDivergedException diverged)
            throws IOException {
        double[] t = new double[series.size()];
        double[] m = new double[series.size()];
        double[] s = new double[series.size()];
        for (int i = 0; i < t.length; i++) {
            t[i] = series.get(i)[0];
            m[i] = series.get(i)[1];
            s[i] = series.get(i)[2];
        }
        XYChart c = Charts.lineChart("Cube (10 x 10 x 10 m): vertical displacement of point P",
                "time (s)", "P, Y displacement (m)", 900, 500);
        c.getStyler().setXAxisDecimalPattern("0.0");
        Charts.addLine(c, "mass-spring (MSS)", t, m);
        Charts.addLine(c, "tensegrity (TS)", t, s);
        if (diverged != null) {
            Charts.markDiverged(c, diverged.timeSeconds());
        }
        Charts.savePng(c, png);
    }
}
