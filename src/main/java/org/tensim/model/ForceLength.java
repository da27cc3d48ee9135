package org.tensim.model;

/**
 * The active force-length relation of skeletal muscle: the share {@code f_L(lambda)} of the
 * maximal active stress a fibre develops at stretch lambda (its length over the optimal length,
 * which is taken as the rest length of the mesh). The ascending limb is Blemker, Pinsky and Delp's
 * piecewise quadratic fit to the sarcomere force-length curve (J Biomech 38:657, 2005, eq. 9;
 * after Gordon, Huxley and Julian, J Physiol 184:170, 1966), the descending limb is left out:
 *
 * <pre>
 *   f_L = 0                      lambda &lt;= 0.4
 *   f_L = 9 (lambda - 0.4)^2     0.4 &lt; lambda &lt;= 0.6
 *   f_L = 1 - 4 (1 - lambda)^2   0.6 &lt; lambda &lt; 1
 *   f_L = 1                      lambda &gt;= 1 (the plateau)
 * </pre>
 *
 * <p>Why it matters: a constant active stress has no limit on how far it shortens a fibre, and a
 * St Venant-Kirchhoff membrane ({@link TriangleElement}) resists compression less and less below
 * a stretch of {@code 1/sqrt(3) = 0.58} (its uniaxial stress {@code E (lambda^3 - lambda) / 2} peaks
 * there at {@code -0.19 E}, 7.7 kPa for the muscle's 40 kPa). Where an active stress above that is
 * not carried by the structure, a triangle collapses through zero length and inverts. With f_L the
 * active tension falls as the fibre shortens, and its slope adds {@code sigma_a f_L'} to the
 * fibre's stiffness: the total stress {@code P(lambda) + sigma_a f_L(lambda)} rises with lambda
 * wherever the active stress is large enough to matter. Above the optimal length the descending
 * limb is replaced by the plateau: the passive tissue dominates there, and a negative active
 * stiffness would make the implicit integrators' Newton matrix indefinite.
 */
public final class ForceLength {
    /** Below this stretch a fibre develops no active force. */
    public static final double MIN_STRETCH = 0.4;
    private static final double KNEE = 0.6;
    /** The integral of f_L from 0 to 1. */
    private static final double INTEGRAL_TO_1 = 3 * cube(KNEE - MIN_STRETCH) + (1 - KNEE) - 4.0 / 3 * cube(1 - KNEE);

    private ForceLength() {
    }

    /** f_L(lambda), in [0, 1]. */
    public static double value(double lambda) {
        if (lambda >= 1) {
            return 1;
        }
        if (lambda > KNEE) {
            double d = 1 - lambda;
            return 1 - 4 * d * d;
        }
        if (lambda > MIN_STRETCH) {
            double d = lambda - MIN_STRETCH;
            return 9 * d * d;
        }
        return 0;
    }

    /** The slope df_L/dlambda (&gt;= 0). */
    public static double slope(double lambda) {
        if (lambda >= 1) {
            return 0;
        }
        if (lambda > KNEE) {
            return 8 * (1 - lambda);
        }
        if (lambda > MIN_STRETCH) {
            return 18 * (lambda - MIN_STRETCH);
        }
        return 0;
    }

    /** The integral of f_L from 0 to lambda: the active energy per unit of {@code sigma_a} and volume. */
    public static double integral(double lambda) {
        if (lambda >= 1) {
            return INTEGRAL_TO_1 + (lambda - 1);
        }
        if (lambda > KNEE) {
            return 3 * cube(KNEE - MIN_STRETCH) + (lambda - KNEE) + 4.0 / 3 * (cube(1 - lambda) - cube(1 - KNEE));
        }
        if (lambda > MIN_STRETCH) {
            return 3 * cube(lambda - MIN_STRETCH);
        }
        return 0;
    }

    private static double cube(double x) {
        return x * x * x;
    }
}
