package org.tensim.solver.stability;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;

/**
 * The stability function of an explicit Runge-Kutta method,
 * {@code R(z) = sum_k gamma_k z^k} with {@code gamma_0 = 1} and
 * {@code gamma_k = b^T A^(k-1) 1} (Hairer and Wanner, Solving ODEs II, IV.2): one step
 * of the method on {@code y' = lambda y} multiplies y by {@code R(h lambda)}. Exact
 * rational coefficients, from the tableau.
 *
 * <p>On an undamped spring of angular frequency w the eigenvalues are {@code +/- i w},
 * so the method keeps it bounded while {@code |R(i w h)| <= 1}: {@link #undampedLimit()}
 * is the largest such w h (0 for forward Euler and every two-stage RK2, whose
 * {@code |R(i y)|^2 = 1 + y^2} and {@code 1 + y^4 / 4} exceed 1 at once; 2 sqrt(2)
 * for classic RK4, from {@code |R(i y)|^2 - 1 = y^6 (y^2 - 8) / 576}).
 */
public final class StabilityPolynomial {
    private final Rational[] gamma;
    private final double[] gammaD;
    private final double undampedLimit;

    /** @param gamma the coefficients gamma_0 .. gamma_s (gamma_0 = 1) */
    public StabilityPolynomial(List<Rational> gamma) {
        this.gamma = gamma.toArray(new Rational[0]);
        this.gammaD = new double[this.gamma.length];
        for (int k = 0; k < gammaD.length; k++) {
            gammaD[k] = this.gamma[k].toDouble();
        }
        this.undampedLimit = computeUndampedLimit();
    }

    /** gamma_k, exact. */
    public Rational coefficient(int k) {
        return gamma[k];
    }

    /** Degree s (the number of stages of an explicit method). */
    public int degree() {
        return gamma.length - 1;
    }

    /**
     * |R(x + i y)|, summed in ascending powers of z (so that for 1 + z + z^2/2 it is
     * {@code hypot(1 + x + (x^2 - y^2) / 2, y + x y)} to the last bit).
     */
    public double modulus(double x, double y) {
        double re = 1;
        double im = 0;
        double pr = 1; // z^k
        double pi = 0;
        for (int k = 1; k < gammaD.length; k++) {
            double r = pr * x - pi * y;
            double i = pr * y + pi * x;
            pr = r;
            pi = i;
            re += gammaD[k] * pr;
            im += gammaD[k] * pi;
        }
        return Math.hypot(re, im);
    }

    /**
     * The largest w h with |R(i w' h)| <= 1 for every w' h in (0, w h]: 0 when the
     * method grows at every step, infinite when it never leaves the unit disc on the
     * imaginary axis. The root is found on exactly evaluated signs, so an exact root
     * such as RK4's {@code (w h)^2 = 8} comes out as the double nearest to sqrt(8).
     */
    public double undampedLimit() {
        return undampedLimit;
    }

    private double computeUndampedLimit() {
        // |R(i y)|^2 - 1 = P(u)^2 + u Q(u)^2 - 1 with u = y^2, P the even and Q the odd part.
        int n = gamma.length;
        Rational[] p = new Rational[n];
        Rational[] q = new Rational[n];
        java.util.Arrays.fill(p, Rational.ZERO);
        java.util.Arrays.fill(q, Rational.ZERO);
        for (int k = 0; k < n; k++) {
            Rational c = (k / 2) % 2 == 0 ? gamma[k] : gamma[k].negate();
            if (k % 2 == 0) {
                p[k / 2] = c;
            } else {
                q[k / 2] = c;
            }
        }
        Rational[] e = new Rational[2 * n + 1];
        java.util.Arrays.fill(e, Rational.ZERO);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                e[i + j] = e[i + j].plus(p[i].times(p[j]));
                e[i + j + 1] = e[i + j + 1].plus(q[i].times(q[j]));
            }
        }
        e[0] = e[0].plus(Rational.ONE.negate());
        List<Rational> g = new ArrayList<>();
        for (Rational c : e) {
            if (!g.isEmpty() || c.signum() != 0) {
                g.add(c); // u^m G(u): drop the vanishing low orders
            }
        }
        while (!g.isEmpty() && g.get(g.size() - 1).signum() == 0) {
            g.remove(g.size() - 1);
        }
        if (g.isEmpty()) {
            return Double.POSITIVE_INFINITY; // |R| = 1 on the whole axis
        }
        if (g.get(0).signum() > 0) {
            return 0; // |R(i y)| > 1 for small y already
        }
        BigInteger[] c = integerCoefficients(g);
        double bound = 1;
        Rational lead = g.get(g.size() - 1);
        for (Rational r : g) {
            bound = Math.max(bound, 1 + Math.abs(r.toDouble() / lead.toDouble()));
        }
        double lo = 0;
        double hi = Double.NaN;
        for (int j = 1; j <= 4096; j++) {
            double u = bound * j / 4096;
            if (sign(c, u) > 0) {
                hi = u;
                break;
            }
            lo = u;
        }
        if (Double.isNaN(hi)) {
            return Double.POSITIVE_INFINITY;
        }
        while (Math.nextUp(lo) < hi) {
            double mid = lo + 0.5 * (hi - lo);
            if (mid <= lo || mid >= hi) {
                mid = Math.nextUp(lo);
            }
            if (sign(c, mid) > 0) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return Math.sqrt(lo);
    }

    /** The coefficients times their common denominator (same signs, integer). */
    private static BigInteger[] integerCoefficients(List<Rational> g) {
        BigInteger d = BigInteger.ONE;
        for (Rational r : g) {
            BigInteger rd = BigInteger.valueOf(r.den());
            d = d.divide(d.gcd(rd)).multiply(rd);
        }
        BigInteger[] c = new BigInteger[g.size()];
        for (int k = 0; k < c.length; k++) {
            c[k] = BigInteger.valueOf(g.get(k).num()).multiply(d.divide(BigInteger.valueOf(g.get(k).den())));
        }
        return c;
    }

    /** Exact sign of sum c_k u^k. */
    private static int sign(BigInteger[] c, double u) {
        BigDecimal x = new BigDecimal(u);
        BigDecimal sum = BigDecimal.ZERO;
        for (int k = c.length - 1; k >= 0; k--) {
            sum = sum.multiply(x).add(new BigDecimal(c[k]));
        }
        return sum.signum();
    }
}
