package org.tensim.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.io.Charts;

/**
 * The scaling chart: cost per spring per step (ns, best of the repeats) against the
 * number of springs, one line per thread count and integrator. A flat line means
 * the cost grows linearly with the work; a rise shows where the working set leaves
 * a cache level.
 */
final class ScalingChart {
    private ScalingChart() {
    }

    static void write(List<Map<String, Object>> results, Path png) throws IOException {
        Map<String, List<double[]>> series = new TreeMap<>();
        for (Map<String, Object> r : results) {
            String key = r.get("threads") + (((Integer) r.get("threads")) == 1 ? " thread, " : " threads, ")
                    + r.get("integrator") + ((Integer) r.get("links") > 0 ? ", links" : "")
                    + (Boolean.TRUE.equals(r.get("shuffled")) ? ", shuffled" : "");
            series.computeIfAbsent(key, k -> new ArrayList<>())
                    .add(new double[] {((Number) r.get("springs")).doubleValue(),
                        ((Number) r.get("ns_per_spring_step")).doubleValue()});
        }
        XYChart chart = Charts.lineChart("Cost per spring per step (lattice, best of repeats)", "springs",
                "ns per spring per step (all stages)", 900, 560);
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisMin(0.0);
        chart.getStyler().setMarkerSize(7);
        for (Map.Entry<String, List<double[]>> e : series.entrySet()) {
            List<double[]> pts = e.getValue();
            pts.sort((p, q) -> Double.compare(p[0], q[0]));
            double[] x = new double[pts.size()];
            double[] y = new double[pts.size()];
            for (int i = 0; i < x.length; i++) {
                x[i] = pts.get(i)[0];
                y[i] = pts.get(i)[1];
            }
            chart.addSeries(e.getKey(), x, y).setMarker(SeriesMarkers.CIRCLE);
        }
        Charts.savePng(chart, png);
    }
}
