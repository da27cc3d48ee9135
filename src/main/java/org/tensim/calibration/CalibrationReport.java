package org.tensim.calibration;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.PresetScene;
import org.tensim.tuning.Settings;
import org.tensim.tuning.Tuning;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BoundaryConditions;

/**
 * Writes what a calibration found: {@code best-preset.json} (a GUI preset with the fitted
 * and fixed values, opened by {@code ./tensim gui --preset}; for a scene file {@code best-set.txt}, the
 * overrides and the values as {@code --set} options, one a line, for {@code tensim run/gui FILE}), {@code history.csv} and
 * {@code convergence.png} (best score per generation), {@code residuals.json} (each target's
 * residuals at the best candidate, whether it is met, and which fitted parameters ended at a bound)
 * and returns the summary.
 *
 * <p>A target is met when every one of its residuals, a measured error over its tolerance, is at
 * most 1 in magnitude. A best value within {@link #AT_BOUND_FRACTION} of its fitted range from a
 * bound is reported under {@code at_bounds}: the optimiser was stopped by the bound, and the
 * targets may want a value beyond it (CMA-ES clips candidates to the bounds, so such a best is
 * usually exactly the bound).
 */
public final class CalibrationReport {
    /** A best value this close to a bound, as a fraction of its fitted range, is reported as at the bound. */
    public static final double AT_BOUND_FRACTION = 1e-3;

    private CalibrationReport() {
    }

    /** Writes the files into {@code out}; returns the summary (also in residuals.json). */
    public static Map<String, Object> write(Path out, CalibrationSpec spec, Calibrator.Outcome o, String engine)
            throws IOException {
        List<String> names = spec.names();
        Calibrator.Evaluation best = o.best();
        Map<String, Double> values = new LinkedHashMap<>(spec.setup().fixed());
        for (int i = 0; i < names.size(); i++) {
            values.put(names.get(i), best.values()[i]);
        }
        if (spec.setup().dtS() > 0) {
            values.put(Tuning.TIME_STEP, spec.setup().dtS());
        }
        // The muscle load goes with the values: it sets what muscleActionPa means.
        BoundaryConditions.MuscleLoad load = spec.setup().muscleLoad();
        // The diaphragm's scene goes with them too: the preset holds the whole scene the values were found on.
        List<String> scene = spec.setup().scene().equals("diaphragm")
                ? PresetScene.withoutMuscleLoad(spec.setup().diaphragm()) : null;
        if (org.tensim.sweep.SceneFileRun.isFile(spec.setup().scene())) {
            // A scene file takes its values as --set options (tensim run/gui FILE --set NAME=VALUE), not a preset.
            List<String> sets = new ArrayList<>(spec.setup().overrides());
            for (Map.Entry<String, Double> e : values.entrySet()) {
                if (!e.getKey().equals(Tuning.TIME_STEP)) {
                    sets.add(e.getKey() + "=" + e.getValue());
                }
            }
            java.nio.file.Files.write(out.resolve("best-set.txt"), sets.stream().map(x -> "--set " + x).toList());
        } else {
            PresetFile.write(out.resolve("best-preset.json"), new Settings(spec.setup().scene(),
                    spec.setup().integrator(), true, values, load, scene));
        }

        List<String> header = new ArrayList<>(List.of("generation", "runs", "best_of_generation", "best_so_far",
                "wall_s"));
        header.addAll(names);
        try (CsvWriter w = new CsvWriter(out.resolve("history.csv"), header, 1)) {
            for (Calibrator.Generation g : o.history()) {
                double[] row = new double[header.size()];
                row[0] = g.generation();
                row[1] = g.evaluations();
                row[2] = g.best();
                row[3] = g.bestSoFar();
                row[4] = g.wallS();
                System.arraycopy(g.values(), 0, row, 5, names.size());
                w.row(row);
            }
        }
        double[] gen = o.history().stream().mapToDouble(Calibrator.Generation::generation).toArray();
        double[] bestSoFar = o.history().stream().mapToDouble(g -> Math.max(g.bestSoFar(), 1e-12)).toArray();
        double[] genBest = o.history().stream().mapToDouble(g -> Math.max(Math.min(g.best(), Calibrator.PENALTY),
                1e-12)).toArray();
        if (gen.length > 0) {
            XYChart c = Charts.lineChart("Calibration: objective (weighted squared residuals) per generation",
                    "generation", "objective", 800, 500);
            c.getStyler().setYAxisLogarithmic(true);
            Charts.addLineWithMarkers(c, "best so far", gen, bestSoFar);
            Charts.addLineWithMarkers(c, "best of the generation", gen, genBest);
            Charts.savePng(c, out.resolve("convergence.png"));
        }

        Map<String, Object> s = new LinkedHashMap<>();
        s.put("scene", spec.setup().geometry());
        s.put("engine", engine);
        s.put("best", valuesMap(names, best.values()));
        s.put("objective", best.fitness());
        s.put("best_status", best.result().status());
        List<Map<String, Object>> targets = new ArrayList<>();
        int metCount = 0;
        for (Target t : spec.targets()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("target", t.describe());
            m.put("weight", t.weight());
            double[] r = t.residuals(best.result());
            Map<String, Object> res = new LinkedHashMap<>();
            double contribution = 0;
            boolean met = r.length > 0;
            for (int i = 0; i < r.length; i++) {
                res.put(t.residualNames().get(i), r[i]);
                contribution += t.weight() * r[i] * r[i];
                met &= Math.abs(r[i]) <= 1; // false for NaN too
            }
            m.put("residuals", res);
            m.put("met", met);
            metCount += met ? 1 : 0;
            Map<String, Object> measured = new LinkedHashMap<>();
            for (String f : t.fields()) {
                measured.put(f, best.result().field(f));
            }
            m.put("measured", measured);
            m.put("contribution", contribution);
            targets.add(m);
        }
        s.put("targets", targets);
        s.put("targets_met", metCount);
        s.put("all_targets_met", metCount == spec.targets().size());
        s.put("at_bounds", atBounds(spec.free(), best.values()));
        s.put("runs", o.evaluations().size());
        s.put("diverged_or_refused", o.evaluations().stream().filter(e -> !e.result().ok()).count());
        s.put("generations", o.history().size());
        s.put("wall_s", Math.round(o.wallS() * 100) / 100.0);
        s.put("load_average", Math.round(java.lang.management.ManagementFactory.getOperatingSystemMXBean()
                .getSystemLoadAverage() * 100) / 100.0);
        Json.write(out.resolve("residuals.json"), s);
        return s;
    }

    /**
     * The fitted parameters whose value lies within {@link #AT_BOUND_FRACTION} of their range from a
     * bound: name to {@code "min"} or {@code "max"}, in the spec's order.
     */
    static Map<String, String> atBounds(List<CalibrationSpec.Free> free, double[] values) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < free.size(); i++) {
            double u = free.get(i).fraction(values[i]);
            if (u <= AT_BOUND_FRACTION) {
                m.put(free.get(i).name(), "min");
            } else if (u >= 1 - AT_BOUND_FRACTION) {
                m.put(free.get(i).name(), "max");
            }
        }
        return m;
    }

    /**
     * What a user should read before using the best parameters, one line each (empty when
     * nothing): fitted values stopped at a bound, and targets not met.
     */
    @SuppressWarnings("unchecked")
    public static List<String> warnings(List<CalibrationSpec.Free> free, Map<String, Object> summary) {
        List<String> out = new ArrayList<>();
        Map<String, Double> best = (Map<String, Double>) summary.get("best");
        Map<String, String> bounds = (Map<String, String>) summary.get("at_bounds");
        for (CalibrationSpec.Free f : free) {
            String side = bounds.get(f.name());
            if (side != null) {
                boolean low = side.equals("min");
                double limit = low ? f.lowest() : f.highest();
                boolean atLimit = low ? f.min() <= limit : f.max() >= limit;
                out.add("best " + f.name() + " = " + best.get(f.name()) + " is at the " + (low ? "lower" : "upper")
                        + " bound of its fitted range [" + f.min() + ", " + f.max() + "]: " + (atLimit
                        ? "the " + (low ? "smallest" : "largest") + " value the parameter takes, so wider bounds"
                                + " cannot help (the targets need other parameters, or another model)"
                        : "the targets may want a value beyond it (widen the range in 'fit." + f.name() + "'"
                                + (Double.isInfinite(limit) ? "" : ", up to " + limit) + ")"));
            }
        }
        for (Map<String, Object> t : (List<Map<String, Object>>) summary.get("targets")) {
            if (!Boolean.TRUE.equals(t.get("met"))) {
                StringBuilder m = new StringBuilder();
                for (Map.Entry<String, Object> e : ((Map<String, Object>) t.get("measured")).entrySet()) {
                    m.append(m.length() == 0 ? "" : ", ").append(e.getKey()).append(" = ").append(e.getValue()
                            instanceof Double d ? String.format(java.util.Locale.ROOT, "%.4g", d) : e.getValue());
                }
                out.add("target not met at the best candidate: " + t.get("target") + "; measured " + m);
            }
        }
        return out;
    }

    private static Map<String, Double> valuesMap(List<String> names, double[] v) {
        Map<String, Double> m = new LinkedHashMap<>();
        for (int i = 0; i < names.size(); i++) {
            m.put(names.get(i), v[i]);
        }
        return m;
    }
}
