package org.tensim.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.analysis.lungs.FourDctComparison;
import org.tensim.analysis.lungs.MeasuredCase;
import org.tensim.analysis.lungs.ModelFigures;
import org.tensim.analysis.lungs.SiProfile;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.RunFolder;
import org.tensim.io.landmarks.DirLabLandmarks;

/**
 * What {@code tensim validate-4dct} writes (docs/lungs.md): the chart {@value #CHART} (left, the SI ratio of each
 * height bin, model and cases; right, each phase's share, model, its breathing law and cases), a CSV per case
 * ({@code caseN.csv}) and a printed table of the targets.
 */
final class Validate4dctOutputs {
    /** The chart's file. */
    static final String CHART = "validate-4dct.png";
    /** A case's CSV's header. */
    static final List<String> CASE_HEADER = List.of("quantity", "item", "eta_from", "eta_to", "phase_percent",
            "model_time_s", "measured", "model", "model_law", "measured_low_x", "measured_high_x", "model_right",
            "model_left");

    private Validate4dctOutputs() {
    }

    /** Writes the chart and the cases' CSVs into {@code run}. */
    static void write(RunFolder run, FourDctComparison c) throws IOException {
        for (MeasuredCase mc : c.cases()) {
            caseCsv(run, c.model(), mc);
        }
        Charts.savePng(List.of(profileChart(c), phaseChart(c)), run.file(CHART));
    }

    private static void caseCsv(RunFolder run, ModelFigures m, MeasuredCase mc) throws IOException {
        try (CsvWriter w = run.csv("case" + mc.caseNumber() + ".csv", CASE_HEADER, 100)) {
            for (int b = 0; b < SiProfile.BINS; b++) {
                w.rowText("si_ratio", "bin" + (b + 1), num(b / (double) SiProfile.BINS),
                        num((b + 1) / (double) SiProfile.BINS), "", "", num(mc.both().ratio()[b]),
                        num(m.both().ratio()[b]), "", num(mc.lowX().ratio()[b]), num(mc.highX().ratio()[b]),
                        num(m.right() == null ? Double.NaN : m.right().ratio()[b]),
                        num(m.left() == null ? Double.NaN : m.left().ratio()[b]));
            }
            w.rowText("basal_si_mm", "bin" + SiProfile.BINS, num(0.8), num(1), "", "",
                    num(mc.both().basalSiM() * 1e3), num(m.both().basalSiM() * 1e3), "",
                    num(mc.lowX().basalSiM() * 1e3), num(mc.highX().basalSiM() * 1e3),
                    num(m.right() == null ? Double.NaN : m.right().basalSiM() * 1e3),
                    num(m.left() == null ? Double.NaN : m.left().basalSiM() * 1e3));
            w.rowText("mean_3d_mm", "all", num(0), num(1), "", "", num(mc.both().mean3dM() * 1e3),
                    num(m.both().mean3dM() * 1e3), "", num(mc.lowX().mean3dM() * 1e3),
                    num(mc.highX().mean3dM() * 1e3),
                    num(m.right() == null ? Double.NaN : m.right().mean3dM() * 1e3),
                    num(m.left() == null ? Double.NaN : m.left().mean3dM() * 1e3));
            for (int p = 0; p < DirLabLandmarks.SIX_PHASES.size(); p++) {
                w.rowText("phase_share", DirLabLandmarks.SIX_PHASES.get(p), "", "",
                        Integer.toString(ModelFigures.phasePercent(p)), num(m.phaseTimesS()[p]), num(mc.shares()[p]),
                        num(m.shares()[p]), m.lawShares() == null ? "" : num(m.lawShares()[p]),
                        num(mc.sharesLowX()[p]), num(mc.sharesHighX()[p]),
                        m.sharesRight() == null ? "" : num(m.sharesRight()[p]),
                        m.sharesLeft() == null ? "" : num(m.sharesLeft()[p]));
            }
        }
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.6g", v);
    }

    private static XYChart profileChart(FourDctComparison c) {
        XYChart chart = Charts.lineChart("SI displacement / basal bin's, end-exhale to end-inhale",
                "normalised height (0 apex, 1 base), bin centres", "ratio to the basal bin", 700, 520);
        double[] eta = new double[SiProfile.BINS];
        for (int b = 0; b < eta.length; b++) {
            eta[b] = (b + 0.5) / SiProfile.BINS;
        }
        targetBand(chart, java.util.Arrays.copyOf(eta, SiProfile.BINS - 1), c.verdicts().subList(0, 4));
        int k = 0;
        for (MeasuredCase mc : c.cases()) {
            measured(chart, "case " + mc.caseNumber(), eta, mc.both().ratio(), k++);
        }
        model(chart, "model, both lungs", eta, c.model().both().ratio(), SeriesLines.SOLID, 3f, java.awt.Color.BLACK);
        if (c.model().right() != null) {
            model(chart, "model, right lung", eta, c.model().right().ratio(), SeriesLines.DASH_DASH, 1.5f, GREY);
        }
        if (c.model().left() != null) {
            model(chart, "model, left lung", eta, c.model().left().ratio(), SeriesLines.DOT_DOT, 1.5f, GREY);
        }
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW);
        return chart;
    }

    private static XYChart phaseChart(FourDctComparison c) {
        XYChart chart = Charts.lineChart("Share of the end-inhale displacement at each phase",
                "phase, % of the cycle after end-inhale (t00 end-inhale, t50 end-exhale)", "share", 700, 520);
        double[] pct = new double[DirLabLandmarks.SIX_PHASES.size()];
        for (int p = 0; p < pct.length; p++) {
            pct[p] = ModelFigures.phasePercent(p);
        }
        targetBand(chart, java.util.Arrays.copyOfRange(pct, 1, 5), c.verdicts().subList(6, 10));
        int k = 0;
        for (MeasuredCase mc : c.cases()) {
            measured(chart, "case " + mc.caseNumber(), pct, mc.shares(), k++);
        }
        model(chart, "model, its points", pct, c.model().shares(), SeriesLines.SOLID, 3f, java.awt.Color.BLACK);
        if (c.model().lawShares() != null) {
            model(chart, "model, its breathing law", pct, c.model().lawShares(), SeriesLines.DASH_DASH, 2f, GREY);
        }
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNE);
        return chart;
    }

    private static void measured(XYChart chart, String name, double[] x, double[] y, int k) {
        double[][] xy = finite(x, y);
        XYSeries s = chart.addSeries(name, xy[0], xy[1]);
        s.setMarker(SeriesMarkers.CIRCLE);
        s.setLineColor(Charts.color(k + 1));
        s.setMarkerColor(Charts.color(k + 1));
        s.setLineStyle(SeriesLines.DOT_DOT);
        chart.getStyler().setMarkerSize(6);
    }

    /** The colour of the model's secondary lines and of the targets' bounds. */
    private static final java.awt.Color GREY = new java.awt.Color(110, 110, 110);

    /** The targets' ranges at {@code x} as two thin grey lines, "target: cases' range +/- 0.1". */
    private static void targetBand(XYChart chart, double[] x, List<FourDctComparison.Verdict> v) {
        double[] lo = v.stream().mapToDouble(FourDctComparison.Verdict::lo).toArray();
        double[] hi = v.stream().mapToDouble(FourDctComparison.Verdict::hi).toArray();
        String name = "target: cases' range +/- " + FourDctComparison.WIDEN;
        for (double[] y : List.of(lo, hi)) {
            double[][] xy = finite(x, y);
            XYSeries s = chart.addSeries(y == lo ? name : name + " ", xy[0], xy[1]);
            s.setMarker(SeriesMarkers.NONE);
            s.setLineColor(new java.awt.Color(190, 190, 190));
            s.setLineStyle(new java.awt.BasicStroke(1f));
            s.setShowInLegend(y == lo);
        }
    }

    private static void model(XYChart chart, String name, double[] x, double[] y, java.awt.BasicStroke line,
            float width, java.awt.Color colour) {
        double[][] xy = finite(x, y);
        XYSeries s = chart.addSeries(name, xy[0], xy[1]);
        s.setMarker(SeriesMarkers.SQUARE);
        s.setLineColor(colour);
        s.setMarkerColor(colour);
        s.setLineStyle(new java.awt.BasicStroke(width, line.getEndCap(), line.getLineJoin(), line.getMiterLimit(),
                line.getDashArray(), 0));
    }

    /** The points whose y is a number (an empty bin's ratio is NaN and is left out of the line). */
    private static double[][] finite(double[] x, double[] y) {
        List<double[]> keep = new ArrayList<>();
        for (int i = 0; i < x.length; i++) {
            if (Double.isFinite(y[i])) {
                keep.add(new double[] {x[i], y[i]});
            }
        }
        if (keep.isEmpty()) {
            keep.add(new double[] {x[0], 0}); // XChart refuses an empty series; an all-empty line sits at 0
        }
        double[][] out = new double[2][keep.size()];
        for (int i = 0; i < keep.size(); i++) {
            out[0][i] = keep.get(i)[0];
            out[1][i] = keep.get(i)[1];
        }
        return out;
    }

    /** Prints the model's figures, the measured ranges and each target's verdict. */
    static void print(PrintWriter out, FourDctComparison c) {
        ModelFigures m = c.model();
        out.println(String.format(Locale.ROOT, "model (%d points): SI ratio by height bin, apex to base %s; basal"
                + " SI %.2f mm; mean 3D %.2f mm", m.both().points(), fmt(m.both().ratio()),
                m.both().basalSiM() * 1e3, m.both().mean3dM() * 1e3));
        out.println("model shares t00..t50 (its points): " + fmt(m.shares()) + (m.lawShares() == null
                ? "; the run gives no breathing law" : "; its breathing law: " + fmt(m.lawShares())));
        out.println("phase times, s (t00 = end-inhale, tNN = end-inhale + NN % of the period): "
                + fmt(m.phaseTimesS()));
        out.println("target           value   range            pass");
        for (FourDctComparison.Verdict v : c.verdicts()) {
            out.println(String.format(Locale.ROOT, "%-15s %7.3f  %7.3f-%-7.3f  %s", v.name(), v.value(), v.lo(),
                    v.hi(), v.pass() ? "yes" : "NO"));
        }
        out.println(c.passed() + " of " + c.verdicts().size() + " targets met");
    }

    private static String fmt(double[] v) {
        StringBuilder b = new StringBuilder();
        for (double x : v) {
            b.append(b.length() == 0 ? "" : " ").append(String.format(Locale.ROOT, "%.3f", x));
        }
        return b.toString();
    }
}
