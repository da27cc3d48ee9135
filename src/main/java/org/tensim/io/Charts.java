package org.tensim.io;

import java.io.IOException;
import java.nio.file.Path;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** Charts drawn with XChart and saved as PNG. */
public final class Charts {
    private Charts() {
    }

    /** A new line chart with the project's look. */
    public static XYChart lineChart(String title, String xTitle, String yTitle, int width, int height) {
        XYChart chart = new XYChartBuilder().width(width).height(height).title(title).xAxisTitle(xTitle)
                .yAxisTitle(yTitle).build();
        chart.getStyler().setMarkerSize(0);
        chart.getStyler().setChartBackgroundColor(java.awt.Color.WHITE);
        return chart;
    }

    /** Adds a line series without markers. */
    public static void addLine(XYChart chart, String name, double[] x, double[] y) {
        chart.addSeries(name, x, y).setMarker(SeriesMarkers.NONE);
    }

    /** Adds a line series with a marker at every point (for measured data). */
    public static void addLineWithMarkers(XYChart chart, String name, double[] x, double[] y) {
        chart.addSeries(name, x, y).setMarker(SeriesMarkers.CIRCLE);
        chart.getStyler().setMarkerSize(6);
    }

    /** Distinct colours for series that belong together (e.g. measured and theory of one method). */
    private static final java.awt.Color[] PALETTE = {
        new java.awt.Color(31, 119, 180), new java.awt.Color(255, 127, 14), new java.awt.Color(44, 160, 44),
        new java.awt.Color(214, 39, 40), new java.awt.Color(148, 103, 189), new java.awt.Color(140, 86, 75),
        new java.awt.Color(227, 119, 194), new java.awt.Color(127, 127, 127), new java.awt.Color(188, 189, 34),
        new java.awt.Color(23, 190, 207),
    };

    /** The i-th colour of the project's palette (cycling). */
    public static java.awt.Color color(int i) {
        return PALETTE[Math.floorMod(i, PALETTE.length)];
    }

    /** Makes both axes logarithmic (every plotted value must then be > 0). */
    public static void logLog(XYChart chart) {
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
    }

    /**
     * Saves the chart as a PNG file at {@code path}, written whole then renamed
     * ({@link OutputFiles#writeAtomically}). An exception of the chart library (e.g.
     * a logarithmic axis given a value <= 0) becomes an IOException naming the chart.
     */
    public static void savePng(XYChart chart, Path path) throws IOException {
        byte[] png;
        try {
            png = BitmapEncoder.getBitmapBytes(chart, BitmapEncoder.BitmapFormat.PNG);
        } catch (IOException | RuntimeException e) {
            throw new IOException("cannot draw the chart '" + chart.getTitle() + "' for " + path + ": "
                    + (e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage()), e);
        }
        OutputFiles.writeAtomically(path, out -> out.write(png));
    }

    /**
     * Saves charts side by side, left to right, as one PNG file at {@code path} (written whole then renamed); an
     * error of the chart library becomes an IOException naming the first chart, as {@link #savePng(XYChart, Path)}.
     */
    public static void savePng(java.util.List<XYChart> charts, Path path) throws IOException {
        java.io.ByteArrayOutputStream png = new java.io.ByteArrayOutputStream();
        try {
            BitmapEncoder.saveBitmap(charts, 1, charts.size(), png, BitmapEncoder.BitmapFormat.PNG);
        } catch (IOException | RuntimeException e) {
            throw new IOException("cannot draw the chart '" + charts.get(0).getTitle() + "' for " + path + ": "
                    + (e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage()), e);
        }
        OutputFiles.writeAtomically(path, out -> out.write(png.toByteArray()));
    }

    /**
     * Marks a chart of a run that diverged: its title starts with "DIVERGED at t = ... s"
     * and the plot background turns pink, so that no reader takes its curves for a result.
     */
    public static void markDiverged(XYChart chart, double atTimeS) {
        chart.setTitle(divergedTitle(atTimeS, chart.getTitle()));
        chart.getStyler().setPlotBackgroundColor(new java.awt.Color(255, 225, 225));
    }

    /**
     * "DIVERGED at t = ... s: " and the title, shortened to its part before the first colon when
     * the whole would not fit a chart's width (the mark must stay readable).
     */
    public static String divergedTitle(double atTimeS, String title) {
        String mark = String.format(java.util.Locale.ROOT, "DIVERGED at t = %.4g s: ", atTimeS);
        if (mark.length() + title.length() > 80 && title.indexOf(':') > 0) {
            title = title.substring(0, title.indexOf(':'));
        }
        return mark + title;
    }
}
