package org.tensim.sweep;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.io.Charts;

/** One scatter chart per output and parameter: the output of every finished point against the parameter. */
public final class SweepCharts {
    private SweepCharts() {
    }

    /**
     * Writes {@code OUTPUT-vs-PARAMETER.png} into {@code dir} for every pair; points that diverged or
     * were refused, or lack the output, are left out. Returns the files written.
     */
    public static List<Path> write(Path dir, List<String> parameters, List<String> outputs,
            Collection<PointResult> results) throws IOException {
        List<Path> files = new ArrayList<>();
        for (String o : outputs) {
            for (int p = 0; p < parameters.size(); p++) {
                List<double[]> xy = new ArrayList<>();
                for (PointResult r : results) {
                    double y = r.field(o);
                    if (r.ok() && Double.isFinite(y)) {
                        xy.add(new double[] {r.values()[p], y});
                    }
                }
                if (xy.isEmpty()) {
                    continue;
                }
                double[] x = xy.stream().mapToDouble(v -> v[0]).toArray();
                double[] y = xy.stream().mapToDouble(v -> v[1]).toArray();
                XYChart c = Charts.lineChart(o + " against " + parameters.get(p) + " (" + xy.size() + " points)",
                        parameters.get(p), o, 700, 450);
                c.getStyler().setLegendVisible(false);
                c.getStyler().setMarkerSize(7);
                c.addSeries(o, x, y).setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter)
                        .setMarker(SeriesMarkers.CIRCLE);
                Path f = dir.resolve(o + "-vs-" + parameters.get(p) + ".png");
                Charts.savePng(c, f);
                files.add(f);
            }
        }
        return files;
    }
}
