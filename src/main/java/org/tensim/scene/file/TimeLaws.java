package org.tensim.scene.file;

import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvParser;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.conditions.BreathingLaw;
import org.tensim.scene.conditions.TimeLaw;

/**
 * Reads a scene's {@code laws:} block: named {@link TimeLaw}s.
 * <pre>
 * laws:
 *   wave:  {type: sine, amplitude: 1, frequency: 0.25 Hz, phase: 0 rad}
 *   start: {type: ramp, start: 0 s, duration: 1 s, from: 0, to: 1}
 *   steps: {type: table, points: [[0 s, 0], [1 s, 1], [2 s, 0.5]], extend: constant}
 *   trace: {type: csv, file: breath.csv, extend: extrapolate}
 *   breath: {type: breathing, period: 4 s, inspiration: 0.333, pause: 0.25, amplitude: 1}
 * </pre>
 * A breathing law is the diaphragm's cycle ({@link BreathingLaw}): inspiration (a share of the period, 1/3 by
 * default: I:E = 1:2) then expiration, each a half cosine, from 0 to the amplitude (1) and back, the expiration
 * ending in a pause at 0 ({@code pause}, a share of the expiration, {@code BreathingCycle.QUIET_PAUSE_SHARE} by
 * default).
 * A csv file has a header line, then one {@code time,value} row a line (times in the file's time unit, or with
 * units); times must increase, in tables and files alike.
 */
public final class TimeLaws {
    /** The law types. */
    public static final List<String> TYPES = List.of("sine", "ramp", "table", "csv", "breathing");
    /** The keys of each type (each also takes {@code type}). */
    public static final Map<String, List<String>> KEYS = Map.of(
            "sine", List.of("type", "amplitude", "frequency", "phase"),
            "ramp", List.of("type", "start", "duration", "from", "to"),
            "table", List.of("type", "points", "extend"),
            "csv", List.of("type", "file", "extend"),
            "breathing", List.of("type", "period", "inspiration", "pause", "amplitude"));
    /** A breathing law's default period, s: 15 breaths a minute ({@code BreathingCycle.quiet()}). */
    static final double DEFAULT_PERIOD_S = 4;
    private static final List<String> EXTENSIONS = List.of("constant", "extrapolate");

    private TimeLaws() {
    }

    /** The laws by name, in file order; an absent block is none. */
    public static Map<String, TimeLaw> read(SceneNode block, SceneUnits u, Path folder) {
        Map<String, TimeLaw> laws = new LinkedHashMap<>();
        if (block == null) {
            return laws;
        }
        if (!block.isMap()) {
            throw SceneException.at(block, "expected a map of named laws, got " + block.describe());
        }
        for (Map.Entry<String, SceneNode> e : block.entries().entrySet()) {
            laws.put(e.getKey(), law(e.getValue(), u, folder));
        }
        return laws;
    }

    static TimeLaw law(SceneNode node, SceneUnits u, Path folder) {
        if (!node.isMap()) {
            throw SceneException.at(node, "expected a law {type: sine|ramp|table|csv|breathing, ...}, got "
                    + node.describe());
        }
        String type = typeOf(node, TYPES);
        MapReader r = new MapReader(node, KEYS.get(type));
        switch (type) {
            case "sine":
                return TimeLaw.sine(r.quantity("amplitude", QuantityKind.NUMBER, u, 1),
                        r.nonNegative("frequency", QuantityKind.FREQUENCY, u, Double.NaN),
                        r.quantity("phase", QuantityKind.ANGLE, u, 0));
            case "ramp":
                return TimeLaw.ramp(r.quantity("start", QuantityKind.TIME, u, 0),
                        r.positive("duration", QuantityKind.TIME, u, Double.NaN),
                        r.quantity("from", QuantityKind.NUMBER, u, 0), r.quantity("to", QuantityKind.NUMBER, u, 1));
            case "table":
                return table(r.list("points"), extension(r), u);
            case "breathing":
                return breathing(r, u);
            default:
                return csv(r.scalar("file"), BodyContext.file(r.scalar("file"), folder), extension(r), u);
        }
    }

    /** The {@code type:} of a map that must have one of {@code types}. */
    static String typeOf(SceneNode node, List<String> types) {
        SceneNode t = node.get("type");
        if (t == null || !t.isScalar()) {
            throw SceneException.at(t == null ? node : t, (t == null ? "missing required key 'type'" : "expected a"
                    + " type name, got " + t.describe()) + " (one of " + String.join(", ", types) + ")");
        }
        if (!types.contains(t.text())) {
            throw SceneException.at(t, t.describe() + " is not one of " + String.join(", ", types)
                    + DidYouMean.suggest(t.text(), types));
        }
        return t.text();
    }

    private static TimeLaw breathing(MapReader r, SceneUnits u) {
        double period = r.positive("period", QuantityKind.TIME, u, DEFAULT_PERIOD_S);
        double share = r.quantity("inspiration", QuantityKind.NUMBER, u, 1.0 / 3);
        double pause = r.quantity("pause", QuantityKind.NUMBER, u,
                org.tensim.scene.diaphragm.BreathingCycle.QUIET_PAUSE_SHARE);
        double amplitude = r.quantity("amplitude", QuantityKind.NUMBER, u, 1);
        try {
            return new BreathingLaw(period, share, pause, amplitude);
        } catch (IllegalArgumentException e) {
            String at = e.getMessage().contains("pause") ? "pause" : "inspiration";
            throw SceneException.at(r.has(at) ? r.node().get(at) : r.node(), e.getMessage());
        }
    }

    private static TimeLaw.Extension extension(MapReader r) {
        return r.choice("extend", EXTENSIONS, "constant").equals("constant") ? TimeLaw.Extension.CONSTANT
                : TimeLaw.Extension.EXTRAPOLATE;
    }

    private static TimeLaw table(SceneNode points, TimeLaw.Extension ext, SceneUnits u) {
        int n = points.items().size();
        if (n == 0) {
            throw SceneException.at(points, "expected at least one point [time, value]");
        }
        double[] ts = new double[n];
        double[] vs = new double[n];
        for (int i = 0; i < n; i++) {
            SceneNode p = points.items().get(i);
            if (!p.isList() || p.items().size() != 2) {
                throw SceneException.at(p, "expected a point [time, value], got " + p.describe());
            }
            ts[i] = u.si(p.items().get(0), QuantityKind.TIME);
            vs[i] = u.si(p.items().get(1), QuantityKind.NUMBER);
            if (i > 0 && !(ts[i] > ts[i - 1])) {
                throw SceneException.at(p.items().get(0), "the table's times must increase: "
                        + p.items().get(0).describe() + " is not after the time of point " + (i - 1) + " ("
                        + points.items().get(i - 1).items().get(0).describe() + ")");
            }
        }
        return TimeLaw.table(ts, vs, ext);
    }

    private static TimeLaw csv(SceneNode at, Path file, TimeLaw.Extension ext, SceneUnits u) {
        CsvMapper m = new CsvMapper();
        m.enable(CsvParser.Feature.WRAP_AS_ARRAY);
        m.enable(CsvParser.Feature.SKIP_EMPTY_LINES);
        List<Double> ts = new ArrayList<>();
        List<Double> vs = new ArrayList<>();
        String name = file.getFileName().toString();
        try (MappingIterator<String[]> it = m.readerFor(String[].class).readValues(file.toFile())) {
            boolean header = true;
            while (it.hasNext()) {
                String[] row = it.next();
                int line = it.getParser().currentTokenLocation().getLineNr();
                if (header) {
                    header = false;
                    continue;
                }
                String where = name + ":" + line + ":1";
                if (row.length != 2) {
                    throw SceneException.at(at, where + ": expected two columns (time, value), got " + row.length);
                }
                SceneNode t = SceneNode.scalar(SceneNode.Token.STRING, row[0], where, at.path() + " (" + name + ")");
                SceneNode v = SceneNode.scalar(SceneNode.Token.STRING, row[1], where, at.path() + " (" + name + ")");
                double ti = u.si(t, QuantityKind.TIME);
                if (!ts.isEmpty() && !(ti > ts.get(ts.size() - 1))) {
                    throw SceneException.at(t, "the times must increase: " + t.describe()
                            + " is not after the row before's " + ts.get(ts.size() - 1) + " s");
                }
                ts.add(ti);
                vs.add(u.si(v, QuantityKind.NUMBER));
            }
        } catch (IOException | RuntimeException e) {
            if (e instanceof SceneException s) {
                throw s;
            }
            throw SceneException.at(at, "cannot read " + file + " as CSV (" + e.getMessage() + ")");
        }
        if (ts.isEmpty()) {
            throw SceneException.at(at, file + " has no row after its header; expected time,value rows");
        }
        return TimeLaw.table(ts.stream().mapToDouble(Double::doubleValue).toArray(),
                vs.stream().mapToDouble(Double::doubleValue).toArray(), ext);
    }
}
