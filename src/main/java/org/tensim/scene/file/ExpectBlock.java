package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.measure.IncommensurableException;
import javax.measure.UnconvertibleException;
import javax.measure.Unit;
import tech.units.indriya.AbstractUnit;

/**
 * Reads a scene's {@code expect:} block, a list of {@link SceneExpectation}s:
 * <pre>
 * expect:
 *   - {column: mss_dy_m, stat: min, value: -8.04 m, tolerance: 1 %}
 *   - {column: ts_dy_m, stat: min, between: [-0.075 m, -0.065 m]}
 *   - {summary: steps, value: 4000, tolerance: 0}
 * </pre>
 * A column must be one the run writes ({@code t_s} or a probe's), a summary key one of
 * {@link SceneExpectation#summaryKeys}; others are refused with a "did you mean". Values are read in the column's
 * dimension (a length for {@code _m}, a time for {@code _s}, a plain number for counts), so a pressure given for a
 * displacement is refused as any value of the wrong dimension is.
 */
final class ExpectBlock {
    /** The keys of one check. */
    static final List<String> KEYS = List.of("column", "summary", "stat", "between", "value", "tolerance");

    private ExpectBlock() {
    }

    /** The checks of the block (none when it is absent). */
    static List<SceneExpectation> read(SceneNode block, Map<String, SceneBody> bodies, List<SceneProbe> probes,
            SceneUnits units) {
        List<SceneExpectation> out = new ArrayList<>();
        if (block == null) {
            return out;
        }
        if (!block.isList() || block.items().isEmpty()) {
            throw SceneException.at(block, "expected a list of checks (at least one), e.g. - {column: p_dy_m, stat:"
                    + " min, between: [-9 m, -7 m]}, got " + block.describe());
        }
        // A standalone body's run (the diaphragm's) writes its own summary, and probe columns only when it has probes.
        boolean standalone = bodies.values().stream().anyMatch(b -> BodyTypes.get(b.type()).standalone());
        List<String> columns = standalone && probes.isEmpty() ? List.of() : SceneExpectation.columns(probes);
        Map<String, String> summary = standalone ? SceneExpectation.summaryKeys(List.of(), columns)
                : SceneExpectation.summaryKeys(bodies.keySet(), columns);
        if (standalone) {
            // Its summary has the columns' ranges, not the generic run's step count and body sizes.
            summary.keySet().removeIf(k -> !k.startsWith("columns."));
        }
        for (SceneBody b : bodies.values()) {
            summary.putAll(BodyTypes.get(b.type()).summaryKeys());
        }
        for (SceneNode item : block.items()) {
            out.add(one(item, columns, summary, units));
        }
        return out;
    }

    private static SceneExpectation one(SceneNode item, List<String> columns, Map<String, String> summary,
            SceneUnits units) {
        MapReader r = new MapReader(item, KEYS);
        if (r.has("column") == r.has("summary")) {
            throw SceneException.at(item, "give either column (a CSV column: " + String.join(", ", columns)
                    + ") or summary (a key of summary.json)");
        }
        String source;
        String key;
        String stat;
        String unit;
        if (r.has("column")) {
            source = "column";
            SceneNode c = r.scalar("column");
            key = c.text();
            if (columns.isEmpty()) {
                throw SceneException.at(c, "this scene's run writes no CSV columns: check its summary instead"
                        + " (summary: KEY; keys: " + String.join(", ", summary.keySet()) + "), or give the file"
                        + " probes, whose columns it then writes");
            }
            if (!columns.contains(key)) {
                throw SceneException.at(c, c.describe() + " is not a column of this scene's CSV"
                        + DidYouMean.suggest(key, columns) + " (columns: " + String.join(", ", columns) + ")");
            }
            r.required("stat");
            stat = r.choice("stat", SceneExpectation.STATS, null);
            unit = SceneExpectation.columnUnit(key);
        } else {
            source = "summary";
            SceneNode s = r.scalar("summary");
            key = s.text();
            if (!summary.containsKey(key)) {
                throw SceneException.at(s, s.describe() + " is not a number of this scene's summary"
                        + DidYouMean.suggest(key, summary.keySet()) + " (keys: " + String.join(", ", summary.keySet())
                        + ")");
            }
            stat = r.choice("stat", List.of("value"), "value");
            unit = summary.get(key);
        }
        Unit<?> u = SceneExpectation.parse(unit);
        QuantityKind kind = kindOf(u);
        String where = item.where() + ": " + item.shownPath();
        if (r.has("between") == r.has("value")) {
            throw SceneException.at(item, "give either between: [low, high] or value: v with tolerance: t");
        }
        if (r.has("between")) {
            if (r.has("tolerance")) {
                throw SceneException.at(item.get("tolerance"), "a tolerance goes with value:, not with between:");
            }
            SceneNode b = r.list("between");
            if (b.items().size() != 2) {
                throw SceneException.at(b, "expected two values [low, high], got a list of " + b.items().size());
            }
            double lo = in(b.items().get(0), kind, u, units);
            double hi = in(b.items().get(1), kind, u, units);
            if (hi < lo) {
                throw SceneException.at(b.items().get(1), "high " + b.items().get(1).describe() + " is below low "
                        + b.items().get(0).describe());
            }
            String stated = "between " + b.items().get(0).text() + " and " + b.items().get(1).text();
            return new SceneExpectation(source, key, stat, unit, lo, hi, stated, where);
        }
        SceneNode vNode = r.scalar("value");
        double v = in(vNode, kind, u, units);
        SceneNode t = r.scalar("tolerance");
        String tText = t.text().strip();
        double tol;
        if (tText.endsWith("%")) {
            SceneNode number = SceneNode.scalar(SceneNode.Token.STRING, tText.substring(0, tText.length() - 1),
                    t.where(), t.path());
            tol = units.si(number, QuantityKind.NUMBER) / 100 * Math.abs(v);
        } else {
            tol = in(t, kind, u, units);
        }
        if (!(tol >= 0)) {
            throw SceneException.at(t, "a tolerance must be >= 0, got " + t.describe());
        }
        String stated = vNode.text() + " ± " + tText;
        return new SceneExpectation(source, key, stat, unit, v - tol, v + tol, stated, where);
    }

    /** The kind whose SI unit has the dimension of {@code u}; plain numbers when none has (or for counts). */
    static QuantityKind kindOf(Unit<?> u) {
        if (u.equals(AbstractUnit.ONE)) {
            return QuantityKind.NUMBER; // not an angle, which is dimensionless too
        }
        for (QuantityKind k : QuantityKind.values()) {
            if (k != QuantityKind.NUMBER && k.unit().isCompatible(u)) {
                return k;
            }
        }
        return QuantityKind.NUMBER;
    }

    /** A value of the column's dimension in the column's unit. */
    private static double in(SceneNode node, QuantityKind kind, Unit<?> u, SceneUnits units) {
        double si = units.si(node, kind);
        if (kind == QuantityKind.NUMBER) {
            return si;
        }
        try {
            return kind.unit().getConverterToAny(u).convert(si);
        } catch (IncommensurableException | UnconvertibleException e) {
            throw SceneException.at(node, node.describe() + " cannot be given in " + u);
        }
    }
}
