package org.tensim.sweep;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tensim.io.Json;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.TunableScenes;

/**
 * Reads and validates a sweep spec ({@link SweepSpec} shows the format). Everything is
 * checked before any run starts; each refusal is a {@link SpecException} naming the file,
 * the field (e.g. {@code parameters.muscleActionPa.max}), the value and what was expected:
 * unknown fields and parameters, empty ranges, bounds outside a parameter's valid range,
 * non-finite numbers, missing files. Relative paths are relative to the spec's folder.
 */
public final class SpecReader {
    /** A spec that cannot be used; the message names the file and the field. */
    public static final class SpecException extends Exception {
        public SpecException(String message) {
            super(message);
        }
    }

    final String where;
    final Path base;

    /** @param file the spec's path, named in messages; relative paths inside are resolved against its folder */
    public SpecReader(Path file) {
        this.where = file.toString();
        Path parent = file.toAbsolutePath().getParent();
        this.base = parent == null ? Path.of(".") : parent;
    }

    /** Reads a sweep spec. */
    public static SweepSpec readSweep(Path file) throws SpecException {
        SpecReader r = new SpecReader(file);
        return r.sweep(r.root(file));
    }

    /** The file's JSON object. */
    public JsonNode root(Path file) throws SpecException {
        JsonNode root;
        try {
            root = Json.mapper().readTree(Files.readAllBytes(file));
        } catch (NoSuchFileException e) {
            throw new SpecException(where + ": no such file");
        } catch (JsonProcessingException e) {
            JsonLocation loc = e.getLocation();
            throw new SpecException(where + " is not valid JSON" + (loc == null ? "" : " at line " + loc.getLineNr()
                    + ", column " + loc.getColumnNr()) + ": " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new SpecException("cannot read " + where + ": " + e.getMessage());
        }
        if (root == null || !root.isObject()) {
            throw new SpecException(where + ": expected a JSON object { ... } at the top level");
        }
        return root;
    }

    /** A sweep spec from its JSON object. */
    public SweepSpec sweep(JsonNode root) throws SpecException {
        allowOnly(root, "", Set.of("scene", "overrides", "mesh", "boxes", "muscleLoad", "diaphragm", "parameters",
                "sampling", "fixed", "solver", "outputs"));
        RunSetup setup = setup(root);
        SweepSpec.Sampling sampling = sampling(root.get("sampling"));
        JsonNode params = root.get("parameters");
        if (params == null || !params.isObject() || params.size() == 0) {
            throw fail("parameters", params, "an object with at least one parameter: {\"NAME\": {\"min\": .., \"max\": "
                    + ".., \"steps\": ..}}; parameters of scene '" + setup.scene() + "': " + keys(setup.scene()));
        }
        List<SweepSpec.Range> ranges = new ArrayList<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = params.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            if (setup.fixed().containsKey(e.getKey())) {
                throw fail("fixed." + e.getKey(), null, "a parameter either swept or fixed, not both");
            }
            ranges.add(range(setup.scene(), e.getKey(), e.getValue(), sampling));
        }
        List<String> outputs = outputs(root.get("outputs"), SceneRun.knownFields(setup.scene()));
        return new SweepSpec(setup, ranges, sampling, outputs);
    }

    /** The shared part of sweep and calibration specs: scene, mesh, boxes, solver and fixed values. */
    public RunSetup setup(JsonNode root) throws SpecException {
        String scene = text(root, "scene", null);
        org.tensim.scene.file.Scene file = null;
        List<String> overrides = List.of();
        if (SceneFileRun.isFile(scene)) {
            scene = existing("scene", scene).toAbsolutePath().toString();
            overrides = overrides(root.get("overrides"));
            try {
                file = SceneFileRun.load(scene, overrides);
            } catch (org.tensim.scene.file.SceneException e) {
                throw new SpecException(where + ": field 'scene': " + e.getMessage());
            }
        } else if (!TunableScenes.names().contains(scene)) {
            throw fail("scene", root.get("scene"), "one of " + TunableScenes.names() + ", or a scene file (.yaml,"
                    + " .yml, .json; docs/scenes.md)");
        } else if (root.has("overrides")) {
            throw fail("overrides", root.get("overrides"), "left out: overrides change a scene file's values (the"
                    + " built-in scenes take fixed values)");
        }
        List<String> args = SpecDiaphragm.args(this, root, scene);
        JsonNode solver = root.get("solver");
        String integrator = file != null ? file.run().integrator() : "rk2";
        double dt = 0;
        double seconds = file != null ? file.run().durationS() : scene.equals("diaphragm") ? 4
                : org.tensim.scene.CubeParameters.paper().durationS();
        if (solver != null) {
            if (!solver.isObject()) {
                throw fail("solver", solver, "an object {\"integrator\": .., \"dtS\": .., \"seconds\": ..}");
            }
            allowOnly(solver, "solver.", Set.of("integrator", "dtS", "seconds"));
            integrator = text(solver, "integrator", integrator);
            try {
                Integrators.choice(integrator);
            } catch (IllegalArgumentException e) {
                throw fail("solver.integrator", solver.get("integrator"), e.getMessage());
            }
            dt = number(solver, "solver.dtS", 0);
            if (dt < 0) {
                throw fail("solver.dtS", solver.get("dtS"), "a time step >= 0 s (0: the scene's own)");
            }
            seconds = number(solver, "solver.seconds", seconds);
            positive("solver.seconds", seconds);
        }
        Map<String, Double> fixed = new LinkedHashMap<>();
        JsonNode f = root.get("fixed");
        if (f != null) {
            if (!f.isObject()) {
                throw fail("fixed", f, "an object {\"NAME\": value}");
            }
            for (Iterator<Map.Entry<String, JsonNode>> it = f.fields(); it.hasNext();) {
                Map.Entry<String, JsonNode> e = it.next();
                TunableParameter p = parameter(scene, "fixed." + e.getKey(), e.getKey());
                double v = number(f, "fixed." + e.getKey(), Double.NaN);
                inRange(p, "fixed." + e.getKey(), v);
                fixed.put(e.getKey(), v);
            }
        }
        return new RunSetup(scene, args, integrator, dt, seconds, fixed, List.of(), overrides);
    }

    /**
     * A scene file's {@code overrides}: {"NAME or key.path": value}, a number (in a named parameter's unit, or the
     * file's) or a string with its unit ("8 kPa"), as {@code --set} options in order.
     */
    private List<String> overrides(JsonNode o) throws SpecException {
        List<String> out = new ArrayList<>();
        if (o == null) {
            return out;
        }
        if (!o.isObject()) {
            throw fail("overrides", o, "an object {\"NAME or key.path\": value}, e.g. {\"E\": 8, \"run.dt\": \"5 ms\"}");
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = o.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            JsonNode v = e.getValue();
            if (!v.isNumber() && !v.isTextual()) {
                throw fail("overrides." + e.getKey(), v, "a number or a value with its unit (\"8 kPa\")");
            }
            out.add(e.getKey() + "=" + v.asText());
        }
        return out;
    }

    private SweepSpec.Sampling sampling(JsonNode s) throws SpecException {
        if (s == null) {
            return SweepSpec.Sampling.grid();
        }
        if (!s.isObject()) {
            throw fail("sampling", s, "{\"method\": \"grid\"} or {\"method\": \"lhs\", \"points\": N, \"seed\": S}");
        }
        allowOnly(s, "sampling.", Set.of("method", "points", "seed"));
        String method = text(s, "method", "grid");
        if (method.equals("grid")) {
            if (s.has("points")) {
                throw fail("sampling.points", s.get("points"), "no points for a grid (each range gives its steps)");
            }
            return SweepSpec.Sampling.grid();
        }
        if (!method.equals("lhs")) {
            throw fail("sampling.method", s.get("method"), "\"grid\" or \"lhs\" (Latin hypercube)");
        }
        JsonNode n = s.get("points");
        if (n == null || !n.isIntegralNumber() || n.asLong() < 1 || n.asLong() > 1_000_000) {
            throw fail("sampling.points", n, "a whole number of points from 1 to 1000000");
        }
        JsonNode seed = s.get("seed");
        if (seed != null && !seed.isIntegralNumber()) {
            throw fail("sampling.seed", seed, "a whole number");
        }
        return new SweepSpec.Sampling(true, n.asInt(), seed == null ? 1 : seed.asLong());
    }

    private SweepSpec.Range range(String scene, String name, JsonNode r, SweepSpec.Sampling sampling)
            throws SpecException {
        String field = "parameters." + name;
        TunableParameter p = parameter(scene, field, name);
        if (!r.isObject()) {
            throw fail(field, r, "an object {\"min\": .., \"max\": .., \"steps\": ..} or {\"values\": [..]}");
        }
        allowOnly(r, field + ".", Set.of("min", "max", "steps", "values"));
        if (r.has("values")) {
            if (sampling.latinHypercube()) {
                throw fail(field + ".values", r.get("values"), "min and max: a Latin hypercube samples intervals");
            }
            if (r.has("min") || r.has("max") || r.has("steps")) {
                throw fail(field, r, "either values or min/max/steps, not both");
            }
            JsonNode a = r.get("values");
            if (!a.isArray() || a.size() == 0) {
                throw fail(field + ".values", a, "a non-empty array of numbers (an empty range has no points)");
            }
            double[] v = new double[a.size()];
            for (int i = 0; i < v.length; i++) {
                String fi = field + ".values[" + i + "]";
                if (!a.get(i).isNumber()) {
                    throw fail(fi, a.get(i), "a number");
                }
                v[i] = a.get(i).asDouble();
                inRange(p, fi, v[i]);
            }
            return new SweepSpec.Range(name, Double.NaN, Double.NaN, v.length, v);
        }
        double min = number(r, field + ".min", Double.NaN);
        double max = number(r, field + ".max", Double.NaN);
        inRange(p, field + ".min", min);
        inRange(p, field + ".max", max);
        if (!(min < max) && !(min == max && !sampling.latinHypercube())) {
            throw fail(field, r, "a non-empty range: min (" + min + ") must be below max (" + max + ")");
        }
        int steps = 1;
        if (!sampling.latinHypercube()) {
            JsonNode s = r.get("steps");
            if (s == null || !s.isIntegralNumber() || s.asLong() < 1 || s.asLong() > 100_000) {
                throw fail(field + ".steps", s, "a whole number of grid values from 1 to 100000");
            }
            steps = s.asInt();
            if (min == max && steps > 1) {
                throw fail(field + ".steps", s, "1 when min equals max (the other values would repeat it)");
            }
        } else if (r.has("steps")) {
            throw fail(field + ".steps", r.get("steps"), "no steps with a Latin hypercube (sampling.points sets them)");
        }
        return new SweepSpec.Range(name, min, max, steps, null);
    }

    /** The outputs list: names among {@code known}. */
    public List<String> outputs(JsonNode o, List<String> known) throws SpecException {
        if (o == null || !o.isArray() || o.size() == 0) {
            throw fail("outputs", o, "a non-empty array of summary fields, from " + known);
        }
        List<String> out = new ArrayList<>();
        for (int i = 0; i < o.size(); i++) {
            String name = o.get(i).asText();
            if (!o.get(i).isTextual() || !known.contains(name)) {
                throw fail("outputs[" + i + "]", o.get(i), "a summary field, one of " + known);
            }
            out.add(name);
        }
        return out;
    }

    /** The scene's parameter of that name, or a refusal naming the field and the known names. */
    public TunableParameter parameter(String scene, String field, String name) throws SpecException {
        try {
            return SceneRun.parameter(scene, name);
        } catch (IllegalArgumentException e) {
            throw new SpecException(where + ": field '" + field + "': " + e.getMessage());
        }
    }

    /** Refuses a value outside the parameter's valid range (or non-finite), naming the field. */
    public void inRange(TunableParameter p, String field, double v) throws SpecException {
        try {
            p.validate(v, null);
        } catch (IllegalArgumentException e) {
            throw new SpecException(where + ": field '" + field + "': " + e.getMessage());
        }
    }

    /** A finite number field, or {@code fallback} when absent (NaN: required). */
    public double number(JsonNode obj, String field, double fallback) throws SpecException {
        JsonNode n = obj.get(field.substring(field.lastIndexOf('.') + 1));
        if (n == null) {
            if (Double.isNaN(fallback)) {
                throw fail(field, null, "a number (required)");
            }
            return fallback;
        }
        if (!n.isNumber()) {
            throw fail(field, n, "a number");
        }
        double v = n.asDouble();
        if (!Double.isFinite(v)) {
            throw fail(field, n, "a finite number");
        }
        return v;
    }

    /** A text field, or {@code fallback} when absent (null: required). */
    public String text(JsonNode obj, String name, String fallback) throws SpecException {
        JsonNode n = obj.get(name);
        if (n == null) {
            if (fallback == null) {
                throw fail(name, null, "a string (required)");
            }
            return fallback;
        }
        if (!n.isTextual()) {
            throw fail(name, n, "a string");
        }
        return n.asText();
    }

    /** A path relative to the spec's folder that must be an existing file. */
    public Path existing(String field, String path) throws SpecException {
        Path p = base.resolve(path).normalize();
        if (!Files.isRegularFile(p)) {
            throw new SpecException(where + ": field '" + field + "': no such file " + p);
        }
        return p;
    }

    public void positive(String field, double v) throws SpecException {
        if (!(v > 0)) { // also NaN
            throw new SpecException(where + ": field '" + field + "' must be > 0, got " + v);
        }
    }

    /** Refuses fields of {@code obj} that are not in {@code allowed}. */
    public void allowOnly(JsonNode obj, String prefix, Set<String> allowed) throws SpecException {
        for (Iterator<String> it = obj.fieldNames(); it.hasNext();) {
            String f = it.next();
            if (!allowed.contains(f)) {
                throw new SpecException(where + ": unknown field '" + prefix + f + "'; expected one of "
                        + new java.util.TreeSet<>(allowed));
            }
        }
    }

    /** A refusal naming the field, the value found and what was expected. */
    public SpecException fail(String field, JsonNode found, String expected) {
        return new SpecException(where + ": field '" + field + "' must be " + expected + (found == null
                ? " (missing)" : ", got " + found));
    }

    private static List<String> keys(String scene) {
        return SceneRun.parameters(scene).stream().map(TunableParameter::key).toList();
    }
}
