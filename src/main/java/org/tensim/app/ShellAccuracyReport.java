package org.tensim.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.tensim.analysis.FlatMeshes;
import org.tensim.analysis.ShellStatics;
import org.tensim.analysis.ShellStudy;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;

/**
 * The static section of {@code tensim accuracy}: runs {@link ShellStudy}, writes
 * {@code shell-MODEL.csv} and {@code shell-MODEL-convergence.png} (relative error against
 * element size, log-log, with the measured orders) and returns its summary for the JSON line.
 */
final class ShellAccuracyReport {
    private ShellAccuracyReport() {
    }

    static Map<String, Object> run(ShellStudy.Result r, org.tensim.io.RunFolder out) throws IOException {
        String model = r.model().name().toLowerCase();
        Path csv = out.dir().resolve("shell-" + model + ".csv");
        try (CsvWriter w = out.csv("shell-" + model + ".csv", List.of(
                "scene", "mesh", "element_size_m", "nodes", "measured",
                "exact", "relative_error", "largest_element_deviation"), 1)) {
            r.patch().forEach((p, cases) -> cases.forEach(c -> row(w, "patch", p.name().toLowerCase(), c)));
            r.plate().forEach(c -> row(w, "plate", "rings", c));
        }
        XYChart chart = Charts.lineChart("Shell statics, " + model + " tissue model: error against element size",
                "element size h (m)", "relative error", 900, 600);
        Charts.logLog(chart);
        add(chart, String.format("plate w0 vs Kirchhoff (order %.2f)", r.plateOrder()), r.plate(), false);
        add(chart, String.format("plate: change to the next mesh (order %.2f)", r.selfOrder()), r.plate(), true);
        for (Map.Entry<FlatMeshes.Pattern, List<ShellStatics.Case>> e : r.patch().entrySet()) {
            add(chart, "patch test, " + e.getKey().name().toLowerCase() + " (order "
                    + String.format("%.2f", ShellStatics.order(e.getValue())) + ")", e.getValue(), false);
        }
        Path png = out.file("shell-" + model + "-convergence.png");
        Charts.savePng(chart, png);
        System.out.println(String.format("shell (%s): plate error against Kirchhoff, measured order %.2f; change "
                + "between successive meshes, measured order %.2f", model, r.plateOrder(), r.selfOrder()));
        System.out.println("wrote " + csv + ", " + png);
        Map<String, Object> json = new LinkedHashMap<>();
        ShellStatics.Case finest = r.plate().get(r.plate().size() - 1);
        json.put("plate_error_finest", round(finest.relativeError()));
        json.put("plate_finest_h_m", finest.elementSizeM());
        json.put("plate_order", round(r.plateOrder()));
        json.put("plate_self_order", round(r.selfOrder()));
        Map<String, Object> patch = new LinkedHashMap<>();
        r.patch().forEach((p, cases) -> patch.put(p.name().toLowerCase(),
                round(cases.stream().mapToDouble(ShellStatics.Case::relativeError).max().orElse(Double.NaN))));
        json.put("patch_worst_error", patch);
        return json;
    }

    private static void row(CsvWriter w, String scene, String mesh, ShellStatics.Case c) {
        try {
            w.rowText(scene, mesh, Double.toString(c.elementSizeM()), Integer.toString(c.nodes()),
                    Double.toString(c.measured()), Double.toString(c.exact()), Double.toString(c.relativeError()),
                    Double.toString(c.spread()));
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static void add(XYChart chart, String label, List<ShellStatics.Case> cases, boolean changes) {
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < cases.size() - (changes ? 1 : 0); i++) {
            ShellStatics.Case c = cases.get(i);
            double e = changes ? Math.abs(c.measured() - cases.get(i + 1).measured()) / c.exact() : c.relativeError();
            if (e > 0) {
                pts.add(new double[] {c.elementSizeM(), e});
            }
        }
        if (!pts.isEmpty()) {
            Charts.addLineWithMarkers(chart, label, pts.stream().mapToDouble(p -> p[0]).toArray(),
                    pts.stream().mapToDouble(p -> p[1]).toArray());
        }
    }

    private static Double round(double v) {
        return Double.isFinite(v) ? Math.round(v * 1e5) / 1e5 : null;
    }
}
