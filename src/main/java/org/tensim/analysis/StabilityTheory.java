package org.tensim.analysis;

/**
 * Linear stability theory of the integrators on one spring, m x'' = -k x - c x',
 * written from each method's formulas independently of its implementation. With
 * w = sqrt(k/m), zeta = c / (2 sqrt(k m)) and the step h, each method maps
 * (x, v) to A (x, v) with a 2 x 2 amplification matrix A(w h, zeta); the method is
 * stable when the spectral radius of A is at most 1.
 *
 * <p>Undamped limits (PHYSICS.md): forward Euler and the two-stage RK2 never
 * (|R(i w h)| &gt; 1), symplectic Euler and velocity Verlet w h &lt; 2, classic RK4
 * w h &lt;= 2 sqrt(2), implicit Euler always.
 */
public final class StabilityTheory {
    private StabilityTheory() {
    }

    /** Theoretical undamped limit of w h for an integrator name (0 never stable, infinite always). */
    public static double undampedLimit(String integrator) {
        return criticalOmegaH(integrator, 0);
    }

    /**
     * The largest w h for which the method is stable on a spring of damping ratio
     * zeta, found by bisection on the spectral radius between 1e-6 and 1e3; 0 when
     * unstable at 1e-6, infinite when stable at 1e3.
     */
    public static double criticalOmegaH(String integrator, double zeta) {
        // Closed forms where the bisection could not reach them exactly.
        if (zeta == 0) {
            switch (integrator) {
                case "euler", "rk2", "heun":
                    return 0;
                case "symplectic-euler", "verlet":
                    return 2;
                case "rk4":
                    return 2 * Math.sqrt(2);
                case "implicit-euler":
                    return Double.POSITIVE_INFINITY;
                default:
                    break;
            }
        }
        double lo = 1e-6;
        double hi = 1e3;
        if (!stable(integrator, lo, zeta)) {
            return 0;
        }
        if (stable(integrator, hi, zeta)) {
            return Double.POSITIVE_INFINITY;
        }
        // First crossing from below: scan up in small ratios, then bisect the bracket.
        double a = lo;
        double b = lo * 1.01;
        while (stable(integrator, b, zeta)) {
            a = b;
            b *= 1.01;
        }
        for (int i = 0; i < 60; i++) {
            double m = 0.5 * (a + b);
            if (stable(integrator, m, zeta)) {
                a = m;
            } else {
                b = m;
            }
        }
        return a;
    }

    /** Whether the spectral radius of A(w h, zeta) is at most 1 (+1e-12). */
    public static boolean stable(String integrator, double omegaH, double zeta) {
        return spectralRadius(amplification(integrator, omegaH, zeta)) <= 1 + 1e-12;
    }

    /**
     * The amplification matrix {a11, a12, a21, a22} acting on (x, v / w) for one
     * step of size h, with w = 1 (so h = w h); dimensionless.
     */
    public static double[] amplification(String integrator, double h, double zeta) {
        double[] c1 = step(integrator, h, zeta, 1, 0);
        double[] c2 = step(integrator, h, zeta, 0, 1);
        return new double[] {c1[0], c2[0], c1[1], c2[1]};
    }

    /** One step of the method on x'' = -x - 2 zeta x' (w = 1) from (x, v). */
    private static double[] step(String integrator, double h, double zeta, double x, double v) {
        double c = 2 * zeta;
        switch (integrator) {
            case "euler": {
                double a = -x - c * v;
                return new double[] {x + h * v, v + h * a};
            }
            case "symplectic-euler": {
                double v1 = v + h * (-x - c * v);
                return new double[] {x + h * v1, v1};
            }
            case "rk2": {
                double a1 = -x - c * v;
                double xm = x + h / 2 * v;
                double vm = v + h / 2 * a1;
                return new double[] {x + h * vm, v + h * (-xm - c * vm)};
            }
            case "heun": {
                double a1 = -x - c * v;
                double xp = x + h * v;
                double vp = v + h * a1;
                return new double[] {x + h / 2 * (v + vp), v + h / 2 * (a1 + (-xp - c * vp))};
            }
            case "rk4": {
                double a1 = -x - c * v;
                double x2 = x + h / 2 * v;
                double v2 = v + h / 2 * a1;
                double a2 = -x2 - c * v2;
                double x3 = x + h / 2 * v2;
                double v3 = v + h / 2 * a2;
                double a3 = -x3 - c * v3;
                double x4 = x + h * v3;
                double v4 = v + h * a3;
                double a4 = -x4 - c * v4;
                return new double[] {x + h / 6 * (v + 2 * v2 + 2 * v3 + v4), v + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)};
            }
            case "verlet": {
                double a0 = -x - c * v;
                double vh = v + h / 2 * a0;
                double x1 = x + h * vh;
                double a1 = -x1 - c * (v + h * a0);
                return new double[] {x1, vh + h / 2 * a1};
            }
            case "implicit-euler": {
                // (1 + h c + h^2) v1 = v - h x ; x1 = x + h v1
                double v1 = (v - h * x) / (1 + h * c + h * h);
                return new double[] {x + h * v1, v1};
            }
            default:
                throw new IllegalArgumentException("no stability theory for integrator '" + integrator + "'");
        }
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
