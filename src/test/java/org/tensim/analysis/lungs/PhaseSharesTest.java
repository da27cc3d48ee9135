package org.tensim.analysis.lungs;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

class PhaseSharesTest {
    @Test
    void aFieldThatKeepsItsShapeGivesItsLawsShares() {
        // Six phases, t00 end-inhale to t50 end-exhale, on the cosine law (1 + cos(pi p / 5)) / 2 of a breath's
        // exhalation; every point's displacement from end-exhale is the law times its own end-inhale one.
        Random r = new Random(11);
        int n = 50;
        double[] x0 = new double[3 * n];
        double[] big = new double[3 * n];
        for (int k = 0; k < 3 * n; k++) {
            x0[k] = r.nextDouble() * 0.2;
            big[k] = (r.nextDouble() - 0.3) * 0.01;
        }
        double[] law = new double[6];
        double[][] pos = new double[6][3 * n];
        for (int p = 0; p < 6; p++) {
            law[p] = (1 + Math.cos(Math.PI * p / 5)) / 2;
            for (int k = 0; k < 3 * n; k++) {
                pos[p][k] = x0[k] + law[p] * big[k];
            }
        }
        double[] s = PhaseShares.of(pos, 5, 0);
        assertArrayEquals(law, s, 1e-12);
        assertEquals(1, s[0], 1e-15);
        assertEquals(0, s[5], 1e-15);
    }

    @Test
    void aPartOrthogonalToTheEndInhaleFieldDoesNotCount() {
        // Two points: end-inhale field (1, 0, 0) and (0, 1, 0) mm; at the phase, half of it plus a motion along z
        // and +0.2 mm along the first point's field with -0.2 mm along the second's, which cancel.
        double[][] pos = {
            {0.001, 0, 0, 0, 0.001, 0},
            {0.0005 + 0.0002, 0, 0.003, 0, 0.0005 - 0.0002, -0.001},
            {0, 0, 0, 0, 0, 0}};
        double[] s = PhaseShares.of(pos, 2, 0);
        assertEquals(0.5, s[1], 1e-12);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> PhaseShares.of(new double[][] {{0, 0, 0}, {0, 0, 0}}, 1, 0));
        assertEquals("the points do not move from end-exhale to end-inhale: no share of it can be taken",
                e.getMessage());
    }

    @Test
    void twoCloudsAreSplitAtTheGapBetweenThem() {
        // 20 points at x in [0, 0.1), 30 in [0.15, 0.25]: the gap's middle is at 0.125 m or so.
        Random r = new Random(3);
        double[] x = new double[3 * 50];
        double lowMax = 0;
        double highMin = 1;
        for (int i = 0; i < 50; i++) {
            double v = i < 20 ? r.nextDouble() * 0.1 : 0.15 + r.nextDouble() * 0.1;
            x[3 * i] = v;
            x[3 * i + 1] = r.nextDouble();
            x[3 * i + 2] = r.nextDouble();
            if (i < 20) {
                lowMax = Math.max(lowMax, v);
            } else {
                highMin = Math.min(highMin, v);
            }
        }
        LungSplit s = LungSplit.of(x, 0);
        assertEquals(20, s.low().length);
        assertEquals(30, s.high().length);
        assertEquals((lowMax + highMin) / 2, s.planeM(), 1e-15);
        assertEquals(highMin - lowMax, s.gapM(), 1e-15);
        assertArrayEquals(java.util.stream.IntStream.range(0, 20).toArray(), s.low());
    }
}
