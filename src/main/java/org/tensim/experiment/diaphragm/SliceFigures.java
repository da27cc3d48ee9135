package org.tensim.experiment.diaphragm;

import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.io.Charts;

/**
 * Displacement vectors in two slices, after the paper's Fig. 5: an
 * antero-posterior (sagittal, y-z) slice through the dome apex and an axial (x-y)
 * slice below it. Each vector starts at a node's position at the first instant
 * and points along its displacement to the second, multiplied by a scale factor;
 * nodes are those of the upper surface within half a band of the slice plane.
 * Drawn with XChart (one short line series per vector).
 */
public final class SliceFigures {
    /** Most vectors drawn per slice (evenly subsampled beyond that). */
    static final int MAX_VECTORS = 260;

    private SliceFigures() {
    }

    /**
     * @param from     positions at the first instant, m (3 per node)
     * @param to       positions at the second instant, m
     * @param nodes    candidate nodes (upper surface)
     * @param axis     0 for a sagittal slice (x = planeM; plots y, z), 2 for an axial one (z = planeM; plots x, y)
     * @param planeM   the slice plane's coordinate, m
     * @param bandM    slice thickness, m
     * @param scale    vector scale factor
     * @return the number of vectors drawn
     */
    public static int write(Path png, String title, double[] from, double[] to, int[] nodes, int axis, double planeM,
            double bandM, double scale) throws IOException {
        int u = axis == 0 ? 1 : 0;
        int v = axis == 0 ? 2 : 1;
        List<Integer> in = new ArrayList<>();
        for (int n : nodes) {
            if (Math.abs(from[3 * n + axis] - planeM) <= 0.5 * bandM) {
                in.add(n);
            }
        }
        in.sort((a, b) -> Double.compare(from[3 * a + u], from[3 * b + u]));
        String uName = axis == 0 ? "y (posterior +), mm" : "x (patient's left +), mm";
        String vName = axis == 0 ? "z (superior +), mm" : "y (posterior +), mm";
        XYChart c = Charts.lineChart(title, uName, vName, 900, 700);
        c.getStyler().setLegendVisible(false);
        c.getStyler().setMarkerSize(3);
        double[] pu = new double[in.size()];
        double[] pv = new double[in.size()];
        for (int i = 0; i < in.size(); i++) {
            pu[i] = 1e3 * from[3 * in.get(i) + u];
            pv[i] = 1e3 * from[3 * in.get(i) + v];
        }
        if (in.isEmpty()) {
            pu = new double[] {0};
            pv = new double[] {0};
        }
        XYSeries pts = c.addSeries("nodes", pu, pv);
        pts.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        pts.setMarker(SeriesMarkers.CIRCLE);
        pts.setMarkerColor(Color.GRAY);
        int stride = Math.max(1, (in.size() + MAX_VECTORS - 1) / MAX_VECTORS);
        int drawn = 0;
        BasicStroke thin = new BasicStroke(1.2f);
        for (int i = 0; i < in.size(); i += stride) {
            int n = in.get(i);
            double x0 = 1e3 * from[3 * n + u];
            double y0 = 1e3 * from[3 * n + v];
            double x1 = x0 + scale * 1e3 * (to[3 * n + u] - from[3 * n + u]);
            double y1 = y0 + scale * 1e3 * (to[3 * n + v] - from[3 * n + v]);
            // The arrow: shaft, then a head of two short strokes back from the tip.
            double dx = x1 - x0;
            double dy = y1 - y0;
            double len = Math.hypot(dx, dy);
            double h = 0.3 * len;
            double ca = Math.cos(Math.toRadians(25));
            double sa = Math.sin(Math.toRadians(25));
            double ux = len > 0 ? -dx / len : 0;
            double uy = len > 0 ? -dy / len : 0;
            double[] xs = {x0, x1, x1 + h * (ux * ca - uy * sa), x1, x1 + h * (ux * ca + uy * sa)};
            double[] ys = {y0, y1, y1 + h * (uy * ca + ux * sa), y1, y1 + h * (uy * ca - ux * sa)};
            XYSeries s = c.addSeries("v" + n, xs, ys);
            s.setMarker(SeriesMarkers.NONE);
            s.setLineColor(new Color(200, 40, 40));
            s.setLineStyle(thin);
            drawn++;
        }
        Charts.savePng(c, png);
        return drawn;
    }
}
