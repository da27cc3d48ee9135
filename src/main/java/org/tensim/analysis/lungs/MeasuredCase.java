package org.tensim.analysis.lungs;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.io.landmarks.DirLabLandmarks;
import org.tensim.io.landmarks.LandmarkFormatException;
import org.tensim.io.landmarks.LandmarkSet;

/**
 * One DIR-Lab case's figures (docs/lungs.md): from its 300 pairs, the SI profile of both lungs together and of
 * each lung ({@link LungSplit} across the scan's x axis); from its 75 landmarks at six phases, each phase's share of
 * the end-inhale displacement ({@link PhaseShares}, end-exhale {@code t50}), for both lungs and each.
 *
 * <p>Which lung lies at low x is not established from these files: in the usual radiological display the patient's
 * right is at low x, but the files do not say, so the lungs are named by their side of the split, {@code low_x} and
 * {@code high_x}.
 *
 * @param caseNumber  1-5
 * @param both        the SI profile of all 300 landmarks
 * @param lowX        of the landmarks at low x
 * @param highX       of those at high x
 * @param split       the split of the 300
 * @param shares      each phase's share, {@code t00} (1, end-inhale) to {@code t50} (0, end-exhale), all 75
 * @param sharesLowX  the same of the 75 at low x
 * @param sharesHighX at high x
 */
public record MeasuredCase(int caseNumber, SiProfile both, SiProfile lowX, SiProfile highX, LungSplit split,
        double[] shares, double[] sharesLowX, double[] sharesHighX) {

    /** Reads case {@code n}'s two files from {@code folder} and computes its figures. */
    public static MeasuredCase read(Path folder, int n) throws IOException, LandmarkFormatException {
        LandmarkSet pairs = DirLabLandmarks.readPairs(folder, n);
        LandmarkSet six = DirLabLandmarks.readSixPhases(folder, n);
        double[] x = pairs.at("ee");
        double[] d = pairs.displacement("ee", "ei");
        double[] up = pairs.superior();
        LungSplit split = LungSplit.of(x, 0);
        SiProfile both = SiProfile.of(x, d, up, null);
        SiProfile low = SiProfile.of(x, d, up, split.low());
        SiProfile high = SiProfile.of(x, d, up, split.high());
        int exhale = six.phase("t50");
        int inhale = six.phase("t00");
        double[][] pos = six.positions();
        LungSplit split6 = LungSplit.of(pos[exhale], 0);
        return new MeasuredCase(n, both, low, high, split, PhaseShares.of(pos, exhale, inhale),
                PhaseShares.of(subset(pos, split6.low()), exhale, inhale),
                PhaseShares.of(subset(pos, split6.high()), exhale, inhale));
    }

    private static double[][] subset(double[][] pos, int[] idx) {
        double[][] out = new double[pos.length][3 * idx.length];
        for (int p = 0; p < pos.length; p++) {
            for (int k = 0; k < idx.length; k++) {
                System.arraycopy(pos[p], 3 * idx[k], out[p], 3 * k, 3);
            }
        }
        return out;
    }

    /** The figures as a map of plain values, mm and ratios (for a summary): both lungs' at the top level. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>(profile(both));
        m.put("phase_share", phaseMap(shares));
        m.put("low_x", lung(lowX, sharesLowX));
        m.put("high_x", lung(highX, sharesHighX));
        m.put("split_x_mm", round(split.planeM() * 1e3, 2));
        m.put("split_gap_mm", round(split.gapM() * 1e3, 2));
        return m;
    }

    private static Map<String, Object> lung(SiProfile p, double[] s) {
        Map<String, Object> m = new LinkedHashMap<>(profile(p));
        m.put("phase_share", phaseMap(s));
        return m;
    }

    static Map<String, Object> profile(SiProfile p) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("points", p.points());
        m.put("si_profile_ratio", rounded(p.ratio(), 1, 3));
        m.put("si_bin_mean_mm", rounded(p.binMeanM(), 1e3, 2));
        m.put("bin_points", p.binCount());
        m.put("basal_si_mm", round(p.basalSiM() * 1e3, 2));
        m.put("lowest_fifth_by_count_si_mm", round(p.lowestFifthByCountM() * 1e3, 2));
        m.put("mean_3d_mm", round(p.mean3dM() * 1e3, 2));
        m.put("height_mm", round(p.heightM() * 1e3, 1));
        return m;
    }

    static Map<String, Object> phaseMap(double[] s) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int p = 0; p < s.length; p++) {
            m.put(DirLabLandmarks.SIX_PHASES.get(p), round(s[p], 3));
        }
        return m;
    }

    static double[] rounded(double[] v, double scale, int digits) {
        double[] r = new double[v.length];
        for (int i = 0; i < v.length; i++) {
            r[i] = round(v[i] * scale, digits);
        }
        return r;
    }

    static double round(double v, int digits) {
        double f = Math.pow(10, digits);
        return Double.isFinite(v) ? Math.round(v * f) / f : v;
    }
}
