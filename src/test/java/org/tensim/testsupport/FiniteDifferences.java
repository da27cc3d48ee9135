package org.tensim.testsupport;

import java.util.Random;
import java.util.function.BiConsumer;
import java.util.function.ToDoubleFunction;

/**
 * Central differences for the tests that forces are minus the gradient of an energy and that a
 * tangent is the derivative of the forces, and the vectors those tests draw.
 */
public final class FiniteDifferences {
    private FiniteDifferences() {
    }

    /**
     * The gradient of {@code energy} at x by central differences of step h:
     * {@code (E(x + h e_k) - E(x - h e_k)) / (2 h)} for every k. x is changed during the call and
     * restored.
     */
    public static double[] gradient(ToDoubleFunction<double[]> energy, double[] x, double h) {
        double[] g = new double[x.length];
        for (int k = 0; k < x.length; k++) {
            double keep = x[k];
            x[k] = keep + h;
            double ep = energy.applyAsDouble(x);
            x[k] = keep - h;
            double em = energy.applyAsDouble(x);
            x[k] = keep;
            g[k] = (ep - em) / (2 * h);
        }
        return g;
    }

    /**
     * The derivative of {@code forces} at x along z by central differences of step h:
     * {@code (f(x + h z) - f(x - h z)) / (2 h)}; {@code forces.accept(x, f)} adds the forces at x to
     * f (given zeroed).
     */
    public static double[] directional(BiConsumer<double[], double[]> forces, double[] x, double[] z, double h) {
        double[] xp = x.clone();
        double[] xm = x.clone();
        for (int k = 0; k < x.length; k++) {
            xp[k] += h * z[k];
            xm[k] -= h * z[k];
        }
        double[] fp = new double[x.length];
        double[] fm = new double[x.length];
        forces.accept(xp, fp);
        forces.accept(xm, fm);
        double[] d = new double[x.length];
        for (int k = 0; k < x.length; k++) {
            d[k] = (fp[k] - fm[k]) / (2 * h);
        }
        return d;
    }

    /** The largest absolute component of v (0 for an empty v). */
    public static double maxAbs(double[] v) {
        double m = 0;
        for (double d : v) {
            m = Math.max(m, Math.abs(d));
        }
        return m;
    }

    /** A copy of x with {@code amplitude} times a standard normal draw of rnd added to each component. */
    public static double[] perturbed(double[] x, Random rnd, double amplitude) {
        double[] y = x.clone();
        for (int k = 0; k < y.length; k++) {
            y[k] += amplitude * rnd.nextGaussian();
        }
        return y;
    }
}
