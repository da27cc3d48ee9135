package org.tensim.solver.stability;

/**
 * An exact fraction {@code num / den} (den > 0, reduced), for Butcher tableaux and
 * stability polynomials: their low-order terms must cancel exactly (a double 1/6
 * would leave a spurious 1e-17 where theory has 0). Overflow throws
 * {@link ArithmeticException}; tableaux of a few stages stay far from it.
 */
public record Rational(long num, long den) {
    public static final Rational ZERO = new Rational(0, 1);
    public static final Rational ONE = new Rational(1, 1);

    /** Reduces and normalises the sign; den must not be 0. */
    public Rational {
        if (den == 0) {
            throw new ArithmeticException("fraction " + num + "/0");
        }
        long g = gcd(Math.abs(num), Math.abs(den));
        if (den < 0) {
            g = -g;
        }
        num /= g;
        den /= g;
    }

    public static Rational of(long n) {
        return new Rational(n, 1);
    }

    /**
     * Parses {@code "p"} or {@code "p/q"} (integers).
     *
     * @throws IllegalArgumentException naming the text when it is neither
     */
    public static Rational parse(String text) {
        try {
            int slash = text.indexOf('/');
            if (slash < 0) {
                return of(Long.parseLong(text.trim()));
            }
            return new Rational(Long.parseLong(text.substring(0, slash).trim()),
                    Long.parseLong(text.substring(slash + 1).trim()));
        } catch (NumberFormatException | ArithmeticException e) {
            throw new IllegalArgumentException("not a fraction: '" + text + "' (expected p or p/q, integers, q != 0)");
        }
    }

    public Rational plus(Rational o) {
        return new Rational(Math.addExact(Math.multiplyExact(num, o.den), Math.multiplyExact(o.num, den)),
                Math.multiplyExact(den, o.den));
    }

    public Rational times(Rational o) {
        return new Rational(Math.multiplyExact(num, o.num), Math.multiplyExact(den, o.den));
    }

    public Rational negate() {
        return new Rational(-num, den);
    }

    public int signum() {
        return Long.signum(num);
    }

    /** The nearest double (num and den are exact below 2^53). */
    public double toDouble() {
        return (double) num / den;
    }

    /** Greatest common divisor of |a| and |b| (1 when both are 0). */
    public static long gcdOf(long a, long b) {
        return gcd(Math.abs(a), Math.abs(b));
    }

    static long gcd(long a, long b) {
        while (b != 0) {
            long t = a % b;
            a = b;
            b = t;
        }
        return a == 0 ? 1 : a;
    }

    @Override
    public String toString() {
        return den == 1 ? Long.toString(num) : num + "/" + den;
    }
}
