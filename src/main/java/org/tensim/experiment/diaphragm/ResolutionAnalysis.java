package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;

/**
 * What a resolution study measured, family by family: each model's error against the
 * family's finest, the convergence order, and the coarsest model within a tolerance.
 *
 * <p>Error: relative RMS of the end-inspiration displacement of the upper surface against the
 * finest model's, the coarse field interpolated at each fine node ({@link ResolutionStudy#error}).
 *
 * <p>Order: with h the mean edge length, the least-squares slope p of log e against log h
 * over the models coarser than the reference ({@code e ~ C h^p}), and the order between
 * neighbours {@code log(e_i / e_j) / log(h_i / h_j)}. Measured against the finest model
 * rather than the exact solution, the errors of the models nearest the reference are
 * underestimated, which steepens the apparent order there.
 */
final class ResolutionAnalysis {
    private ResolutionAnalysis() {
    }

    /**
     * The coarse models' fields transferred to their finest model's upper nodes ({@link FieldTransfer#differences}),
     * each pair once: the error, where it sits and {@code resolution-nodes.csv} read the same transfer, the costly
     * part of the analysis (a search of the coarse surface for each of the full mesh's upper nodes).
     */
    static final class Transfers {
        private final Map<ResolutionStudy.Run, Map<ResolutionStudy.Run, double[]>> byFine = new IdentityHashMap<>();
        private int computed;

        /** The differences of {@code coarse}'s transferred field from {@code fine}'s, m (3 per node of fine). */
        double[] differences(ResolutionStudy.Run fine, ResolutionStudy.Run coarse) {
            return byFine.computeIfAbsent(fine, f -> new IdentityHashMap<>()).computeIfAbsent(coarse, c -> {
                computed++;
                return FieldTransfer.differences(fine, c);
            });
        }

        /** How many transfers were computed. */
        int computed() {
            return computed;
        }
    }

    /** One row per model, coarse to fine, with the error and the order to the next finer model. */
    static List<Map<String, Object>> rows(List<ResolutionStudy.Run> family) {
        return rows(family, new Transfers());
    }

    /** As {@link #rows(List)}, the transfers taken from (and kept in) {@code transfers}. */
    static List<Map<String, Object>> rows(List<ResolutionStudy.Run> family, Transfers transfers) {
        ResolutionStudy.Run ref = family.get(family.size() - 1);
        List<Map<String, Object>> rows = new ArrayList<>();
        double[] e = new double[family.size()];
        List<List<Map<String, Object>>> hotspots = new ArrayList<>();
        for (int i = 0; i < family.size(); i++) {
            ResolutionStudy.Run r = family.get(i);
            hotspots.add(null);
            if (i == family.size() - 1) {
                e[i] = 0;
            } else if (r.upperTriangles() != null) {
                // One transfer of the coarse field (the costly part) for the error and where it sits.
                double[] diff = transfers.differences(ref, r);
                e[i] = FieldTransfer.relativeRms(ref.rest(), ref.end(), ref.upper(), diff);
                hotspots.set(i, ErrorHotspots.of(ref.rest(), ref.upper(), diff, ErrorHotspots.CELL_M,
                        ErrorHotspots.TOP));
            } else {
                e[i] = ResolutionStudy.error(ref, r);
            }
        }
        for (int i = 0; i < family.size(); i++) {
            ResolutionStudy.Run r = family.get(i);
            Map<String, Object> row = new LinkedHashMap<>();
            row.put("family", r.family());
            row.put("model", r.label());
            row.put("nodes", r.nodes());
            row.put("springs", r.springs());
            row.put("element_mm", DiaphragmReport.round(r.elementSizeM() * 1e3, 3));
            row.put("dt_s", r.dt());
            row.put("wall_s_per_simulated_s", DiaphragmReport.round(r.costPerSimS(), 3));
            row.put("apex_descent_mm", DiaphragmReport.round(r.apexDescentM() * 1e3, 3));
            row.put("relative_rms_error", DiaphragmReport.round(e[i], 4));
            if (hotspots.get(i) != null) {
                row.put("error_hotspots", hotspots.get(i));
            }
            if (i + 2 < family.size() && e[i] > 0 && e[i + 1] > 0) {
                row.put("order_to_next", DiaphragmReport.round(
                        Math.log(e[i] / e[i + 1]) / Math.log(r.elementSizeM() / family.get(i + 1).elementSizeM()), 3));
            }
            rows.add(row);
        }
        return rows;
    }

    /** Least-squares slope of log(error) on log(element size) over the rows with a positive error; NaN under 2. */
    static double order(List<Map<String, Object>> rows) {
        double sx = 0;
        double sy = 0;
        double sxx = 0;
        double sxy = 0;
        int n = 0;
        for (Map<String, Object> r : rows) {
            double e = (double) r.get("relative_rms_error");
            if (e > 0) {
                double x = Math.log((double) r.get("element_mm"));
                double y = Math.log(e);
                sx += x;
                sy += y;
                sxx += x * x;
                sxy += x * y;
                n++;
            }
        }
        return n < 2 ? Double.NaN : (n * sxy - sx * sy) / (n * sxx - sx * sx);
    }

    /** Whether the errors fall at every refinement (rows coarse to fine). */
    static boolean monotone(List<Map<String, Object>> rows) {
        for (int i = 0; i + 1 < rows.size(); i++) {
            if ((double) rows.get(i + 1).get("relative_rms_error") >= (double) rows.get(i).get("relative_rms_error")) {
                return false;
            }
        }
        return true;
    }

    /**
     * Index of the coarsest row that is within the tolerance together with every finer row; the last
     * (the reference) when none is.
     */
    static int pick(List<Map<String, Object>> rows, double tolerance) {
        int pick = rows.size() - 1;
        for (int i = rows.size() - 2; i >= 0; i--) {
            if ((double) rows.get(i).get("relative_rms_error") > tolerance) {
                break;
            }
            pick = i;
        }
        return pick;
    }

    static void csv(Path file, List<Map<String, Object>> rows) throws IOException {
        List<String> cols = List.of("family", "model", "nodes", "springs", "element_mm", "dt_s",
                "wall_s_per_simulated_s", "apex_descent_mm", "relative_rms_error", "order_to_next");
        try (CsvWriter csv = new CsvWriter(file, cols, 1)) {
            for (Map<String, Object> r : rows) {
                String[] cells = new String[cols.size()];
                for (int i = 0; i < cells.length; i++) {
                    Object v = r.get(cols.get(i));
                    cells[i] = v == null ? "" : String.valueOf(v);
                }
                csv.rowText(cells);
            }
        }
    }

    /**
     * Where the error sits: per upper node of the family's finest model, its rest position (mm), its
     * displacement's magnitude (mm) and, per coarser model with triangles, the magnitude of the difference
     * {@link FieldTransfer#differences} sums (mm).
     */
    static void nodesCsv(Path file, List<ResolutionStudy.Run> family, Transfers transfers) throws IOException {
        ResolutionStudy.Run fine = family.get(family.size() - 1);
        List<String> cols = new ArrayList<>(List.of("x_mm", "y_mm", "z_mm", "displacement_mm"));
        List<double[]> diffs = new ArrayList<>();
        for (ResolutionStudy.Run c : family.subList(0, family.size() - 1)) {
            if (c.upperTriangles() != null) {
                cols.add("difference_mm " + c.label());
                diffs.add(transfers.differences(fine, c));
            }
        }
        try (CsvWriter csv = new CsvWriter(file, cols, 1000)) {
            double[] row = new double[cols.size()];
            for (int i = 0; i < fine.upper().length; i++) {
                if (!fine.upper()[i]) {
                    continue;
                }
                double u = 0;
                for (int a = 0; a < 3; a++) {
                    row[a] = 1e3 * fine.rest()[3 * i + a];
                    u += sq(fine.end()[3 * i + a] - fine.rest()[3 * i + a]);
                }
                row[3] = 1e3 * Math.sqrt(u);
                for (int k = 0; k < diffs.size(); k++) {
                    double[] d = diffs.get(k);
                    row[4 + k] = 1e3 * Math.sqrt(sq(d[3 * i]) + sq(d[3 * i + 1]) + sq(d[3 * i + 2]));
                }
                csv.row(row);
            }
        }
    }

    private static double sq(double x) {
        return x * x;
    }

    /** Error against element size, log-log, one series per family, with the tolerance. */
    static void chart(Path png, List<Map<String, Object>> rows, double tolerance) throws IOException {
        XYChart c = Charts.lineChart("Resolution study: error against the finest model of each family",
                "mean edge length, mm", "relative RMS displacement error at end-inspiration", 900, 600);
        c.getStyler().setXAxisLogarithmic(true);
        c.getStyler().setYAxisLogarithmic(true);
        // About a decade of element sizes and errors: label 1-9 times each power of ten, not the decades alone
        // (one labelled tick per axis otherwise).
        c.getStyler().setXAxisLogarithmicDecadeOnly(false);
        c.getStyler().setYAxisLogarithmicDecadeOnly(false);
        List<String> families = new ArrayList<>();
        for (Map<String, Object> r : rows) {
            if (!families.contains((String) r.get("family"))) {
                families.add((String) r.get("family"));
            }
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = 0;
        for (String fam : families) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (Map<String, Object> r : rows) {
                if (r.get("family").equals(fam) && (double) r.get("relative_rms_error") > 0) {
                    x.add((double) r.get("element_mm"));
                    y.add((double) r.get("relative_rms_error"));
                    lo = Math.min(lo, x.get(x.size() - 1));
                    hi = Math.max(hi, x.get(x.size() - 1));
                }
            }
            if (!x.isEmpty()) {
                XYSeries s = c.addSeries(fam, x, y);
                s.setMarker(SeriesMarkers.CIRCLE);
            }
        }
        if (hi > 0) {
            Charts.addLine(c, "tolerance " + tolerance, new double[] {lo, hi}, new double[] {tolerance, tolerance});
        }
        c.getStyler().setMarkerSize(7);
        Charts.savePng(c, png);
    }
}
