package org.tensim.analysis.lungs;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;

/** The model's figures on a synthetic motion whose profile, magnitudes and time course are known by hand. */
class ModelFiguresTest {
    private static final double PERIOD = 4.0;

    /** Bin means of u over the points of {@code side} (null: both), from the analytic field. */
    private static double[] binMeans(SyntheticMotion f, String side) {
        double[] sum = new double[5];
        int[] n = new int[5];
        for (int i = 0; i < f.eta.length; i++) {
            if (side == null || f.lung[i].equals(side)) {
                int b = Math.min(4, (int) Math.floor(f.eta[i] * 5));
                sum[b] += f.u(i);
                n[b]++;
            }
        }
        for (int b = 0; b < 5; b++) {
            sum[b] /= n[b];
        }
        return sum;
    }

    private static double[] ratios(double[] means) {
        double[] r = new double[5];
        for (int b = 0; b < 5; b++) {
            r[b] = means[b] / means[4];
        }
        return r;
    }

    @Test
    void aLinearFieldGivesItsBinsRatiosBasalAndMean3dPerLungAndBoth() {
        // u = 2 mm + 10 mm eta on the right, 2 mm + 6 mm eta on the left; 1.5 mm sideways.
        SyntheticMotion f = new SyntheticMotion(0.002, 0.010, 0.006, 0.0015);
        double tEi = 1.0;
        ModelMotion m = f.motion(SyntheticMotion.cosine(tEi, PERIOD), 0.05, PERIOD, tEi + PERIOD / 2, tEi);
        ModelFigures fig = ModelFigures.of(m);
        double[] both = binMeans(f, null);
        // Both lungs' bin means are the mean of the two lungs' (each bin holds as many points of each).
        assertArrayEquals(both, fig.both().binMeanM(), 1e-12);
        assertArrayEquals(ratios(both), fig.both().ratio(), 1e-10);
        assertArrayEquals(ratios(binMeans(f, "right")), fig.right().ratio(), 1e-10);
        assertArrayEquals(ratios(binMeans(f, "left")), fig.left().ratio(), 1e-10);
        // The basal bin: the base point (eta 1) and 20 points evenly in [0.8, 1], mean eta (20 * 0.9 + 1) / 21.
        double basalEta = (SyntheticMotion.PER_BIN * 0.9 + 1) / (SyntheticMotion.PER_BIN + 1);
        assertEquals(0.002 + 0.010 * basalEta, fig.right().basalSiM(), 1e-12);
        assertEquals(0.002 + 0.008 * basalEta, fig.both().basalSiM(), 1e-12);
        double mean3d = 0;
        for (int i = 0; i < f.eta.length; i++) {
            mean3d += Math.hypot(f.u(i), f.c) / f.eta.length;
        }
        assertEquals(mean3d, fig.both().mean3dM(), 1e-12);
        assertEquals(SyntheticMotion.HEIGHT_M, fig.both().heightM(), 1e-12);
    }

    @Test
    void theSharesAreTheLawAtTheSixPhasesAndTheLawIsNormalisedAlike() {
        SyntheticMotion f = new SyntheticMotion(0.003, 0.009, 0.007, 0.001);
        // End-inhale at 3 s of a 4 s cycle sampled on [0, 3.95]: t10 (3.4 s) and t20 (3.8 s) lie within the
        // samples; t30-t50 (4.2-5 s) past them, taken one period back (0.2-1 s).
        double tEi = 3.0;
        DoubleUnaryOperator s = SyntheticMotion.cosine(tEi, PERIOD);
        ModelFigures fig = ModelFigures.of(f.motion(s, 0.05, PERIOD, tEi + PERIOD / 2, tEi));
        double[] expected = new double[6];
        for (int p = 0; p < 6; p++) {
            expected[p] = 0.5 * (1 + Math.cos(2 * Math.PI * p / 10.0));
            assertEquals(tEi + p / 10.0 * PERIOD, fig.phaseTimesS()[p], 1e-12);
        }
        assertArrayEquals(expected, fig.shares(), 1e-9);
        assertArrayEquals(expected, fig.sharesRight(), 1e-9);
        assertArrayEquals(expected, fig.sharesLeft(), 1e-9);
        assertArrayEquals(expected, fig.lawShares(), 1e-9);
    }

    @Test
    void anExhalationLongerThanHalfTheCycleLeavesT50ShortOfEndExhale() {
        // Inhalation over 40 % of the cycle (end-exhale at 0, end-inhale at 1.6 s), exhalation over 60 %: the
        // phase tNN is NN % of the cycle after end-inhale, so t50 (3.6 s) is still 1/6 of the way from exhale.
        double tEe = 0.0;
        double tEi = 1.6;
        DoubleUnaryOperator s = t -> {
            double u = ((t - tEe) % PERIOD + PERIOD) % PERIOD;
            return u <= tEi ? u / tEi : 1 - (u - tEi) / (PERIOD - tEi);
        };
        SyntheticMotion f = new SyntheticMotion(0.002, 0.01, 0.01, 0.0);
        ModelFigures fig = ModelFigures.of(f.motion(s, 0.05, PERIOD, tEe, tEi));
        double[] expected = new double[6];
        for (int p = 0; p < 6; p++) {
            expected[p] = 1 - p * 0.4 / 2.4;
        }
        assertArrayEquals(expected, fig.shares(), 1e-9);
        assertEquals(1 / 6.0, fig.shares()[5], 1e-9);
        assertArrayEquals(expected, fig.lawShares(), 1e-9);
    }

    @Test
    void theVerdictsAreTheModelsFiguresAgainstTheCasesRangesWidened() {
        SyntheticMotion model = new SyntheticMotion(0.001, 0.012, 0.012, 0.002);
        ModelFigures fig = ModelFigures.of(model.motion(SyntheticMotion.cosine(1, PERIOD), 0.05, PERIOD, 3, 1));
        // Two measured "cases" with known profiles: u = 4 mm eta + 1 mm and u = 8 mm eta (apex 0).
        List<MeasuredCase> cases = List.of(measured(1, 0.001, 0.004), measured(2, 0.0, 0.008));
        FourDctComparison c = FourDctComparison.of(fig, cases);
        assertEquals(4 + 2 + 4, c.verdicts().size());
        for (int b = 0; b < 4; b++) {
            FourDctComparison.Verdict v = c.verdicts().get(b);
            double r1 = cases.get(0).both().ratio()[b];
            double r2 = cases.get(1).both().ratio()[b];
            assertEquals("profile_bin" + (b + 1), v.name());
            assertEquals(fig.both().ratio()[b], v.value(), 0);
            assertEquals(Math.min(r1, r2) - 0.1, v.lo(), 1e-12);
            assertEquals(Math.max(r1, r2) + 0.1, v.hi(), 1e-12);
            assertEquals(v.value() >= v.lo() && v.value() <= v.hi(), v.pass());
        }
        FourDctComparison.Verdict basal = c.verdicts().get(4);
        assertEquals("basal_si_mm", basal.name());
        assertEquals(fig.both().basalSiM() * 1e3, basal.value(), 1e-12);
        assertEquals(6, basal.lo());
        assertEquals(20, basal.hi());
        // 1 mm + 12 mm eta: basal about 12 mm passes, the mean 3D about 7.3 mm too.
        assertTrue(basal.pass());
        assertTrue(c.verdicts().get(5).pass());
        // The cases' shares are 1 - p/5 (straight lines) and the model's the cosine: t20's 0.655 is within
        // 0.6 +/- 0.1, t10's 0.905 is not within 0.8 +/- 0.1.
        assertEquals("share_t10", c.verdicts().get(6).name());
        assertFalse(c.verdicts().get(6).pass());
        assertTrue(c.verdicts().get(7).pass());
        assertEquals(0.8 - 0.1, c.verdicts().get(6).lo(), 1e-12);
        assertEquals(c.verdicts().stream().filter(FourDctComparison.Verdict::pass).count(), c.passed());
        assertNull(((java.util.Map<?, ?>) c.toMap().get("cases")).get("case3"));
    }

    /** A case whose 300 "landmarks" move u = a + b eta (three axes' frame: superior -z, as DIR-Lab's). */
    private static MeasuredCase measured(int n, double a, double b) {
        int pts = 100;
        double[] x = new double[3 * pts];
        double[] d = new double[3 * pts];
        double[][] six = new double[6][3 * pts];
        for (int i = 0; i < pts; i++) {
            double eta = i / (pts - 1.0);
            x[3 * i] = (i % 2 == 0 ? -0.1 : 0.1);
            x[3 * i + 2] = 0.2 * eta; // z towards the feet
            d[3 * i + 2] = a + b * eta;
            for (int p = 0; p < 6; p++) {
                System.arraycopy(x, 3 * i, six[p], 3 * i, 3);
                six[p][3 * i + 2] += (1 - p / 5.0) * d[3 * i + 2];
            }
        }
        double[] up = {0, 0, -1};
        SiProfile both = SiProfile.of(x, d, up, null);
        LungSplit split = LungSplit.of(x, 0);
        double[] shares = PhaseShares.of(six, 5, 0);
        return new MeasuredCase(n, both, SiProfile.of(x, d, up, split.low()), SiProfile.of(x, d, up, split.high()),
                split, shares, shares, shares);
    }

    @Test
    void aMotionThatDoesNotSpanACycleOrHasNoInhalationIsRefused() {
        SyntheticMotion f = new SyntheticMotion(0.002, 0.01, 0.01, 0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ModelFigures.of(f.motion(t -> 0, 0.05, PERIOD, 0, 2)));
        assertTrue(e.getMessage().contains("at both end-exhale and end-inhale: no share"), e.getMessage());
        ModelMotion ok = f.motion(SyntheticMotion.cosine(1, PERIOD), 0.05, PERIOD, 3, 1);
        e = assertThrows(IllegalArgumentException.class, () -> new ModelMotion(
                java.util.Arrays.copyOf(ok.timesS(), 40), java.util.Arrays.copyOf(ok.positionsM(), 40), ok.lung(),
                3, 1, PERIOD, ok.superior()));
        assertTrue(e.getMessage().contains("less than the period 4.0 s"), e.getMessage());
    }
}
