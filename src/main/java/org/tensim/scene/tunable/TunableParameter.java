package org.tensim.scene.tunable;

import java.math.BigDecimal;
import java.math.MathContext;
import org.tensim.model.Check;

/**
 * One parameter a user can tune while a simulation runs: a key (used in preset
 * files, and which carries the unit, e.g. {@code stiffnessNPerM}), a label and a
 * unit for people, an allowed closed range and a default. The descriptor holds no
 * value: values live in the GUI's tuning state and reach a scene through
 * {@link ViewScene#apply(String, double)}.
 *
 * @param key         identifier in presets, letters and digits only
 * @param label       short name shown next to the control
 * @param unit        unit of the value (e.g. {@code N/m}); empty for a pure number
 * @param min         smallest allowed value, in {@code unit}
 * @param max         largest allowed value, in {@code unit} (> min)
 * @param defaultValue the value a new scene starts with, within [min, max]
 * @param logarithmic whether a slider should move along a logarithmic scale (min must be > 0)
 * @param description one sentence on what the parameter does, for tooltips and docs
 * @param restarts    true when a change needs a new scene (the simulation restarts from rest); false when
 *                    it takes effect in the running simulation
 */
public record TunableParameter(String key, String label, String unit, double min, double max, double defaultValue,
        boolean logarithmic, String description, boolean restarts) {
    public TunableParameter {
        if (key == null || !key.matches("[A-Za-z][A-Za-z0-9]*")) {
            throw new IllegalArgumentException("parameter key must be letters and digits starting with a letter, got '"
                    + key + "'");
        }
        Check.finite(key + " minimum", unit, min);
        Check.finite(key + " maximum", unit, max);
        if (!(max > min)) {
            throw new IllegalArgumentException(key + ": maximum " + max + " must be greater than minimum " + min);
        }
        if (logarithmic && !(min > 0)) {
            throw new IllegalArgumentException(key + ": a logarithmic range needs a minimum > 0, got " + min);
        }
        if (!(defaultValue >= min && defaultValue <= max)) {
            throw new IllegalArgumentException(key + ": default " + defaultValue + " is outside [" + min + ", "
                    + max + "] " + unit);
        }
    }

    /** A linear parameter. */
    public static TunableParameter linear(String key, String label, String unit, double min, double max,
            double defaultValue, String description) {
        return new TunableParameter(key, label, unit, min, max, defaultValue, false, description, false);
    }

    /** A parameter best moved on a logarithmic scale (stiffness, time step). */
    public static TunableParameter log(String key, String label, String unit, double min, double max,
            double defaultValue, String description) {
        return new TunableParameter(key, label, unit, min, max, defaultValue, true, description, false);
    }

    /** The same parameter, marked as needing a new scene when it changes. */
    public TunableParameter restarting() {
        return new TunableParameter(key, label, unit, min, max, defaultValue, logarithmic, description, true);
    }

    /**
     * Returns the value when it is finite and within range; otherwise throws an
     * exception naming the parameter, the value, the unit and the range.
     *
     * @param source where the value came from (e.g. a file name), for the message; may be null
     */
    public double validate(double value, String source) {
        if (!Double.isFinite(value) || value < min || value > max) {
            throw new IllegalArgumentException((source == null ? "" : source + ": ") + label + " (" + key + ") must be "
                    + "between " + format(min) + " and " + format(max) + (unit.isEmpty() ? "" : " " + unit)
                    + ", got " + value);
        }
        return value;
    }

    /** Position of a value on the control's scale, 0 at min and 1 at max (log or linear). */
    public double toFraction(double value) {
        double v = Math.max(min, Math.min(max, value));
        return logarithmic ? Math.log(v / min) / Math.log(max / min) : (v - min) / (max - min);
    }

    /** Inverse of {@link #toFraction(double)}; the fraction is clamped to [0, 1]. */
    public double fromFraction(double fraction) {
        double f = Math.max(0, Math.min(1, fraction));
        double v = logarithmic ? min * Math.pow(max / min, f) : min + f * (max - min);
        return Math.max(min, Math.min(max, v)); // rounding at the ends must not leave the range
    }

    /** The label with its unit, e.g. {@code Stiffness (N/m)}. */
    public String labelWithUnit() {
        return unit.isEmpty() ? label : label + " (" + unit + ")";
    }

    /** A compact, locale-independent rendering of a value of this parameter. */
    public static String format(double v) {
        if (v == 0 || !Double.isFinite(v)) {
            return v == 0 ? "0" : Double.toString(v);
        }
        BigDecimal b = new BigDecimal(v).round(new MathContext(4)).stripTrailingZeros();
        double a = Math.abs(v);
        return a >= 1e-5 && a < 1e7 ? b.toPlainString() : b.toString();
    }
}
