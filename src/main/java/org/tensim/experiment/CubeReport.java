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
import org.tensim.scene.CubeParameters;
import org.tensim.solver.SimulationDivergedException;

/**
 * Runs the {@link CubeExperiment} and writes its outputs: {@code cube.csv} (time
 * and P's displacement in both cubes, every step, flushed as it goes),
 * {@code cube.png} (P's Y displacement against time, both cubes) and
 * {@code summary.json}.
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

    /**
     * Runs the experiment and writes every output to {@code dir}. If a cube
     * diverges the CSV keeps the rows written so far and the error names the step.
     */
    public static CubeReport run(CubeParameters p, Path dir) throws IOException {
        return run(p, "rk2", dir);
    }

    /** As {@link #run(CubeParameters, Path)} with the named integrator. */
    public static CubeReport run(CubeParameters p, String integrator, Path dir) throws IOException {
        CubeExperiment e = new CubeExperiment(p, integrator);
        List<double[]> series = new ArrayList<>();
        CubeExperiment.Result r;
        try (CsvWriter w = new CsvWriter(dir.resolve("cube.csv"), List.of("t_s", "mss_dx_m", "mss_dy_m", "mss_dz_m",
                "ts_dx_m", "ts_dy_m", "ts_dz_m"), 1000)) {
            long every = Math.max(1, p.steps() / 4000);
            long[] count = {0};
            r = e.run((t, m, s) -> {
                w.row(t, m[0], m[1], m[2], s[0], s[1], s[2]);
                if (count[0]++ % every == 0) {
                    series.add(new double[] {t, m[1], s[1]});
                }
            });
        } catch (SimulationDivergedException ex) {
            throw new IOException(ex.getMessage() + "; the rows up to that step are in "
                    + dir.resolve("cube.csv"), ex);
        }
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("mss_peak_y_m", r.mssPeakY());
        s.put("ts_peak_y_m", r.tsPeakY());
        s.put("paper_mss_peak_y_m", CubeExperiment.PAPER_MSS_PEAK_Y_M);
        s.put("paper_ts_peak_y_m", CubeExperiment.PAPER_TS_PEAK_Y_M);
        s.put("peak_ratio_mss_over_ts", r.mssPeakY() / r.tsPeakY());
        s.put("ts_max_link_error_rel", r.tsMaxLinkError());
        s.put("steps", r.steps());
        s.put("dt_s", r.dtS());
        s.put("duration_s", p.durationS());
        s.put("integrator", integrator);
        s.put("wall_s", r.wallS());
        s.put("parameters", p);
        CubeReport report = new CubeReport(dir, s);
        Json.write(report.summaryFile, s);
        writeChart(series, report.chart);
        return report;
    }

    private static void writeChart(List<double[]> series, Path png) throws IOException {
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
        Charts.savePng(c, png);
    }
}
