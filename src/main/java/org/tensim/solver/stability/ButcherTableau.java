package org.tensim.solver.stability;

import java.util.ArrayList;
import java.util.List;

/**
 * An explicit Runge-Kutta method's Butcher tableau, with exact rational entries
 * (after Hipparchus's {@code ButcherArrayProvider}):
 *
 * <pre>
 *   c_1 = 0 |
 *   c_2     | a_21
 *   ...     | ...        ...
 *   c_s     | a_s1  ...  a_s,s-1
 *   --------+----------------------
 *           | b_1   ...  b_s-1  b_s
 * </pre>
 *
 * Stage i of a step of size h from (t, y) evaluates the slope at
 * {@code t + c_i h, y + h sum_j a_ij k_j} (c_i = the row sum); the step ends at
 * {@code y + h sum_i b_i k_i}. {@code integrators.ExplicitRungeKutta} runs it on (x, v) with the
 * slopes (v, f / m). The tableau also gives the linear stability: the stability
 * polynomial R(z) and, on the test oscillator, the same arithmetic as the node loops.
 */
public final class ButcherTableau implements LinearStability {
    /**
     * The paper's method, the explicit midpoint rule (c = (0, 1/2), a_21 = 1/2,
     * b = (0, 1)): the tableau of {@code MidpointRK2}, and the reference that
     * {@link TimeStepPolicy} gives methods without a stability limit.
     */
    public static final ButcherTableau MIDPOINT = of(new String[][] {{}, {"1/2"}}, "0", "1");

    /** Row i: the indices j of the non-zero a_ij (j < i), and h a_ij = (h num) / den. */
    private final int[][] terms;
    private final double[][] termNum;
    private final double[][] termDen;
    /** c_i = cNum / cDen. */
    private final double[] cNum;
    private final double[] cDen;
    /** b_j = weight_j / weightDen with integer weights (0 for unused stages). */
    private final double[] weight;
    private final double weightDen;
    /** Whether the non-zero weights are all equal (then 1 each, since they sum to weightDen). */
    private final boolean equalWeights;
    private final StabilityPolynomial polynomial;

    private ButcherTableau(Rational[][] a, Rational[] b) {
        int s = b.length;
        terms = new int[s][];
        termNum = new double[s][];
        termDen = new double[s][];
        cNum = new double[s];
        cDen = new double[s];
        for (int i = 0; i < s; i++) {
            if (a[i].length != i) {
                throw new IllegalArgumentException("Butcher tableau row " + i + " has " + a[i].length
                        + " entries; an explicit method's row i has exactly i (a_ij for j < i)");
            }
            List<Integer> nz = new ArrayList<>();
            Rational c = Rational.ZERO;
            for (int j = 0; j < i; j++) {
                c = c.plus(a[i][j]);
                if (a[i][j].signum() != 0) {
                    nz.add(j);
                }
            }
            terms[i] = nz.stream().mapToInt(Integer::intValue).toArray();
            termNum[i] = new double[nz.size()];
            termDen[i] = new double[nz.size()];
            for (int t = 0; t < nz.size(); t++) {
                termNum[i][t] = a[i][nz.get(t)].num();
                termDen[i][t] = a[i][nz.get(t)].den();
            }
            cNum[i] = c.num();
            cDen[i] = c.den();
        }
        long lcm = 1;
        Rational sum = Rational.ZERO;
        for (Rational r : b) {
            lcm = lcm / Rational.gcdOf(lcm, r.den()) * r.den();
            sum = sum.plus(r);
        }
        if (!sum.equals(Rational.ONE)) {
            throw new IllegalArgumentException("Butcher tableau weights sum to " + sum + "; a consistent method's sum to 1");
        }
        weight = new double[s];
        weightDen = lcm;
        long common = 0;
        boolean equal = true;
        for (int j = 0; j < s; j++) {
            long wj = b[j].num() * (lcm / b[j].den());
            weight[j] = wj;
            if (wj != 0) {
                equal &= common == 0 || common == wj;
                common = wj;
            }
        }
        equalWeights = equal;
        polynomial = new StabilityPolynomial(gamma(a, b));
    }

    /**
     * A tableau from its entries written as fractions ("1/2", "0", "1").
     *
     * @param a the rows a_i1 .. a_i,i-1 (row 0 empty)
     * @param b the weights b_1 .. b_s (summing to 1)
     * @throws IllegalArgumentException naming a malformed entry, a row of the wrong length or weights not summing to 1
     */
    public static ButcherTableau of(String[][] a, String... b) {
        if (a.length != b.length) {
            throw new IllegalArgumentException("Butcher tableau has " + a.length + " rows and " + b.length + " weights");
        }
        Rational[][] ra = new Rational[a.length][];
        for (int i = 0; i < a.length; i++) {
            ra[i] = new Rational[a[i].length];
            for (int j = 0; j < a[i].length; j++) {
                ra[i][j] = Rational.parse(a[i][j]);
            }
        }
        Rational[] rb = new Rational[b.length];
        for (int j = 0; j < b.length; j++) {
            rb[j] = Rational.parse(b[j]);
        }
        return new ButcherTableau(ra, rb);
    }

    /** gamma_k = b^T A^(k-1) 1, k = 0..s (gamma_0 = 1). */
    private static List<Rational> gamma(Rational[][] a, Rational[] b) {
        int s = b.length;
        List<Rational> g = new ArrayList<>();
        g.add(Rational.ONE);
        Rational[] y = new Rational[s]; // A^(k-1) 1
        java.util.Arrays.fill(y, Rational.ONE);
        for (int k = 1; k <= s; k++) {
            Rational sum = Rational.ZERO;
            for (int j = 0; j < s; j++) {
                sum = sum.plus(b[j].times(y[j]));
            }
            g.add(sum);
            Rational[] next = new Rational[s];
            for (int i = 0; i < s; i++) {
                next[i] = Rational.ZERO;
                for (int j = 0; j < i; j++) {
                    next[i] = next[i].plus(a[i][j].times(y[j]));
                }
            }
            y = next;
        }
        return g;
    }

    /** Number of stages s (force evaluations per step). */
    public int stages() {
        return weight.length;
    }

    /** The stages j &lt; i with a non-zero a_ij, ascending (a copy). */
    public int[] terms(int i) {
        return terms[i].clone();
    }

    /** h a_ij for the t-th non-zero term of row i, computed as (h num) / den. */
    public double stepCoefficient(int i, int t, double h) {
        return h * termNum[i][t] / termDen[i][t];
    }

    /** t + c_i h, computed as t + (h num) / den. */
    public double stageTime(int i, double t, double h) {
        return t + h * cNum[i] / cDen[i];
    }

    /** The integer weight beta_j of stage j: b_j = beta_j / {@link #weightDenominator()}. */
    public double weight(int j) {
        return weight[j];
    }

    /** The common denominator D of the weights (the least). */
    public double weightDenominator() {
        return weightDen;
    }

    /** Whether the non-zero weights are all equal (each then 1 over D). */
    public boolean equalWeights() {
        return equalWeights;
    }

    /** The stability function R(z) (exact coefficients). */
    public StabilityPolynomial stabilityPolynomial() {
        return polynomial;
    }

    /** From R(z): the largest undamped w h with |R(i w h)| &lt;= 1. */
    @Override
    public double undampedLimit() {
        return polynomial.undampedLimit();
    }

    /**
     * max |R(h lambda)| over the mode's two eigenvalues
     * {@code lambda = w (-zeta +/- i sqrt(1 - zeta^2))} (both real when zeta &gt;= 1).
     */
    @Override
    public double modeAmplification(double h, double w, double zeta) {
        if (zeta >= 1) {
            double d = Math.sqrt(zeta * zeta - 1);
            return Math.max(polynomial.modulus(h * (-w * (zeta - d)), 0), polynomial.modulus(h * (-w * (zeta + d)), 0));
        }
        return polynomial.modulus(h * (-w * zeta), h * (w * Math.sqrt(1 - zeta * zeta)));
    }

    /** The method on x'' = -x - 2 zeta x', with the node loops' order of operations (w = 1 there). */
    @Override
    public double[] oscillatorStep(double h, double zeta, double x, double v) {
        int s = stages();
        double c = 2 * zeta;
        double[] xs = new double[s];
        double[] vs = new double[s];
        double[] as = new double[s];
        for (int i = 0; i < s; i++) {
            double dx = 0;
            double dv = 0;
            for (int t = 0; t < terms[i].length; t++) {
                int j = terms[i][t];
                double coef = stepCoefficient(i, t, h);
                dx = t == 0 ? coef * vs[j] : dx + coef * vs[j];
                dv = t == 0 ? coef * as[j] : dv + coef * as[j];
            }
            xs[i] = terms[i].length == 0 ? x : x + dx;
            vs[i] = terms[i].length == 0 ? v : v + dv;
            as[i] = -xs[i] - c * vs[i];
        }
        double hb = h / weightDen;
        double sx = 0;
        double sa = 0;
        boolean first = true;
        for (int j = 0; j < s; j++) {
            if (weight[j] != 0) {
                sx = first ? weight[j] * vs[j] : sx + weight[j] * vs[j];
                sa = first ? weight[j] * as[j] : sa + weight[j] * as[j];
                first = false;
            }
        }
        return new double[] {x + hb * sx, v + hb * sa};
    }
}
