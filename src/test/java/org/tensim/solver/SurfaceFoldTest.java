package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.solver.SurfaceSliding.Mode;

/**
 * A follower passing over a fold: two triangles meeting at a ridge along the y axis, one flat (z = 0, x < 0), one
 * sloping down at 40 degrees (x > 0). Its distance to the surface is h over the flat face, the distance to the ridge
 * in the ridge's own region, and the sloping plane's beyond, continuous throughout; the term's distance must be
 * that one, not the extended plane of whichever triangle it is paired with (which jumps by h (sqrt(1 + t^2) - 1),
 * 6 cm here, where the pairing moves), and its forces minus its energy's gradient there too.
 */
class SurfaceFoldTest {
    private static final double T = Math.tan(Math.toRadians(40));
    private static final double H = 0.2;
    private static final double K = 50;

    /** Nodes 0-3 the surface's corners, node 4 the follower at (fx, 0, fz). */
    private static double[] state(double fx, double fz) {
        return new double[] {0, -1, 0, 0, 1, 0, -1, 0, 0, 1, 0, -T, fx, 0, fz};
    }

    private static SurfaceSliding term(Mode mode, double gap, double[] x) {
        LinearMapping.Builder b = new LinearMapping.Builder(5);
        for (int i = 0; i < 4; i++) {
            b.add(new int[] {i}, new double[] {1});
        }
        // Flat (0, 1, 2), normal +z; sloping (1, 0, 3), normal (t, 0, 1) / sqrt(1 + t^2): both outward (up).
        return new SurfaceSliding(new int[] {4}, b.build(), new int[] {0, 1, 2, 1, 0, 3}, new double[] {K}, mode, gap,
                x);
    }

    /** The exact signed distance of (x, 0, H) to the fold. */
    private static double exact(double x) {
        if (x <= 0) {
            return H;
        }
        if (x <= H * T) {
            return Math.hypot(x, H);
        }
        return (T * x + H) / Math.sqrt(1 + T * T);
    }

    @Test
    void theDistanceIsTheSurfacesOwnAndContinuousWhereThePairingMoves() {
        double[] x = state(-0.3, H);
        SurfaceSliding s = term(Mode.SLIDING, 0, x);
        double[] d = new double[1];
        double previous = Double.NaN;
        int pairings = 0;
        int last = -1;
        for (int i = 0; i <= 900; i++) {
            double fx = -0.3 + i * 0.001;
            x = state(fx, H);
            s.addForces(0, x, new double[15], new double[15]); // the force pass moves the pairing along
            s.distancesM(x, d);
            assertEquals(exact(fx), d[0], 1e-12, "at x = " + fx);
            if (i > 0) {
                assertTrue(Math.abs(d[0] - previous) < 2e-3, "continuous at x = " + fx + ": " + previous + " -> "
                        + d[0]);
            }
            previous = d[0];
            if (s.pairedTriangle(0) != last) {
                pairings++;
                last = s.pairedTriangle(0);
            }
        }
        assertEquals(2, pairings, "the follower passed from the flat triangle to the sloping one");
    }

    @Test
    void overTheRidgeTheForceIsAlongTheRidgesNormalAndMinusTheGradient() {
        for (Mode mode : Mode.values()) {
            double fx = 0.5 * H * T; // in the ridge's region
            double gap = 0.3; // touching: pushed out along the ridge's normal
            double[] x = state(fx, H);
            SurfaceSliding s = term(mode, gap, x);
            double[] f = new double[15];
            s.addForces(0, x, new double[15], f);
            double r = Math.hypot(fx, H);
            double pen = gap - r;
            assertEquals(K * pen * fx / r, f[12], 1e-12, mode + ": the follower's x force");
            assertEquals(K * pen * H / r, f[14], 1e-12, mode + ": the follower's z force");
            assertEquals(0, f[13], 1e-12);
            for (int k = 0; k < 15; k++) {
                double eps = 1e-7;
                double[] xp = x.clone();
                double[] xm = x.clone();
                xp[k] += eps;
                xm[k] -= eps;
                double grad = (s.energy(0, xp) - s.energy(0, xm)) / (2 * eps);
                assertEquals(-grad, f[k], 1e-6 * K, mode + ": coordinate " + k + " is minus the gradient");
            }
            double sum = 0;
            for (int k = 0; k < 15; k += 3) {
                sum += f[k];
            }
            assertEquals(0, sum, 1e-12, "the ridge's corners take the follower's reaction");
        }
    }
}
