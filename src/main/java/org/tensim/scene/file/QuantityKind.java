package org.tensim.scene.file;

import java.util.Locale;
import javax.measure.Unit;
import tech.units.indriya.AbstractUnit;
import tech.units.indriya.format.SimpleUnitFormat;

/**
 * The kinds of quantity a scene file's values have, each with its SI unit (the model's unit) and an example for
 * messages. A {@code units:} block sets the unit of bare numbers per kind, by these names.
 */
public enum QuantityKind {
    LENGTH("length", "m", "2.5 mm"),
    MASS("mass", "kg", "10 g"),
    TIME("time", "s", "1 ms"),
    FREQUENCY("frequency", "Hz", "0.25 Hz"),
    FORCE("force", "N", "400 N"),
    PRESSURE("pressure", "Pa", "2 kPa"),
    STIFFNESS("stiffness", "N/m", "100 N/m"),
    DAMPING("damping", "N*s/m", "2 N*s/m"),
    DENSITY("density", "kg/m^3", "1050 kg/m^3"),
    ACCELERATION("acceleration", "m/s^2", "9.81 m/s^2"),
    ANGLE("angle", "rad", "0.5 rad"),
    /** Stiffness per unit area of a surface (a penalty, an elastic foundation's modulus): Pa/m. */
    AREAL_STIFFNESS("areal_stiffness", "Pa/m", "5e7 Pa/m"),
    /** Factors, fractions, Poisson's ratio: a plain number. */
    NUMBER("number", "", "0.45");

    private final String word;
    private final String si;
    private final String example;
    private final Unit<?> unit;

    QuantityKind(String word, String si, String example) {
        this.word = word;
        this.si = si;
        this.example = example;
        this.unit = si.isEmpty() ? AbstractUnit.ONE : SimpleUnitFormat.getInstance().parse(si);
    }

    /** The key of this kind in a {@code units:} block, and its name in messages. */
    public String word() {
        return word;
    }

    /** The SI unit as written in the docs ("" for plain numbers). */
    public String siSymbol() {
        return si;
    }

    /** A value of this kind as a scene file may write it. */
    public String example() {
        return example;
    }

    /** The SI unit (indriya). */
    public Unit<?> unit() {
        return unit;
    }

    /** The kind named {@code word} in a {@code units:} block, or null. */
    public static QuantityKind byWord(String word) {
        for (QuantityKind k : values()) {
            if (k.word.equals(word.toLowerCase(Locale.ROOT)) && k != NUMBER) {
                return k;
            }
        }
        return null;
    }
}
