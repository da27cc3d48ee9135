package org.tensim.analysis.lungs;

import java.util.function.DoubleUnaryOperator;

/**
 * A model motion with a known answer: two lungs side by side across x, each a column of points over the same
 * height H along +z (superior), every point's displacement from end-exhale {@code s(t) D_i} with
 * {@code D_i = (c, 0, -(a + b eta_i))}: an SI displacement linear in the normalised height eta (0 apex, 1 base),
 * towards the feet, and a constant sideways part c; {@code s} is the time law, 0 at end-exhale and 1 at
 * end-inhale.
 */
public final class SyntheticMotion {
    /** The cloud's height, m. */
    public static final double HEIGHT_M = 0.2;
    /** Points per lung in each of the five height bins (plus the apex and the base point of each lung). */
    public static final int PER_BIN = 20;

    public final double a;
    public final double bRight;
    public final double bLeft;
    public final double c;
    /** Each point's normalised height. */
    public final double[] eta;
    /** Each point's lung. */
    public final String[] lung;

    /**
     * @param a      SI displacement at the apex, m
     * @param bRight its increase from apex to base in the right lung, m
     * @param bLeft  in the left lung, m
     * @param c      sideways displacement, m
     */
    public SyntheticMotion(double a, double bRight, double bLeft, double c) {
        this.a = a;
        this.bRight = bRight;
        this.bLeft = bLeft;
        this.c = c;
        int perLung = 5 * PER_BIN + 2;
        eta = new double[2 * perLung];
        lung = new String[2 * perLung];
        for (int side = 0; side < 2; side++) {
            for (int k = 0; k < perLung; k++) {
                int i = side * perLung + k;
                // The apex and the base themselves, then evenly spread points within each bin.
                eta[i] = k == 0 ? 0 : k == 1 ? 1 : ((k - 2) / PER_BIN + ((k - 2) % PER_BIN + 0.5) / PER_BIN) / 5;
                lung[i] = side == 0 ? "right" : "left";
            }
        }
    }

    /** Point i's SI displacement to end-inhale, m (towards the feet). */
    public double u(int i) {
        return a + (lung[i].equals("right") ? bRight : bLeft) * eta[i];
    }

    /** The end-exhale position of point i, m: right lung at x < 0, left at x > 0, apex at z = H. */
    public double[] rest(int i) {
        double x = (lung[i].equals("right") ? -0.08 : 0.08) + 0.01 * Math.sin(7.0 * i);
        return new double[] {x, 0.02 * Math.cos(3.0 * i), HEIGHT_M * (1 - eta[i])};
    }

    /**
     * The motion sampled every {@code stepS} from 0 while {@code t < periodS}, law {@code s}; the law's values
     * given as {@code 10 + 5 s(t)} (an offset and a scale the comparison must take out).
     */
    public ModelMotion motion(DoubleUnaryOperator s, double stepS, double periodS, double endExhaleS,
            double endInhaleS) {
        int count = (int) Math.round(periodS / stepS);
        double[] times = new double[count];
        double[][] pos = new double[count][3 * eta.length];
        double[] law = new double[count];
        for (int k = 0; k < count; k++) {
            times[k] = k * stepS;
            double f = s.applyAsDouble(times[k]);
            law[k] = 10 + 5 * f;
            for (int i = 0; i < eta.length; i++) {
                double[] r = rest(i);
                pos[k][3 * i] = r[0] + f * c;
                pos[k][3 * i + 1] = r[1];
                pos[k][3 * i + 2] = r[2] - f * u(i);
            }
        }
        return new ModelMotion(times, pos, lung.clone(), endExhaleS, endInhaleS, periodS, new double[] {0, 0, 1},
                law);
    }

    /** A raised cosine: 1 at end-inhale {@code tEi}, 0 half a period later. */
    public static DoubleUnaryOperator cosine(double tEi, double periodS) {
        return t -> 0.5 * (1 + Math.cos(2 * Math.PI * (t - tEi) / periodS));
    }

    /** Writes {@code m} into a run folder {@code dir} as a run of the lungs would, and returns the folder. */
    public static java.nio.file.Path writeRun(java.nio.file.Path dir, ModelMotion m) throws Exception {
        org.tensim.io.RunFolder.run(dir, "lungs-synthetic", java.util.List.of(), run -> {
            java.util.Map<String, Object> fields = new java.util.LinkedHashMap<>();
            fields.put(LungPointsFolder.KEY, LungPointsFolder.write(run, m));
            run.finish(org.tensim.io.RunStatus.OK, fields);
        });
        return dir;
    }
}
