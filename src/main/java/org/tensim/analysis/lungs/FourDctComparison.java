package org.tensim.analysis.lungs;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A model's lung motion against the measured DIR-Lab cases (docs/lungs.md, "tensim validate-4dct"), with the
 * verdicts of the lungs' targets, each measured, never asserted:
 * <ul>
 * <li><b>profile</b>: in each of the four bins above the basal one, the model's SI ratio (both lungs) within the
 * range of the cases' ratios, widened by {@value #WIDEN} either side;</li>
 * <li><b>magnitudes</b>: basal SI displacement {@value #BASAL_LO_MM}-{@value #BASAL_HI_MM} mm and mean 3D
 * displacement {@value #MEAN3D_LO_MM}-{@value #MEAN3D_HI_MM} mm (the five cases: 7.6-14.7 and 3.9-9.8 mm);</li>
 * <li><b>time course</b>: the share of each of t10-t40 (both lungs) within the cases' range widened by
 * {@value #WIDEN}.</li>
 * </ul>
 *
 * @param model    the model's figures
 * @param cases    the measured cases compared with, in order
 * @param verdicts the targets' verdicts, profile first, then magnitudes, then time course
 */
public record FourDctComparison(ModelFigures model, List<MeasuredCase> cases, List<Verdict> verdicts) {
    /** How far each measured range is widened either side for the profile and time-course targets. */
    public static final double WIDEN = 0.1;
    /** The basal SI displacement's target range, mm. */
    public static final double BASAL_LO_MM = 6;
    /** Upper end, mm. */
    public static final double BASAL_HI_MM = 20;
    /** The mean 3D displacement's target range, mm. */
    public static final double MEAN3D_LO_MM = 3;
    /** Upper end, mm. */
    public static final double MEAN3D_HI_MM = 12;

    /**
     * One target: the model's value, the range it is to lie in and whether it does.
     *
     * @param name  e.g. {@code profile_bin1} (apex), {@code basal_si_mm}, {@code share_t10}
     * @param value the model's value (mm for magnitudes, a ratio or share otherwise)
     * @param lo    the range's lower end
     * @param hi    its upper end
     * @param pass  {@code lo <= value <= hi}
     */
    public record Verdict(String name, double value, double lo, double hi, boolean pass) {
        static Verdict of(String name, double value, double lo, double hi) {
            return new Verdict(name, value, lo, hi, value >= lo && value <= hi);
        }
    }

    /**
     * Compares {@code model} with {@code cases} (at least one).
     *
     * @throws IllegalArgumentException when no case is given
     */
    public static FourDctComparison of(ModelFigures model, List<MeasuredCase> cases) {
        if (cases.isEmpty()) {
            throw new IllegalArgumentException("no measured case to compare the model with: expected 1 to 5");
        }
        List<Verdict> v = new ArrayList<>();
        for (int b = 0; b < SiProfile.BINS - 1; b++) {
            final int bin = b;
            double[] r = range(cases.stream().mapToDouble(c -> c.both().ratio()[bin]).toArray());
            v.add(Verdict.of("profile_bin" + (b + 1), model.both().ratio()[b], r[0] - WIDEN, r[1] + WIDEN));
        }
        v.add(Verdict.of("basal_si_mm", model.both().basalSiM() * 1e3, BASAL_LO_MM, BASAL_HI_MM));
        v.add(Verdict.of("mean_3d_mm", model.both().mean3dM() * 1e3, MEAN3D_LO_MM, MEAN3D_HI_MM));
        for (int p = 1; p <= 4; p++) {
            final int phase = p;
            double[] r = range(cases.stream().mapToDouble(c -> c.shares()[phase]).toArray());
            v.add(Verdict.of("share_" + org.tensim.io.landmarks.DirLabLandmarks.SIX_PHASES.get(p),
                    model.shares()[p], r[0] - WIDEN, r[1] + WIDEN));
        }
        return new FourDctComparison(model, List.copyOf(cases), List.copyOf(v));
    }

    /** The smallest and largest of {@code v}, ignoring NaN (an empty bin); NaN both when all are. */
    static double[] range(double[] v) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double x : v) {
            if (!Double.isNaN(x)) {
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        return lo <= hi ? new double[] {lo, hi} : new double[] {Double.NaN, Double.NaN};
    }

    /** The measured cases' range of bin {@code b}'s SI ratio (both lungs), unwidened. */
    public double[] ratioRange(int b) {
        return range(cases.stream().mapToDouble(c -> c.both().ratio()[b]).toArray());
    }

    /** The measured cases' range of phase {@code p}'s share (both lungs), unwidened. */
    public double[] shareRange(int p) {
        return range(cases.stream().mapToDouble(c -> c.shares()[p]).toArray());
    }

    /** How many targets pass. */
    public long passed() {
        return verdicts.stream().filter(Verdict::pass).count();
    }

    /**
     * The figures for a summary (mm, ratios and shares, rounded): the model's for both lungs at the top level
     * ({@code model_si_profile_ratio}, {@code model_basal_si_mm}, {@code model_mean_3d_mm}, ...), each lung's
     * beside them ({@code model_right}, {@code model_left}), the cases' under {@code cases}, their ranges and the
     * targets' verdicts.
     */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        SiProfile b = model.both();
        m.put("model_points", b.points());
        m.put("model_si_profile_ratio", MeasuredCase.rounded(b.ratio(), 1, 3));
        m.put("model_basal_si_mm", MeasuredCase.round(b.basalSiM() * 1e3, 2));
        m.put("model_mean_3d_mm", MeasuredCase.round(b.mean3dM() * 1e3, 2));
        m.put("model_si_bin_mean_mm", MeasuredCase.rounded(b.binMeanM(), 1e3, 2));
        m.put("model_bin_points", b.binCount());
        m.put("model_height_mm", MeasuredCase.round(b.heightM() * 1e3, 1));
        m.put("model_phase_share", MeasuredCase.phaseMap(model.shares()));
        m.put("model_law_share", model.lawShares() == null ? null : MeasuredCase.phaseMap(model.lawShares()));
        Map<String, Object> times = new LinkedHashMap<>();
        for (int p = 0; p < model.phaseTimesS().length; p++) {
            times.put(org.tensim.io.landmarks.DirLabLandmarks.SIX_PHASES.get(p),
                    MeasuredCase.round(model.phaseTimesS()[p], 4));
        }
        m.put("model_phase_time_s", times);
        m.put("model_right", lung(model.right(), model.sharesRight()));
        m.put("model_left", lung(model.left(), model.sharesLeft()));
        Map<String, Object> c = new LinkedHashMap<>();
        for (MeasuredCase mc : cases) {
            c.put("case" + mc.caseNumber(), mc.toMap());
        }
        m.put("cases", c);
        Map<String, Object> ranges = new LinkedHashMap<>();
        List<double[]> ratio = new ArrayList<>();
        for (int k = 0; k < SiProfile.BINS; k++) {
            ratio.add(MeasuredCase.rounded(ratioRange(k), 1, 3));
        }
        ranges.put("si_profile_ratio", ratio);
        ranges.put("basal_si_mm", MeasuredCase.rounded(range(cases.stream().mapToDouble(x -> x.both().basalSiM())
                .toArray()), 1e3, 2));
        ranges.put("mean_3d_mm", MeasuredCase.rounded(range(cases.stream().mapToDouble(x -> x.both().mean3dM())
                .toArray()), 1e3, 2));
        Map<String, Object> shares = new LinkedHashMap<>();
        for (int p = 0; p < model.shares().length; p++) {
            shares.put(org.tensim.io.landmarks.DirLabLandmarks.SIX_PHASES.get(p),
                    MeasuredCase.rounded(shareRange(p), 1, 3));
        }
        ranges.put("phase_share", shares);
        m.put("measured_range", ranges);
        Map<String, Object> t = new LinkedHashMap<>();
        for (Verdict v : verdicts) {
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("value", MeasuredCase.round(v.value(), 3));
            e.put("range", MeasuredCase.rounded(new double[] {v.lo(), v.hi()}, 1, 3));
            e.put("pass", v.pass());
            t.put(v.name(), e);
        }
        m.put("targets", t);
        m.put("targets_passed", passed() + " of " + verdicts.size());
        return m;
    }

    private static Map<String, Object> lung(SiProfile p, double[] s) {
        if (p == null) {
            return null;
        }
        Map<String, Object> m = new LinkedHashMap<>(MeasuredCase.profile(p));
        m.put("phase_share", s == null ? null : MeasuredCase.phaseMap(s));
        return m;
    }
}
