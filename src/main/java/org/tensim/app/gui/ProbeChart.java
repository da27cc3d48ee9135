package org.tensim.app.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.util.ArrayDeque;
import java.util.List;
import org.knowm.xchart.XChartPanel;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.ProbeRecorder;

/**
 * Live XChart of each body's probe displacement (m) against simulated time (s),
 * over the last {@value #WINDOW_S} s. Samples come from a {@link ProbeRecorder}
 * and are drawn on the Swing thread by {@link #refresh()}.
 */
final class ProbeChart {
    /** Width of the time window shown, s. */
    static final double WINDOW_S = 20;
    private static final int MAX_POINTS = 1200;
    private static final String[] AXIS = {"x", "y", "z", "|d|"};

    private final XYChart chart;
    private final XChartPanel<XYChart> panel;
    private final ArrayDeque<double[]> samples = new ArrayDeque<>(); // t, then x y z per body
    private ProbeRecorder recorder;
    private List<Body> bodies = List.of();
    private int axis;
    private boolean dirty;

    ProbeChart(int axis) {
        this.axis = axis;
        chart = new XYChartBuilder().width(600).height(200).title("Probe displacement").xAxisTitle("time (s)")
                .yAxisTitle(yTitle()).build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setMarkerSize(0);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setPlotGridLinesVisible(true);
        // No decimal pattern on y: XChart 3.8.8 loops forever computing ticks when a pattern cannot tell
        // tiny values apart (a probe that has moved by nanometres). Its default formatting copes.
        chart.getStyler().setXAxisDecimalPattern("0.##");
        chart.getStyler().setXAxisMaxLabelCount(12); // readable time labels on a long window
        chart.getStyler().setChartTitleFont(chart.getStyler().getChartTitleFont().deriveFont(12f));
        panel = new XChartPanel<>(chart);
        panel.setName("probeChart");
        panel.setPreferredSize(new Dimension(600, 210));
    }

    XChartPanel<XYChart> panel() {
        return panel;
    }

    /** Starts over with a new scene's recorder. */
    void attach(ProbeRecorder r, List<Body> b) {
        for (String name : List.copyOf(chart.getSeriesMap().keySet())) {
            chart.removeSeries(name);
        }
        recorder = r;
        bodies = b;
        samples.clear();
        for (Body body : b) {
            XYSeries s = chart.addSeries(seriesName(body), new double[] {0}, new double[] {0});
            s.setMarker(SeriesMarkers.NONE);
        }
        dirty = true;
    }

    /** Chart component: 0 = x, 1 = y, 2 = z, 3 = magnitude. */
    void setAxis(int a) {
        axis = a;
        chart.setYAxisTitle(yTitle());
        dirty = true;
    }

    private String yTitle() {
        return "displacement " + AXIS[axis] + " (m)";
    }

    private static String seriesName(Body b) {
        return b.name() + " probe";
    }

    /** Takes new samples and redraws when anything changed. Swing thread. */
    void refresh() {
        if (recorder == null) {
            return;
        }
        recorder.drain(this::add);
        redraw();
    }

    /** Adds one sample: time (s) and per body the displacement (m). */
    void add(double t, double[][] d) {
        double[] row = new double[1 + 3 * d.length];
        row[0] = t;
        for (int b = 0; b < d.length; b++) {
            System.arraycopy(d[b], 0, row, 1 + 3 * b, 3);
        }
        samples.addLast(row);
        dirty = true;
    }

    /** Puts the samples held into the chart's series, when they changed. */
    void redraw() {
        if (!dirty || samples.isEmpty()) {
            return;
        }
        double end = samples.peekLast()[0];
        while (samples.size() > 1 && samples.peekFirst()[0] < end - WINDOW_S) {
            samples.removeFirst();
        }
        int stride = Math.max(1, (samples.size() + MAX_POINTS - 1) / MAX_POINTS);
        int n = (samples.size() + stride - 1) / stride;
        double[] t = new double[n];
        double[][] y = new double[bodies.size()][n];
        int i = 0;
        int k = 0;
        for (double[] row : samples) {
            if (k++ % stride != 0) {
                continue;
            }
            t[i] = row[0];
            for (int b = 0; b < bodies.size(); b++) {
                y[b][i] = component(row, b);
            }
            i++;
        }
        for (int b = 0; b < bodies.size(); b++) {
            chart.updateXYSeries(seriesName(bodies.get(b)), t, y[b], null);
        }
        // At least 0.1 s of time axis, so that the "0.##" time labels stay distinct.
        chart.getStyler().setXAxisMin(t[0]);
        chart.getStyler().setXAxisMax(Math.max(t[n - 1], t[0] + 0.1));
        dirty = false;
        panel.revalidate();
        panel.repaint();
    }

    private double component(double[] row, int body) {
        int o = 1 + 3 * body;
        if (axis < 3) {
            return row[o + axis];
        }
        return Math.sqrt(row[o] * row[o] + row[o + 1] * row[o + 1] + row[o + 2] * row[o + 2]);
    }

    /** Draws the chart into an image (tests, and what the panel paints). */
    java.awt.image.BufferedImage render() {
        return org.knowm.xchart.BitmapEncoder.getBufferedImage(chart);
    }

    /** Samples currently held (for tests). */
    int sampleCount() {
        return samples.size();
    }

    /** Latest value charted for a body (for tests); NaN when none. */
    double latest(int body) {
        return samples.isEmpty() ? Double.NaN : component(samples.peekLast(), body);
    }
}
