package org.tensim.analysis.lungs;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

class SiProfileTest {
    /** A tilted frame: the head along (0.6, 0, 0.8), so that no axis is the superior one. */
    private static final double[] UP = {0.6, 0, 0.8};
    private static final double[] SIDE = {0, 1, 0};
    private static final double[] FRONT = {0.8, 0, -0.6};

    /** Points at height fraction eta (0 apex .. 1 base) of a 0.2 m cloud, scattered sideways. */
    private static double[] point(double eta, double a, double b) {
        double s = 0.2 * (1 - eta);
        double[] p = new double[3];
        for (int k = 0; k < 3; k++) {
            p[k] = s * UP[k] + a * SIDE[k] + b * FRONT[k] + 0.05;
        }
        return p;
    }

    @Test
    void aFieldMadeToMatchAProfileGivesThatProfile() {
        // Inferior displacement u(eta) = 12 mm * eta^2 plus a sideways part; the bins' means of eta^2 are known
        // when the points are evenly spread within each bin: mean of eta^2 over [b/5, (b+1)/5].
        Random r = new Random(7);
        int perBin = 400;
        int n = 5 * perBin;
        double[] x = new double[3 * n];
        double[] d = new double[3 * n];
        double[] expected = new double[5];
        double mean3d = 0;
        for (int b = 0; b < 5; b++) {
            for (int k = 0; k < perBin; k++) {
                int i = b * perBin + k;
                // Midpoints of perBin equal sub-intervals of the bin, the apex and base points themselves first.
                double eta = (b + (k + 0.5) / perBin) / 5;
                if (i == 0) {
                    eta = 0;
                } else if (i == n - 1) {
                    eta = 1;
                }
                double[] p = point(eta, r.nextDouble() * 0.1, r.nextDouble() * 0.1);
                double u = 0.012 * eta * eta;
                double side = 0.002 * r.nextDouble();
                for (int a = 0; a < 3; a++) {
                    x[3 * i + a] = p[a];
                    d[3 * i + a] = -u * UP[a] + side * SIDE[a];
                }
                expected[b] += u / perBin;
                mean3d += Math.sqrt(u * u + side * side) / n;
            }
        }
        SiProfile p = SiProfile.of(x, d, UP, null);
        assertArrayEquals(new int[] {perBin, perBin, perBin, perBin, perBin}, p.binCount());
        assertArrayEquals(expected, p.binMeanM(), 1e-12);
        // The bins' means of eta^2 over [b/5, (b+1)/5] with the midpoint rule's error: within 1e-6 of
        // (3b^2 + 3b + 1) / 75, so the ratios to the basal bin's 61/75 are (3b^2 + 3b + 1) / 61.
        double[] law = {1.0 / 61, 7.0 / 61, 19.0 / 61, 37.0 / 61, 1};
        assertArrayEquals(law, p.ratio(), 1e-4);
        assertEquals(0.012 * 61 / 75, p.basalSiM(), 1e-6);
        assertEquals(mean3d, p.mean3dM(), 1e-12);
        assertEquals(0.2, p.heightM(), 1e-12);
        assertArrayEquals(java.util.Arrays.copyOf(p.ratio(), 4), p.ratiosAboveBase());
    }

    @Test
    void aRigidShiftIsFlatAndTheLowestFifthByCountIsTheLowestPoints() {
        // 10 points, the lowest 2 by count moving 5 mm down, the rest 1 mm: bins by height differ from fifths.
        int n = 10;
        double[] etas = {0, 0.1, 0.32, 0.5, 0.55, 0.62, 0.7, 0.75, 0.95, 1};
        double[] x = new double[3 * n];
        double[] d = new double[3 * n];
        for (int i = 0; i < n; i++) {
            double[] p = point(etas[i], 0.01 * i, 0);
            System.arraycopy(p, 0, x, 3 * i, 3);
            double u = i >= 8 ? 0.005 : 0.001;
            for (int a = 0; a < 3; a++) {
                d[3 * i + a] = -u * UP[a];
            }
        }
        SiProfile p = SiProfile.of(x, d, UP, null);
        assertArrayEquals(new int[] {2, 1, 2, 3, 2}, p.binCount());
        assertEquals(0.005, p.basalSiM(), 1e-15);
        assertEquals(0.005, p.lowestFifthByCountM(), 1e-15);
        assertArrayEquals(new double[] {0.2, 0.2, 0.2, 0.2, 1}, p.ratio(), 1e-12);
        // A subset: only the first 8 points, whose lowest (eta 0.75) is now their own base.
        SiProfile q = SiProfile.of(x, d, UP, new int[] {0, 1, 2, 3, 4, 5, 6, 7});
        assertEquals(8, q.points());
        assertEquals(0.001, q.basalSiM(), 1e-15);
        // Heights 0, 0.13, 0.43, 0.67, 0.73, 0.83, 0.93, 1 of the subset's own: its second bin is empty, its mean
        // and ratio NaN.
        assertArrayEquals(new int[] {2, 0, 1, 2, 3}, q.binCount());
        assertArrayEquals(new double[] {1, Double.NaN, 1, 1, 1}, q.ratio(), 1e-12);
    }

    @Test
    void aFlatCloudIsRefused() {
        double[] x = {0, 0, 1, 1, 0, 1};
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SiProfile.of(x, new double[6], new double[] {0, 0, 1}, null));
        assertEquals("the 2 points have no height along the superior direction (all at 1.0 m): expected a cloud"
                + " spanning apex to base", e.getMessage());
    }
}
