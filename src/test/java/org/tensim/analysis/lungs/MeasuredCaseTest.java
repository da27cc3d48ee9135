package org.tensim.analysis.lungs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.Locale;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.tensim.testsupport.SharedData;

/**
 * The five DIR-Lab cases' figures, against the ranges docs/lungs.md quotes from them: basal SI
 * 7.6-14.7 mm, mean 3D 3.9-9.8 mm, ratios of the four bins above the base 0.0-0.17, 0.16-0.51, 0.32-0.75,
 * 0.67-0.98 (the extremes over the cases, to two decimals). Prints each case's figures.
 */
class MeasuredCaseTest {
    private static final double[][] RATIO_RANGE = {{0.0, 0.17}, {0.16, 0.51}, {0.32, 0.75}, {0.67, 0.98}};

    @Test
    void theFiveCasesSpanTheQuotedRanges() throws Exception {
        for (int n = 1; n <= 5; n++) {
            Path300.check(n);
        }
        double[] lo = {1, 1, 1, 1};
        double[] hi = {0, 0, 0, 0};
        double basalLo = 1;
        double basalHi = 0;
        double meanLo = 1;
        double meanHi = 0;
        for (int n = 1; n <= 5; n++) {
            MeasuredCase c = MeasuredCase.read(SharedData.LUNG_LANDMARKS, n);
            SiProfile p = c.both();
            double[] r = p.ratiosAboveBase();
            System.out.println(String.format(Locale.ROOT, "case %d: ratios %.3f %.3f %.3f %.3f, basal SI %.2f mm,"
                    + " mean 3D %.2f mm, shares t10-t40 %.3f %.3f %.3f %.3f", n, r[0], r[1], r[2], r[3],
                    p.basalSiM() * 1e3, p.mean3dM() * 1e3, c.shares()[1], c.shares()[2], c.shares()[3],
                    c.shares()[4]));
            for (int b = 0; b < 4; b++) {
                lo[b] = Math.min(lo[b], r[b]);
                hi[b] = Math.max(hi[b], r[b]);
            }
            basalLo = Math.min(basalLo, p.basalSiM());
            basalHi = Math.max(basalHi, p.basalSiM());
            meanLo = Math.min(meanLo, p.mean3dM());
            meanHi = Math.max(meanHi, p.mean3dM());
            // Shares: 1 at end-inhale, 0 at end-exhale, and falling through the exhalation in every case.
            assertEquals(1, c.shares()[0], 1e-12);
            assertEquals(0, c.shares()[5], 1e-12);
            for (int k = 1; k < 6; k++) {
                assertTrue(c.shares()[k] < c.shares()[k - 1] + 1e-9, "case " + n + " share t" + k + "0");
            }
            // The SI motion falls from base to apex: each bin below the one under it (within 0.05, as case 3's
            // low-x lung shows measured noise of that size at the base).
            for (int b = 1; b < 5; b++) {
                assertTrue(p.ratio()[b - 1] < p.ratio()[b] + 0.05, "case " + n + " bin " + b);
            }
            assertEquals(300, c.lowX().points() + c.highX().points());
        }
        for (int b = 0; b < 4; b++) {
            assertEquals(RATIO_RANGE[b][0], lo[b], 0.005, "lowest ratio of bin " + (b + 1));
            assertEquals(RATIO_RANGE[b][1], hi[b], 0.005, "highest ratio of bin " + (b + 1));
        }
        assertEquals(7.6, basalLo * 1e3, 0.05, "lowest basal SI, mm");
        assertEquals(14.7, basalHi * 1e3, 0.05, "highest basal SI, mm");
        assertEquals(3.9, meanLo * 1e3, 0.05, "lowest mean 3D, mm");
        assertEquals(9.8, meanHi * 1e3, 0.05, "highest mean 3D, mm");
    }

    /** Skips, naming the file, where a shared case is absent. */
    private static final class Path300 {
        static void check(int n) {
            for (String f : new String[] {"case" + n + "-300-ee-ei.csv", "case" + n + "-75-six-phases.csv"}) {
                java.nio.file.Path p = SharedData.LUNG_LANDMARKS.resolve(f);
                Assumptions.assumeTrue(Files.isRegularFile(p), p.toAbsolutePath() + " not found");
            }
        }
    }
}
