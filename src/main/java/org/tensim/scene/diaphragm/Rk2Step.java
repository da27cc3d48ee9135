package org.tensim.scene.diaphragm;

/**
 * The largest stable time step of the paper's RK2 (explicit midpoint) for a network
 * whose modes have angular frequencies up to {@code w_max} and Rayleigh damping
 * (axial spring damping {@code beta k}, viscous damping {@code alpha m}): a mode of
 * frequency w then has the damping ratio {@code zeta(w) = beta w / 2 + alpha / (2 w)}
 * and the eigenvalues {@code lambda = w (-zeta +/- i sqrt(1 - zeta^2))}; RK2 is
 * stable when {@code |1 + z + z^2 / 2| <= 1} for {@code z = h lambda} of every mode.
 * The step is found by bisection on h, checking modes from {@code w_max / 1000} to
 * {@code w_max}. Without damping there is no stable step (PHYSICS.md); with
 * {@code zeta(w_max) = 0.3} it is about {@code 1.5 / w_max}.
 */
public final class Rk2Step {
    /** Factor applied to the stable step in use (the Gershgorin bound already overestimates w_max). */
    public static final double SAFETY = 0.8;

    private Rk2Step() {
    }

    /** The largest stable h, s (0 when no step is stable). */
    public static double stable(double omegaMax, double beta, double alpha) {
        double lo = 0;
        double hi = 4 / omegaMax;
        for (int it = 0; it < 60; it++) {
            double h = 0.5 * (lo + hi);
            if (stableAt(h, omegaMax, beta, alpha)) {
                lo = h;
            } else {
                hi = h;
            }
        }
        return lo;
    }

    static boolean stableAt(double h, double omegaMax, double beta, double alpha) {
        for (int i = 0; i <= 400; i++) {
            double w = omegaMax * Math.pow(1e-3, 1 - i / 400.0);
            double zeta = beta * w / 2 + alpha / (2 * w);
            double re;
            double im;
            if (zeta >= 1) {
                re = -w * (zeta - Math.sqrt(zeta * zeta - 1)); // the slower real root is the tighter one for RK2
                im = 0;
                double re2 = -w * (zeta + Math.sqrt(zeta * zeta - 1));
                if (amplification(h * re2, 0) > 1 + 1e-12) {
                    return false;
                }
            } else {
                re = -w * zeta;
                im = w * Math.sqrt(1 - zeta * zeta);
            }
            if (amplification(h * re, h * im) > 1 + 1e-12) {
                return false;
            }
        }
        return true;
    }

    /** |1 + z + z^2 / 2| for z = x + i y. */
    static double amplification(double x, double y) {
        double re = 1 + x + 0.5 * (x * x - y * y);
        double im = y + x * y;
        return Math.hypot(re, im);
    }
}
