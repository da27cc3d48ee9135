package org.tensim.model;

/**
 * Validation of values where they enter the model. Every failure names the
 * quantity, the value received and what was expected, so that a user can find
 * the bad number in a scene file or on a command line.
 */
public final class Check {
    private Check() {
    }

    /** Requires a finite value strictly greater than zero. */
    public static double positive(String what, String unit, double value) {
        if (!(value > 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " must be a finite number > 0 " + unit
                    + ", got " + value);
        }
        return value;
    }

    /** Requires a finite value greater than or equal to zero. */
    public static double nonNegative(String what, String unit, double value) {
        if (!(value >= 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " must be a finite number >= 0 " + unit
                    + ", got " + value);
        }
        return value;
    }

    /** Requires a finite value (not NaN, not infinite). */
    public static double finite(String what, String unit, double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " must be a finite number " + unit
                    + ", got " + value);
        }
        return value;
    }

    /** Requires {@code 0 <= index < size}. */
    public static int index(String what, int index, int size) {
        if (index < 0 || index >= size) {
            throw new IndexOutOfBoundsException(what + " " + index + " is out of range: expected 0 <= index < "
                    + size);
        }
        return index;
    }

    /** Requires a whole number at least {@code min}. */
    public static int atLeast(String what, int value, int min) {
        if (value < min) {
            throw new IllegalArgumentException(what + " must be >= " + min + ", got " + value);
        }
        return value;
    }
}
