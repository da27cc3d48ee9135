package org.tensim.scene.file;

import java.util.Locale;

/**
 * A named parameter of a scene file ({@code parameters:}, docs/scenes.md): a value of the scene, at a key path,
 * that the GUI shows as a control, {@code --set NAME=VALUE} sets, and sweeps and calibrations vary. Its values are
 * in its own unit; {@link #toSi} converts them to the SI unit of its kind.
 *
 * @param name         the parameter's name (letters and digits, starting with a letter)
 * @param path         the key path it sets, e.g. {@code bodies.liver.material.E}
 * @param unit         its unit as written (e.g. {@code kPa}; "" for a plain number)
 * @param kind         the kind of quantity at the path (what the loader reads it as)
 * @param siPerUnit    SI units per unit: {@code si = value * siPerUnit}
 * @param min          smallest value, in {@code unit}
 * @param max          largest value, in {@code unit} (> min)
 * @param defaultValue the file's value at the path, in {@code unit}
 * @param value        the value the scene was loaded with (the default, or a {@code --set}), in {@code unit}
 * @param live         true when a running simulation can take a new value ({@code apply: live}); false when the
 *                     scene must be rebuilt ({@code apply: rebuild})
 * @param description  one sentence for people, or ""
 */
public record SceneParameter(String name, String path, String unit, QuantityKind kind, double siPerUnit, double min,
        double max, double defaultValue, double value, boolean live, String description) {
    /** A value of this parameter, in its unit, in SI. */
    public double toSi(double v) {
        return v * siPerUnit;
    }

    /** A value of this parameter as a scene file would write it at the path: {@code "8.0 kPa"}. */
    public String text(double v) {
        return unit.isEmpty() ? Double.toString(v) : v + " " + unit;
    }

    /** The value when it is within [min, max], else a refusal naming the parameter, its range and {@code where}. */
    public double checked(double v, String where) {
        if (!within(v)) {
            throw new SceneException(where + ": " + format(v) + " is outside parameter " + name + "'s range "
                    + range());
        }
        return v;
    }

    /** Whether a value lies in [min, max] (to rounding: a value converted between units stays in). */
    public boolean within(double v) {
        double slack = 1e-12 * Math.max(Math.abs(min), Math.abs(max));
        return Double.isFinite(v) && v >= min - slack && v <= max + slack;
    }

    /** The range as {@code [2, 20] kPa}. */
    public String range() {
        return "[" + format(min) + ", " + format(max) + "]" + (unit.isEmpty() ? "" : " " + unit);
    }

    /** What {@code tensim check} prints of it. */
    public String describe() {
        return String.format(Locale.ROOT, "parameter %s: %s = %s%s (default %s), range %s, applies %s%s", name, path,
                format(value), unit.isEmpty() ? "" : " " + unit, format(defaultValue), range(),
                live ? "live" : "on rebuild", description.isEmpty() ? "" : "; " + description);
    }

    /** Six significant digits, no trailing zeros, plain notation between 1e-4 and 1e9. */
    static String format(double v) {
        if (v == 0 || !Double.isFinite(v)) {
            return v == 0 ? "0" : Double.toString(v);
        }
        java.math.BigDecimal b = new java.math.BigDecimal(v).round(new java.math.MathContext(6)).stripTrailingZeros();
        double a = Math.abs(v);
        return a >= 1e-4 && a < 1e9 ? b.toPlainString() : b.toString();
    }
}
