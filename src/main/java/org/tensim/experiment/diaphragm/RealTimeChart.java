package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.io.Charts;

/**
 * The real-time study's chart: the error against RK2 at the same mesh against the real-time factor,
 * one colour per configuration (its points are the resolutions), circles at end-inspiration and
 * diamonds at the worst sample of the run, with the tolerance and real time as lines: the Pareto
 * front of error against speed is its lower-right edge.
 */
final class RealTimeChart {
    private RealTimeChart() {
    }

    static void write(Path png, List<Map<String, Object>> rows) throws IOException {
        XYChart c = Charts.lineChart("Diaphragm: error against RK2 at the same mesh vs real-time factor",
                "simulated seconds per wall second (1 = real time), sync included",
                "relative RMS displacement error (o end, \u25c6 worst moment)", 1100, 700);
        c.getStyler().setXAxisLogarithmic(true);
        c.getStyler().setYAxisLogarithmic(true);
        // Two decades or so on each axis: label 1-9 times each power of ten, not the decades alone.
        c.getStyler().setXAxisLogarithmicDecadeOnly(false);
        c.getStyler().setYAxisLogarithmicDecadeOnly(false);
        List<String> labels = new ArrayList<>();
        for (Map<String, Object> r : rows) {
            if (!labels.contains((String) r.get("config")) && !r.get("config").equals(rows.get(0).get("config"))) {
                labels.add((String) r.get("config"));
            }
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = 0;
        double bottom = Double.POSITIVE_INFINITY;
        double top = 0;
        int colour = 0;
        for (String label : labels) {
            for (String measure : new String[] {"error_vs_rk2_same_resolution", "worst_error_vs_rk2_same_resolution"}) {
                List<Double> x = new ArrayList<>();
                List<Double> y = new ArrayList<>();
                for (Map<String, Object> r : rows) {
                    double e = (double) r.get(measure);
                    double f = (double) r.get("realtime_factor");
                    if (r.get("config").equals(label) && !(boolean) r.get("diverged") && f > 0 && e > 0
                            && Double.isFinite(e)) {
                        x.add(f);
                        y.add(e);
                        lo = Math.min(lo, f);
                        hi = Math.max(hi, f);
                        bottom = Math.min(bottom, e);
                        top = Math.max(top, e);
                    }
                }
                if (!x.isEmpty()) {
                    boolean end = measure.startsWith("error");
                    XYSeries s = c.addSeries(label + (end ? "" : " (worst)"), x, y);
                    s.setMarker(end ? SeriesMarkers.CIRCLE : SeriesMarkers.DIAMOND);
                    s.setLineColor(Charts.color(colour));
                    s.setMarkerColor(Charts.color(colour));
                    s.setShowInLegend(end);
                }
            }
            colour++;
        }
        if (hi > 0) {
            double yLo = Math.min(bottom, RealTimeStudy.TOLERANCE) / 2;
            double yHi = Math.max(top, RealTimeStudy.TOLERANCE) * 2;
            Charts.addLine(c, "real time", new double[] {1, 1}, new double[] {yLo, yHi});
            double xLo = Math.min(lo, 1) / 1.5;
            double xHi = Math.max(hi, 1) * 1.5;
            Charts.addLine(c, "tolerance (5 %)", new double[] {xLo, xHi},
                    new double[] {RealTimeStudy.TOLERANCE, RealTimeStudy.TOLERANCE});
            c.getStyler().setXAxisMin(xLo);
            c.getStyler().setXAxisMax(xHi);
            c.getStyler().setYAxisMin(yLo);
            c.getStyler().setYAxisMax(yHi);
        }
        c.getStyler().setMarkerSize(7);
        Charts.savePng(c, png);
    }
}
