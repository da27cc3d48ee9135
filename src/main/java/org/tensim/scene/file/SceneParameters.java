package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import javax.measure.Unit;

/**
 * Reads a scene's {@code parameters:} block: named values of the scene.
 * <pre>
 * parameters:
 *   E:       {path: bodies.liver.material.E, unit: kPa, range: [2, 15], apply: live}
 *   gravity: {path: conditions[1].acceleration[2], unit: m/s^2, range: [-20, 0], apply: live}
 *   cell:    {path: bodies.liver.cell, unit: mm, range: [6, 20], apply: rebuild}
 * </pre>
 * Each names a key path of the file (which must be written there: its value is the default), a unit (checked
 * against the dimension the loader reads the key in; optional for plain numbers), a range [min, max] in that unit
 * and {@code apply: live} (only for the keys of {@link LiveKeys}) or {@code rebuild}. It is read in two passes:
 * {@link #declare} before the {@code --set} options (so that {@code --set E=8kPa} can name a parameter), and
 * {@link #resolve} after the scene is built (so that the key's dimension is known from what read it).
 */
final class SceneParameters {
    /** The keys of one parameter. */
    static final List<String> KEYS = List.of("path", "unit", "range", "apply", "description");
    private static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9]*");
    private static final Pattern BARE = Pattern.compile("\\s*[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?\\s*");

    /** A parameter as declared, before the scene is built: its map, its path and the file's node there. */
    record Declared(String name, MapReader keys, String path, SceneNode original) {
    }

    private SceneParameters() {
    }

    /** The parameters of the block (absent: none), their paths checked against the file's tree. */
    static Map<String, Declared> declare(SceneNode root) {
        Map<String, Declared> out = new LinkedHashMap<>();
        SceneNode block = root.get("parameters");
        if (block == null || block.kind() == SceneNode.Kind.NULL) {
            return out;
        }
        if (!block.isMap()) {
            throw SceneException.at(block, "expected a map of named parameters (E: {path: ..., unit: ...,"
                    + " range: [min, max], apply: live}), got " + block.describe());
        }
        for (Map.Entry<String, SceneNode> e : block.entries().entrySet()) {
            String name = e.getKey();
            if (!NAME.matcher(name).matches() || SceneLoader.KEYS.contains(name)) {
                throw new SceneException(block.keyWhere(name) + ": " + SceneNode.child(block.path(), name) + ": '"
                        + name + "' cannot name a parameter (letters and digits, starting with a letter, and none of"
                        + " the top-level keys " + String.join(", ", SceneLoader.KEYS) + ")");
            }
            MapReader r = new MapReader(e.getValue(), KEYS);
            SceneNode pathNode = r.scalar("path");
            String path = pathNode.text().strip();
            SceneNode at;
            try {
                at = Overrides.find(root, path, pathNode.where());
            } catch (SceneException ex) {
                throw SceneException.at(pathNode, "\"" + path + "\" is not a key path (keys joined by '.', list"
                        + " items as [n], e.g. bodies.liver.material.E)");
            }
            if (at == null || !at.isScalar()) {
                throw SceneException.at(pathNode, at == null ? "the file has no value at " + path + " (a parameter's"
                        + " default is the value written there: write it in the file)"
                        : path + " is " + at.describe() + ", not a single value");
            }
            r.choice("apply", List.of("live", "rebuild"), null);
            r.required("apply");
            out.put(name, new Declared(name, r, path, at));
        }
        return out;
    }

    /**
     * Applies the {@code --set} options: {@code NAME=VALUE} for a declared parameter sets its path (a bare number
     * is in the parameter's unit), anything else is a key path ({@link Overrides}).
     */
    static void override(SceneNode root, Map<String, Declared> declared, List<String> sets) {
        for (String set : sets) {
            String[] kv = Overrides.split(set);
            Declared d = declared.get(kv[0]);
            if (d == null) {
                Overrides.apply(root, "--set " + set, kv[0], kv[1]);
                continue;
            }
            String unit = d.keys().has("unit") ? d.keys().string("unit").strip() : "";
            earlyRangeCheck(d, unit, set, kv[1]);
            String value = BARE.matcher(kv[1]).matches() && !unit.isEmpty() ? kv[1] + " " + unit : kv[1];
            Overrides.apply(root, "--set " + set, d.path(), value);
        }
    }

    /**
     * Refuses a value outside the parameter's range before the scene is built (a build with it might fail for
     * another reason first). Values and ranges that do not convert are left to {@link #resolve}, which names why.
     */
    private static void earlyRangeCheck(Declared d, String unit, String set, String text) {
        SceneNode range = d.keys().has("range") ? d.keys().required("range") : null;
        if (range == null || !range.isList() || range.items().size() != 2 || !range.items().get(0).isScalar()
                || !range.items().get(1).isScalar()) {
            return;
        }
        double lo = SceneUnits.in(range.items().get(0).text(), unit);
        double hi = SceneUnits.in(range.items().get(1).text(), unit);
        double v = SceneUnits.in(text, unit);
        double slack = 1e-12 * Math.max(Math.abs(lo), Math.abs(hi));
        if (Double.isFinite(lo) && Double.isFinite(hi) && Double.isFinite(v) && (v < lo - slack || v > hi + slack)) {
            throw new SceneException("--set " + set + ": " + d.path() + ": " + SceneParameter.format(v)
                    + " is outside parameter " + d.name() + "'s range [" + SceneParameter.format(lo) + ", "
                    + SceneParameter.format(hi) + "]" + (unit.isEmpty() ? "" : " " + unit));
        }
    }

    /** The parameters, checked against the built scene: the key's dimension, the apply mode, the range. */
    static List<SceneParameter> resolve(Map<String, Declared> declared, SceneNode root, SceneUnits units) {
        List<SceneParameter> out = new ArrayList<>();
        for (Declared d : declared.values()) {
            MapReader r = d.keys();
            SceneNode current = Overrides.find(root, d.path(), d.path());
            QuantityKind kind = current == null ? null : current.readAs();
            if (kind == null) {
                throw SceneException.at(r.required("path"), d.path() + " (" + d.original().where() + ") is not a"
                        + " quantity this scene reads (a parameter names a number with a unit: a modulus, a"
                        + " stiffness, a length, a magnitude)");
            }
            String unitText = r.has("unit") ? r.string("unit").strip() : "";
            if (unitText.isEmpty() && kind != QuantityKind.NUMBER) {
                throw SceneException.at(r.has("unit") ? r.required("unit") : r.node(), "a unit is required: "
                        + d.path() + " is a " + kind.word() + " (e.g. " + kind.siSymbol() + ")");
            }
            Unit<?> unit;
            try {
                unit = unitText.isEmpty() ? kind.unit() : SceneUnits.unit(r.required("unit"), unitText, kind);
            } catch (SceneException ex) {
                throw SceneException.at(r.required("unit"), "\"" + unitText + "\" is not a unit of "
                        + kind.word() + ", the dimension of " + d.path() + " (expected a unit of "
                        + kind.siSymbol() + ", e.g. \"" + kind.example().replaceAll("^[-0-9.e]+ ", "") + "\")");
            }
            double perUnit = SceneUnits.toSi(unit, 1, r.node(), kind);
            double[] range = range(r, kind, units, unit);
            boolean live = r.string("apply").equals("live");
            if (live) {
                String why = LiveKeys.whyNotLive(root, d.path());
                if (why != null) {
                    throw SceneException.at(r.required("apply"), "parameter " + d.name() + " is marked live, but "
                            + why);
                }
            }
            double def = SceneUnits.fromSi(unit, units.si(d.original(), kind), d.original(), kind);
            double value = SceneUnits.fromSi(unit, current.readAs() == null ? 0 : units.si(current, kind), current,
                    kind);
            SceneParameter p = new SceneParameter(d.name(), d.path(), unitText, kind, perUnit, range[0], range[1], def,
                    value, live, r.string("description", ""));
            if (!p.within(def)) {
                throw SceneException.at(r.required("range"), "the default of parameter " + d.name() + ", "
                        + SceneParameter.format(def) + " " + unitText + " (" + d.path() + " at "
                        + d.original().where() + "), is outside its range " + p.range());
            }
            if (current != d.original()) {
                p.checked(value, current.where() + ": " + d.path());
            }
            out.add(p);
        }
        return out;
    }

    /** [min, max] in the parameter's unit: bare numbers are in it, values with units are converted. */
    private static double[] range(MapReader r, QuantityKind kind, SceneUnits units, Unit<?> unit) {
        SceneNode n = r.list("range");
        if (n.items().size() != 2) {
            throw SceneException.at(n, "expected a range [min, max], got a list of " + n.items().size());
        }
        double[] out = new double[2];
        for (int i = 0; i < 2; i++) {
            SceneNode v = n.items().get(i);
            out[i] = v.isScalar() && BARE.matcher(v.text()).matches() ? Double.parseDouble(v.text().strip())
                    : SceneUnits.fromSi(unit, units.si(v, kind), v, kind);
        }
        if (!(out[1] > out[0])) {
            throw SceneException.at(n.items().get(1), "the range's max " + n.items().get(1).describe()
                    + " must be above its min " + n.items().get(0).describe());
        }
        return out;
    }
}
