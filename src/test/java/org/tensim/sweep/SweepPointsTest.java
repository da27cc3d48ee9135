package org.tensim.sweep;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class SweepPointsTest {
    @Test
    void gridIsTheCartesianProductLastParameterFastest() {
        List<Point> p = SweepPoints.grid(List.of(new SweepSpec.Range("a", 0, 1, 3, null),
                new SweepSpec.Range("b", Double.NaN, Double.NaN, 2, new double[] {5, 7})));
        assertEquals(6, p.size());
        assertArrayEquals(new double[] {0, 5}, p.get(0).values());
        assertArrayEquals(new double[] {0, 7}, p.get(1).values());
        assertArrayEquals(new double[] {0.5, 5}, p.get(2).values());
        assertArrayEquals(new double[] {1, 7}, p.get(5).values());
        for (int i = 0; i < p.size(); i++) {
            assertEquals(i, p.get(i).id());
        }
    }

    @Test
    void latinHypercubeUsesEveryStratumOnceAndRepeatsWithItsSeed() {
        List<SweepSpec.Range> r = List.of(new SweepSpec.Range("a", 10, 20, 1, null),
                new SweepSpec.Range("b", -1, 1, 1, null));
        int n = 16;
        List<Point> p = SweepPoints.latinHypercube(r, n, 42);
        for (int d = 0; d < 2; d++) {
            boolean[] used = new boolean[n];
            for (Point q : p) {
                SweepSpec.Range g = r.get(d);
                double u = (q.values()[d] - g.min()) / (g.max() - g.min());
                assertTrue(u >= 0 && u <= 1);
                int stratum = Math.min(n - 1, (int) Math.floor(u * n));
                assertTrue(!used[stratum], "stratum " + stratum + " of parameter " + d + " used twice");
                used[stratum] = true;
            }
        }
        List<Point> again = SweepPoints.latinHypercube(r, n, 42);
        List<Point> other = SweepPoints.latinHypercube(r, n, 43);
        boolean differs = false;
        for (int i = 0; i < n; i++) {
            assertArrayEquals(p.get(i).values(), again.get(i).values());
            differs |= !java.util.Arrays.equals(p.get(i).values(), other.get(i).values());
        }
        assertTrue(differs, "another seed gives other points");
    }
}
