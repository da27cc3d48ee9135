package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.measure.IncommensurableException;
import javax.measure.UnconvertibleException;
import javax.measure.Unit;
import javax.measure.format.MeasurementParseException;
import tech.units.indriya.format.SimpleUnitFormat;

/**
 * Values with units, converted to SI where the file is read: {@code "3 kPa"}, {@code "2.5 mm"},
 * {@code "1050 kg/m^3"}. The unit after the number is parsed by indriya's {@link SimpleUnitFormat} (JSR 385):
 * prefixes (mm, kPa, kN), products with {@code *} or {@code ·}, quotients with {@code /}, powers with {@code ^}
 * ({@code m^3}, {@code s^-1}, {@code m/s^2}) or superscripts ({@code m³}). The number is read first, by
 * {@link Double#parseDouble} (indriya's own quantity format misreads {@code 1e-3}). A bare number takes the unit of
 * its kind from the file's {@code units:} block, or SI. A unit of another dimension than the key's is refused.
 */
public final class SceneUnits {
    /** A number (Java/JSON syntax) then, optionally, the unit. */
    private static final Pattern VALUE = Pattern.compile(
            "\\s*([-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?)\\s*(.*?)\\s*");

    private final Map<QuantityKind, Unit<?>> defaults = new EnumMap<>(QuantityKind.class);

    /** SI for every kind. */
    public SceneUnits() {
    }

    /** The kinds a {@code units:} block may set (every kind but plain numbers). */
    public static List<String> blockKeys() {
        List<String> l = new ArrayList<>();
        for (QuantityKind k : QuantityKind.values()) {
            if (k != QuantityKind.NUMBER) {
                l.add(k.word());
            }
        }
        return l;
    }

    /** Reads a {@code units:} block: kind: unit, e.g. {@code length: mm}; null keeps SI. */
    public static SceneUnits read(SceneNode block) {
        SceneUnits u = new SceneUnits();
        if (block == null) {
            return u;
        }
        MapReader r = new MapReader(block, blockKeys());
        for (Map.Entry<String, SceneNode> e : block.entries().entrySet()) {
            QuantityKind k = QuantityKind.byWord(e.getKey());
            SceneNode v = r.scalar(e.getKey());
            Unit<?> unit = unit(v, v.text(), k);
            u.defaults.put(k, unit);
        }
        return u;
    }

    /** The unit bare numbers of this kind are in. */
    public Unit<?> unitOf(QuantityKind kind) {
        return defaults.getOrDefault(kind, kind.unit());
    }

    /** A scalar node's value in SI units; refused naming the node if it is not a value of this kind. */
    public double si(SceneNode node, QuantityKind kind) {
        return in(node, kind, kind.unit());
    }

    /**
     * A scalar node's value in {@code target}, a unit of the kind (a value written in that unit is returned as
     * written: an option taking millimetres gets "2.5 mm" as 2.5, not as 2.5e-3 times 1e3).
     */
    public double in(SceneNode node, QuantityKind kind, Unit<?> target) {
        if (!node.isScalar() || node.token() == SceneNode.Token.BOOLEAN) {
            throw SceneException.at(node, node.describe() + " is not " + article(kind) + " (expected a value in "
                    + siText(kind) + ", e.g. \"" + kind.example() + "\")");
        }
        Matcher m = VALUE.matcher(node.text());
        if (!m.matches()) {
            throw SceneException.at(node, node.describe() + " is not " + article(kind) + " (expected a number"
                    + (kind == QuantityKind.NUMBER ? "" : " and a unit, e.g. \"" + kind.example() + "\"") + ")");
        }
        double value = Double.parseDouble(m.group(1));
        if (!Double.isFinite(value)) {
            throw SceneException.at(node, node.describe() + " is not a finite number");
        }
        String unitText = m.group(2);
        Unit<?> unit = unitText.isEmpty() ? unitOf(kind) : unit(node, unitText, kind);
        double converted = convert(unit, value, target, node, kind);
        node.markRead(kind);
        return converted;
    }

    /** {@code value} in {@code unit} (of the kind) converted to the kind's SI unit. */
    static double toSi(Unit<?> unit, double value, SceneNode node, QuantityKind kind) {
        return convert(unit, value, kind.unit(), node, kind);
    }

    /** {@code value} in {@code unit} converted to {@code target} (both of the kind); as written when they are equal. */
    private static double convert(Unit<?> unit, double value, Unit<?> target, SceneNode node, QuantityKind kind) {
        try {
            return unit.equals(target) ? value : unit.getConverterToAny(target).convert(value);
        } catch (IncommensurableException | UnconvertibleException e) {
            throw notKind(node, kind);
        }
    }

    /** {@code si} (in the kind's SI unit) converted to {@code unit}. */
    static double fromSi(Unit<?> unit, double si, SceneNode node, QuantityKind kind) {
        try {
            return kind.unit().getConverterToAny(unit).convert(si);
        } catch (IncommensurableException | UnconvertibleException e) {
            throw notKind(node, kind);
        }
    }

    /**
     * A value's text ({@code "8"}, {@code "8 kPa"}) in {@code unit} (a bare number is taken to be in it); NaN when
     * either does not parse or they are of different dimensions (the loader then says why).
     */
    static double in(String text, String unit) {
        Matcher m = VALUE.matcher(text);
        if (!m.matches()) {
            return Double.NaN;
        }
        double v = Double.parseDouble(m.group(1));
        if (m.group(2).isEmpty() || m.group(2).equals(unit.strip())) {
            return v;
        }
        try {
            Unit<?> to = unit.isBlank() ? tech.units.indriya.AbstractUnit.ONE
                    : SimpleUnitFormat.getInstance().parse(unit.strip());
            return SimpleUnitFormat.getInstance().parse(m.group(2)).getConverterToAny(to).convert(v);
        } catch (MeasurementParseException | IllegalArgumentException | IncommensurableException
                | UnconvertibleException e) {
            return Double.NaN;
        }
    }

    /** A unit's text parsed by indriya, refused at {@code node} unless it is a unit of the kind. */
    static Unit<?> unit(SceneNode node, String text, QuantityKind kind) {
        Unit<?> u;
        try {
            u = SimpleUnitFormat.getInstance().parse(text.strip());
        } catch (MeasurementParseException | IllegalArgumentException e) {
            throw SceneException.at(node, "unknown unit \"" + text + "\" in " + node.describe() + " (expected "
                    + article(kind) + " in " + siText(kind) + ", e.g. \"" + kind.example() + "\"; powers are"
                    + " written m^3, products N*s)");
        }
        if (!u.isCompatible(kind.unit())) {
            throw notKind(node, kind);
        }
        return u;
    }

    private static SceneException notKind(SceneNode node, QuantityKind kind) {
        return SceneException.at(node, node.describe() + " is not " + article(kind) + " (expected a value in "
                + siText(kind) + ", e.g. \"" + kind.example() + "\")");
    }

    private static String siText(QuantityKind kind) {
        return kind.siSymbol().isEmpty() ? "no unit" : kind.siSymbol();
    }

    private static String article(QuantityKind kind) {
        String w = kind.word().toLowerCase(Locale.ROOT);
        return (w.startsWith("a") ? "an " : "a ") + w;
    }
}
