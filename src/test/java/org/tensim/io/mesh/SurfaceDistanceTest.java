package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

class SurfaceDistanceTest {
    /** The unit square z = 0, 0 <= x, y <= 1, as two triangles. */
    private static final SurfaceDistance SQUARE = new SurfaceDistance(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0},
            new int[] {0, 1, 2, 0, 2, 3});

    @Test
    void distancesToAUnitSquareByRegion() {
        assertEquals(0.5, SQUARE.distance(0.3, 0.6, 0.5), 1e-15, "above the face");
        assertEquals(0.25, SQUARE.distance(0.5, 0.5, -0.25), 1e-15, "below the face");
        assertEquals(2, SQUARE.distance(3, 0.5, 0), 1e-15, "beside an edge");
        assertEquals(Math.sqrt(3), SQUARE.distance(2, 2, 1), 1e-15, "off a corner");
        assertEquals(0, SQUARE.distance(0.7, 0.7, 0), 1e-15, "on the diagonal shared by both triangles");
    }

    @Test
    void pruningGivesTheBruteForceMinimumOnARandomSurface() {
        Random r = new Random(5);
        int n = 400;
        double[] v = new double[9 * n];
        int[] t = new int[3 * n];
        for (int i = 0; i < v.length; i++) {
            v[i] = r.nextDouble() * 10;
        }
        for (int i = 0; i < t.length; i++) {
            t[i] = i;
        }
        SurfaceDistance all = new SurfaceDistance(v, t);
        for (int k = 0; k < 200; k++) {
            double x = r.nextDouble() * 12 - 1;
            double y = r.nextDouble() * 12 - 1;
            double z = r.nextDouble() * 12 - 1;
            double brute = Double.POSITIVE_INFINITY;
            for (int j = 0; j < n; j++) {
                double[] one = java.util.Arrays.copyOfRange(v, 9 * j, 9 * j + 9);
                brute = Math.min(brute, new SurfaceDistance(one, new int[] {0, 1, 2}).distance(x, y, z));
            }
            assertEquals(brute, all.distance(x, y, z), 0, "point " + k);
        }
    }

    @Test
    void percentileIsTheNearestRank() {
        double[] d = new double[100];
        for (int i = 0; i < 100; i++) {
            d[i] = 100 - i;
        }
        assertEquals(95, SurfaceDistance.percentile(d, 95));
        assertEquals(1, SurfaceDistance.percentile(new double[] {1}, 95));
    }
}
