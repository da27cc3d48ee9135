package org.tensim.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.analysis.SceneRefinement;
import org.tensim.analysis.VolumeStudy;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;

/**
 * {@code tensim volume-study --scene FILE}: the scene file's volume body run at its own cell and finer
 * ({@link SceneRefinement}), its load's displacement against the known answer, the measured orders, and for a
 * compressed or pulled body the lateral strains against the file's nu; volume-scene.csv and the JSON line.
 */
final class VolumeSceneStudy {
    /** The file this study writes into --out. */
    static final String CSV = "volume-scene.csv";

    private VolumeSceneStudy() {
    }

    static void run(RunFolder run, Path file, String body, List<Integer> factors, List<String> sets)
            throws IOException {
        SceneRefinement.Result r = SceneRefinement.run(file, body, factors, sets);
        SceneRefinement.Answer a = r.answer();
        List<String> header = new ArrayList<>(List.of("factor", "cell_m", "nodes", "loaded_nodes", "load_n",
                "displacement_m", "known_answer_m", "error", "last_sixth_range_m", "statics_m", "statics_error"));
        List<String> lateral = a == null ? List.of() : new ArrayList<>(a.lateral().keySet());
        for (String p : lateral) {
            header.add(p + "_lateral_strain");
            header.add(p + "_measured_poisson");
        }
        List<Double> errors = new ArrayList<>();
        List<Double> displacements = new ArrayList<>();
        List<Double> spreads = new ArrayList<>();
        List<Double> staticErrors = new ArrayList<>();
        Map<String, List<Double>> nus = new LinkedHashMap<>();
        double total = r.loads().isEmpty() ? Double.NaN : r.loads().get(0).totalN();
        System.out.printf("%s, body %s: %s; load %.6g N (kept at every resolution)%n", file, r.body(),
                a == null ? "no known answer (not a box loaded on a face)" : a.kind() + ", known answer "
                        + String.format("%.6g m", a.displacementM()), total);
        try (CsvWriter csv = run.csv(CSV, header, 1)) {
            for (int i = 0; i < r.levels().size(); i++) {
                SceneRefinement.Level l = r.levels().get(i);
                double u = l.conjugateM().length == 0 ? Double.NaN : l.conjugateM()[0];
                double err = a == null ? Double.NaN : r.error(i);
                List<String> row = new ArrayList<>(List.of(Integer.toString(l.factor()), Double.toString(l.cellM()),
                        Integer.toString(l.nodes()), l.loadedNodes().length == 0 ? "" : Integer.toString(
                                l.loadedNodes()[0]), Double.toString(total), Double.toString(u),
                        Double.toString(a == null ? Double.NaN : a.displacementM()), Double.toString(err),
                        Double.toString(l.spreadM()), Double.toString(l.staticM()),
                        Double.toString(a == null ? Double.NaN : r.staticError(i))));
                StringBuilder text = new StringBuilder(String.format("cell %.4g mm (%d nodes, %d loaded): %.6g m"
                        + " along the load", l.cellM() * 1e3, l.nodes(), l.loadedNodes().length == 0 ? 0
                        : l.loadedNodes()[0], u));
                if (a != null) {
                    text.append(String.format(" (%+.2f %% against %.6g m)", 100 * err, a.displacementM()));
                }
                text.append(String.format(", ranging over %.2f %% of it in the run's last sixth; linear statics"
                        + " %.6g m", 100 * l.spreadM() / Math.abs(u), l.staticM()));
                if (a != null) {
                    text.append(String.format(" (%+.2f %%)", 100 * r.staticError(i)));
                    staticErrors.add(r.staticError(i));
                }
                for (String p : lateral) {
                    int axis = a.lateral().get(p);
                    double strain = l.probesM().get(p)[axis] / a.extentsM()[axis];
                    double axial = -u / a.extentsM()[a.face()];
                    double nu = -strain / axial;
                    nus.computeIfAbsent(p, k -> new ArrayList<>()).add(nu);
                    row.add(Double.toString(strain));
                    row.add(Double.toString(nu));
                    text.append(String.format("; %s lateral strain %.4g, -lateral/axial %.4f", p, strain, nu));
                }
                csv.rowText(row.toArray(new String[0]));
                System.out.println(text);
                errors.add(err);
                displacements.add(u);
                spreads.add(l.spreadM());
            }
        }
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("scene", file.toString());
        json.put("body", r.body());
        json.put("kind", a == null ? "none" : a.kind());
        json.put("load_n", total);
        json.put("factors", factors);
        json.put("displacement_m", displacements);
        json.put("last_sixth_range_m", spreads);
        if (a != null) {
            json.put("known_answer_m", a.displacementM());
            json.put("error", errors);
            json.put("finest_error", errors.get(errors.size() - 1));
            List<Double> order = new ArrayList<>();
            for (int i = 1; i < errors.size(); i++) {
                order.add(VolumeStudy.orderAgainst(errors.get(i - 1), errors.get(i), 1.0 / factors.get(i - 1),
                        1.0 / factors.get(i)));
            }
            json.put("order", order);
            json.put("statics_error", staticErrors);
            List<Double> staticOrder = new ArrayList<>();
            for (int i = 1; i < staticErrors.size(); i++) {
                staticOrder.add(VolumeStudy.orderAgainst(staticErrors.get(i - 1), staticErrors.get(i),
                        1.0 / factors.get(i - 1), 1.0 / factors.get(i)));
            }
            json.put("statics_order", staticOrder);
            if (!nus.isEmpty()) {
                json.put("measured_poisson", nus);
            }
        }
        List<Double> observed = new ArrayList<>();
        for (int i = 2; i < factors.size(); i++) {
            double ratio = (double) factors.get(i) / factors.get(i - 1);
            if (Math.abs((double) factors.get(i - 1) / factors.get(i - 2) - ratio) < 1e-9 * ratio) {
                observed.add(VolumeStudy.observedOrder(displacements.get(i - 2), displacements.get(i - 1),
                        displacements.get(i), ratio));
            }
        }
        json.put("observed_order", observed);
        System.out.println("order against the known answer " + json.get("order") + " (linear statics: "
                + json.get("statics_order") + "), observed order " + observed);
        run.finish(RunStatus.OK, json);
        System.out.println(Json.line(json));
    }
}
