package org.tensim.solver.stability;

/**
 * Linear stability theory of an integrator on one spring, m x'' = -k x - c x'. With
 * w = sqrt(k/m), zeta = c / (2 sqrt(k m)) and the step h, each method maps (x, v) to
 * A (x, v) with a 2 x 2 amplification matrix A(w h, zeta), taken from the method's
 * own description ({@link LinearStability#oscillatorStep}); the method is stable when
 * the spectral radius of A is at most 1.
 *
 * <p>Undamped limits (docs/physics.md): forward Euler and the two-stage RK2 never
 * (|R(i w h)| &gt; 1), symplectic Euler and velocity Verlet w h &lt; 2, classic RK4
 * w h &lt;= 2 sqrt(2), implicit Euler always; each method states its own
 * ({@link LinearStability#undampedLimit()}, computed from the stability polynomial
 * for Runge-Kutta methods).
 */
public final class StabilityTheory {
    private StabilityTheory() {
    }

    /**
     * The largest w h for which the method is stable on a spring of damping ratio
     * zeta: the method's own undamped limit at zeta = 0, else found by bisection on the
     * spectral radius between 1e-6 and 1e3; 0 when unstable at 1e-6, infinite when
     * stable at 1e3.
     */
    public static double criticalOmegaH(LinearStability method, double zeta) {
        if (zeta == 0) {
            return method.undampedLimit();
        }
        double lo = 1e-6;
        double hi = 1e3;
        if (!stable(method, lo, zeta)) {
            return 0;
        }
        if (stable(method, hi, zeta)) {
            return Double.POSITIVE_INFINITY;
        }
        // First crossing from below: scan up in small ratios, then bisect the bracket.
        double a = lo;
        double b = lo * 1.01;
        while (stable(method, b, zeta)) {
            a = b;
            b *= 1.01;
        }
        for (int i = 0; i < 60; i++) {
            double m = 0.5 * (a + b);
            if (stable(method, m, zeta)) {
                a = m;
            } else {
                b = m;
            }
        }
        return a;
    }

    /** Whether the spectral radius of A(w h, zeta) is at most 1 (+1e-12). */
    public static boolean stable(LinearStability method, double omegaH, double zeta) {
        return spectralRadius(amplification(method, omegaH, zeta)) <= 1 + 1e-12;
    }

    /**
     * The amplification matrix {a11, a12, a21, a22} acting on (x, v / w) for one
     * step of size h, with w = 1 (so h = w h); dimensionless.
     */
    public static double[] amplification(LinearStability method, double h, double zeta) {
        double[] c1 = method.oscillatorStep(h, zeta, 1, 0);
        double[] c2 = method.oscillatorStep(h, zeta, 0, 1);
        return new double[] {c1[0], c2[0], c1[1], c2[1]};
    }

    /** Spectral radius of a 2 x 2 matrix {a11, a12, a21, a22}. */
    public static double spectralRadius(double[] a) {
        double tr = a[0] + a[3];
        double det = a[0] * a[3] - a[1] * a[2];
        double disc = tr * tr / 4 - det;
        if (disc >= 0) {
            double s = Math.sqrt(disc);
            return Math.max(Math.abs(tr / 2 + s), Math.abs(tr / 2 - s));
        }
        return Math.sqrt(det); // complex pair: |lambda|^2 = det
    }
}
