package org.tensim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The active force-length relation ({@link ForceLength}): the published curve's points, continuity,
 * the slope as the derivative of the value and the integral as its antiderivative, a non-negative
 * slope (the ascending limb stiffens the fibre; no descending limb).
 */
class ForceLengthTest {
    @Test
    void theCurvePassesThroughBlemkersPoints() {
        // Blemker, Pinsky and Delp 2005, eq. 9: 9 (l - 0.4)^2 up to 0.6, 1 - 4 (1 - l)^2 up to the optimum.
        assertEquals(0, ForceLength.value(0.4), 0);
        assertEquals(0.36, ForceLength.value(0.6), 1e-12);
        assertEquals(1 - 4 * 0.15 * 0.15, ForceLength.value(0.85), 1e-12);
        assertEquals(1, ForceLength.value(1), 0);
        assertEquals(1, ForceLength.value(1.5), 0, "the plateau above the optimal length");
        assertEquals(0, ForceLength.value(0.1), 0, "no active force below 0.4");
        assertEquals(0, ForceLength.value(-0.2), 0);
    }

    @Test
    void slopeIsTheDerivativeAndIntegralTheAntiderivative() {
        double h = 1e-6;
        for (double l = 0.05; l < 1.6; l += 0.0137) {
            double dv = (ForceLength.value(l + h) - ForceLength.value(l - h)) / (2 * h);
            assertEquals(dv, ForceLength.slope(l), 1e-5, "slope at " + l);
            double di = (ForceLength.integral(l + h) - ForceLength.integral(l - h)) / (2 * h);
            assertEquals(ForceLength.value(l), di, 1e-6, "integral at " + l);
            assertTrue(ForceLength.slope(l) >= 0, "non-negative slope at " + l);
            double v = ForceLength.value(l);
            assertTrue(v >= 0 && v <= 1, "value in [0, 1] at " + l);
        }
    }

    @Test
    void valueAndIntegralAreContinuousAtTheBreakpoints() {
        for (double b : new double[] {0.4, 0.6, 1.0}) {
            double e = 1e-9;
            assertEquals(ForceLength.value(b - e), ForceLength.value(b + e), 1e-7, "value at " + b);
            assertEquals(ForceLength.integral(b - e), ForceLength.integral(b + e), 1e-8, "integral at " + b);
        }
        // The integral over the whole ascending limb, by Simpson's rule on a fine grid.
        int n = 20_000;
        double sum = 0;
        for (int i = 0; i <= n; i++) {
            double w = i == 0 || i == n ? 1 : i % 2 == 1 ? 4 : 2;
            sum += w * ForceLength.value(i / (double) n);
        }
        assertEquals(sum / (3.0 * n), ForceLength.integral(1), 1e-9);
    }
}
