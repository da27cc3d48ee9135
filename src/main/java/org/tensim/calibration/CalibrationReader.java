package org.tensim.calibration;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.sweep.Measure;
import org.tensim.sweep.RunSetup;
import org.tensim.sweep.SceneRun;
import org.tensim.sweep.SpecReader;
import org.tensim.sweep.SpecReader.SpecException;
import org.tensim.scene.tunable.TunableParameter;

/**
 * Reads and validates a calibration spec ({@link CalibrationSpec} shows the format). As for
 * sweeps, everything is checked before any run: unknown or fixed-and-fitted parameters,
 * empty bounds or bounds outside the parameter's range, a start outside the bounds,
 * non-finite numbers, target files that do not parse (naming the file and line), target
 * times outside the run.
 */
public final class CalibrationReader {
    private final SpecReader r;

    private CalibrationReader(Path file) {
        r = new SpecReader(file);
    }

    /** Reads a calibration spec. */
    public static CalibrationSpec read(Path file) throws SpecException {
        CalibrationReader c = new CalibrationReader(file);
        return c.spec(c.r.root(file));
    }

    /** Only the scene, mesh, solver and fixed values of a calibration spec (its targets may not exist yet). */
    public static RunSetup readSetup(Path file) throws SpecException {
        CalibrationReader c = new CalibrationReader(file);
        return c.r.setup(c.r.root(file));
    }

    private CalibrationSpec spec(JsonNode root) throws SpecException {
        r.allowOnly(root, "", Set.of("scene", "overrides", "mesh", "boxes", "muscleLoad", "diaphragm", "fixed", "solver",
                "fit", "optimizer",
                "targets"));
        RunSetup setup = r.setup(root);
        JsonNode fit = root.get("fit");
        if (fit == null || !fit.isObject() || fit.size() == 0) {
            throw r.fail("fit", fit, "an object of fitted parameters {\"NAME\": {\"min\": .., \"max\": .., \"start\": ..}}");
        }
        List<CalibrationSpec.Free> free = new ArrayList<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = fit.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            String f = "fit." + e.getKey();
            TunableParameter p = r.parameter(setup.scene(), f, e.getKey());
            if (setup.fixed().containsKey(e.getKey())) {
                throw r.fail(f, null, "either fitted or fixed, not both");
            }
            if (!e.getValue().isObject()) {
                throw r.fail(f, e.getValue(), "an object {\"min\": .., \"max\": .., \"start\": ..}");
            }
            r.allowOnly(e.getValue(), f + ".", Set.of("min", "max", "start"));
            double min = r.number(e.getValue(), f + ".min", Double.NaN);
            double max = r.number(e.getValue(), f + ".max", Double.NaN);
            r.inRange(p, f + ".min", min);
            r.inRange(p, f + ".max", max);
            if (!(min < max)) {
                throw r.fail(f, e.getValue(), "a non-empty range: min (" + min + ") below max (" + max + ")");
            }
            double start = r.number(e.getValue(), f + ".start", 0.5 * (min + max));
            if (!(start >= min && start <= max)) {
                throw r.fail(f + ".start", e.getValue().get("start"), "within [" + min + ", " + max + "]");
            }
            free.add(new CalibrationSpec.Free(e.getKey(), min, max, start, p.min(), p.max()));
        }
        CalibrationSpec.Optimizer o = optimizer(root.get("optimizer"), free.size());
        JsonNode t = root.get("targets");
        if (t == null || !t.isArray() || t.size() == 0) {
            throw r.fail("targets", t, "a non-empty array of targets (type summary, landmarks or surface)");
        }
        List<Target> targets = new ArrayList<>();
        List<Measure> measures = new ArrayList<>();
        for (int i = 0; i < t.size(); i++) {
            Target target = target(t.get(i), "targets[" + i + "]", "t" + i + "_", setup);
            targets.add(target);
            if (target.measure() != null) {
                measures.add(target.measure());
            }
        }
        return new CalibrationSpec(setup.withMeasures(measures), free, o, targets);
    }

    private CalibrationSpec.Optimizer optimizer(JsonNode o, int dims) throws SpecException {
        int lambda = 4 + (int) Math.floor(3 * Math.log(dims));
        if (o == null) {
            return new CalibrationSpec.Optimizer(lambda, 40, 0.3, 1, 0, 1e-4);
        }
        r.allowOnly(o, "optimizer.", Set.of("population", "generations", "sigma", "seed", "stopFitness", "tolerance"));
        double pop = r.number(o, "optimizer.population", lambda);
        double gen = r.number(o, "optimizer.generations", 40);
        if (pop != Math.rint(pop) || pop < 2 || pop > 10_000) {
            throw r.fail("optimizer.population", o.get("population"), "a whole number of candidates from 2 to 10000");
        }
        if (gen != Math.rint(gen) || gen < 1 || gen > 100_000) {
            throw r.fail("optimizer.generations", o.get("generations"), "a whole number from 1 to 100000");
        }
        double sigma = r.number(o, "optimizer.sigma", 0.3);
        if (!(sigma > 0 && sigma <= 1)) {
            throw r.fail("optimizer.sigma", o.get("sigma"), "a fraction of the ranges in (0, 1]");
        }
        JsonNode seed = o.get("seed");
        if (seed != null && !seed.isIntegralNumber()) {
            throw r.fail("optimizer.seed", seed, "a whole number");
        }
        double stop = r.number(o, "optimizer.stopFitness", 0);
        double tol = r.number(o, "optimizer.tolerance", 1e-4);
        r.positive("optimizer.tolerance", tol);
        return new CalibrationSpec.Optimizer((int) pop, (int) gen, sigma, seed == null ? 1 : seed.asLong(), stop, tol);
    }

    private Target target(JsonNode t, String f, String prefix, RunSetup setup) throws SpecException {
        if (!t.isObject()) {
            throw r.fail(f, t, "an object with a type: summary, landmarks or surface");
        }
        String type = r.text(t, "type", null);
        double weight = r.number(t, f + ".weight", 1);
        r.positive(f + ".weight", weight);
        switch (type) {
            case "summary" -> {
                r.allowOnly(t, f + ".", Set.of("type", "field", "value", "tolerance", "weight"));
                String field = r.text(t, "field", null);
                if (!SceneRun.knownFields(setup.scene()).contains(field)) {
                    throw r.fail(f + ".field", t.get("field"), "a summary field of scene '" + setup.scene() + "', one of "
                            + SceneRun.knownFields(setup.scene()));
                }
                double value = r.number(t, f + ".value", Double.NaN);
                double tol = r.number(t, f + ".tolerance", Double.NaN);
                r.positive(f + ".tolerance", tol);
                return new SummaryTarget(field, value, tol, weight);
            }
            case "surface" -> {
                r.allowOnly(t, f + ".", Set.of("type", "file", "units", "timeS", "toleranceMm", "weight"));
                diaphragmOnly(setup, f);
                Path file = r.existing(f + ".file", r.text(t, "file", null));
                MeshUnits units = units(t, f);
                double time = r.number(t, f + ".timeS", Double.NaN);
                if (!(time > 0 && time <= setup.seconds())) {
                    throw r.fail(f + ".timeS", t.get("timeS"), "a time within the run (0, " + setup.seconds() + "] s");
                }
                double tol = r.number(t, f + ".toleranceMm", 1);
                r.positive(f + ".toleranceMm", tol);
                TriangleMesh m;
                try {
                    m = MeshLoader.load(file, units).mesh();
                } catch (MeshFormatException | IOException | RuntimeException e) {
                    throw r.fail(f + ".file", t.get("file"), "a mesh file that parses (OBJ, STL or OFF); " + e.getMessage());
                }
                return new SurfaceTarget(file.getFileName().toString(), m.coordinates(), m.triangles(), time, tol,
                        weight, prefix + "surface_");
            }
            case "landmarks" -> {
                r.allowOnly(t, f + ".", Set.of("type", "file", "units", "toleranceMm", "weight"));
                diaphragmOnly(setup, f);
                Path file = r.existing(f + ".file", r.text(t, "file", null));
                double scale = units(t, f) == MeshUnits.MM ? 1e-3 : 1;
                double tol = r.number(t, f + ".toleranceMm", 1);
                r.positive(f + ".toleranceMm", tol);
                return landmarks(file, scale, setup.seconds(), tol, weight, prefix + "landmarks_");
            }
            default -> throw r.fail(f + ".type", t.get("type"), "summary, landmarks or surface");
        }
    }

    private void diaphragmOnly(RunSetup setup, String f) throws SpecException {
        if (!setup.scene().equals("diaphragm")) {
            throw r.fail(f + ".type", null, "summary: surface and landmark targets need the diaphragm scene");
        }
    }

    private MeshUnits units(JsonNode t, String f) throws SpecException {
        String u = r.text(t, "units", "mm");
        try {
            return MeshUnits.parse(u);
        } catch (IllegalArgumentException e) {
            throw r.fail(f + ".units", t.get("units"), "\"mm\" or \"m\"");
        }
    }

    /** Reads id,t,x,y,z rows (header required), refusing a bad row by file and line. */
    static LandmarkTarget landmarks(Path file, double scale, double seconds, double tol, double weight,
            String prefix) throws SpecException {
        List<String[]> rows = new ArrayList<>();
        try (MappingIterator<String[]> it = new CsvMapper().readerFor(String[].class)
                .with(CsvParser.Feature.WRAP_AS_ARRAY).with(CsvParser.Feature.TRIM_SPACES).readValues(file.toFile())) {
            while (it.hasNext()) {
                rows.add(it.next());
            }
        } catch (IOException | RuntimeException e) {
            throw new SpecException(file + " does not parse as CSV: " + e.getMessage());
        }
        if (rows.isEmpty() || !String.join(",", rows.get(0)).equals("id,t,x,y,z")) {
            throw new SpecException(file + " line 1: expected the header id,t,x,y,z, got "
                    + (rows.isEmpty() ? "an empty file" : String.join(",", rows.get(0))));
        }
        int n = rows.size() - 1;
        if (n == 0) {
            throw new SpecException(file + ": no landmark rows after the header");
        }
        String[] ids = new String[n];
        double[] times = new double[n];
        double[] xyz = new double[3 * n];
        for (int k = 0; k < n; k++) {
            String[] c = rows.get(k + 1);
            String where = file + " line " + (k + 2);
            if (c.length != 5) {
                throw new SpecException(where + ": expected 5 cells id,t,x,y,z, got " + c.length);
            }
            ids[k] = c[0];
            try {
                times[k] = Double.parseDouble(c[1]);
                for (int a = 0; a < 3; a++) {
                    xyz[3 * k + a] = scale * Double.parseDouble(c[2 + a]);
                }
            } catch (NumberFormatException e) {
                throw new SpecException(where + ": t, x, y, z must be numbers (" + e.getMessage() + ")");
            }
            for (double v : new double[] {times[k], xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]}) {
                if (!Double.isFinite(v)) {
                    throw new SpecException(where + ": non-finite value");
                }
            }
            if (times[k] < 0 || times[k] > seconds) {
                throw new SpecException(where + ": t = " + times[k] + " s is outside the run [0, " + seconds + "] s");
            }
        }
        return new LandmarkTarget(file.getFileName().toString(), ids, times, xyz, tol, weight, prefix);
    }
}
