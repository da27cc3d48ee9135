package org.tensim.analysis.lungs;

import java.util.Arrays;

/**
 * A model's points followed over its breathing cycle: what a run of the lungs gives the comparison with measured
 * 4D-CT motion ({@link FourDctComparison}). Its folder form is {@link LungPointsFolder}'s.
 *
 * <p>Between sampled instants a position is interpolated linearly in time. A time outside the sampled span is
 * brought into it by whole periods (the motion is taken as periodic); one that then falls in the gap between the
 * last instant and the first plus a period is interpolated between those two.
 *
 * @param timesS      the sampled instants, s, increasing (at least 2)
 * @param positionsM  the points' positions at each instant, m, {@code [instant][3 i + a]}, every instant the same
 *                    points
 * @param lung        each point's lung, {@code "right"} or {@code "left"}
 * @param endExhaleS  the time of end-exhale in the cycle compared, s
 * @param endInhaleS  the time of end-inhale in the cycle compared, s
 * @param periodS     the breathing period, s (> 0)
 * @param superior    the model frame's superior direction, a unit vector (the thorax's: (0, 0, 1), +Z superior)
 * @param law         the breathing law's value at each instant (any unit: only its change from end-exhale to
 *                    end-inhale is used), or null when the run does not give it
 */
public record ModelMotion(double[] timesS, double[][] positionsM, String[] lung, double endExhaleS,
        double endInhaleS, double periodS, double[] superior, double[] law) {
    /** The names a point's lung may have. */
    public static final java.util.List<String> LUNGS = java.util.List.of("right", "left");

    /**
     * Checks the motion.
     *
     * @throws IllegalArgumentException naming the value found and what was expected
     */
    public ModelMotion {
        if (timesS.length < 2 || positionsM.length != timesS.length) {
            throw new IllegalArgumentException("a model motion needs at least 2 instants with positions at each, got "
                    + timesS.length + " instants and " + positionsM.length + " position sets");
        }
        int n = lung.length;
        for (int k = 0; k < timesS.length; k++) {
            if (!Double.isFinite(timesS[k]) || k > 0 && !(timesS[k] > timesS[k - 1])) {
                throw new IllegalArgumentException("instant " + k + " is at t = " + timesS[k] + " s; expected"
                        + " finite times, each after the one before");
            }
            if (positionsM[k].length != 3 * n) {
                throw new IllegalArgumentException("instant " + k + " (t = " + timesS[k] + " s) has "
                        + positionsM[k].length / 3.0 + " points; expected " + n + " (one per lung label)");
            }
        }
        for (int i = 0; i < n; i++) {
            if (!LUNGS.contains(lung[i])) {
                throw new IllegalArgumentException("point " + i + " is in lung '" + lung[i] + "'; expected right or"
                        + " left");
            }
        }
        if (!(periodS > 0) || !Double.isFinite(periodS)) {
            throw new IllegalArgumentException("period_s is " + periodS + "; expected a period > 0 s");
        }
        double norm = superior.length == 3 ? Math.sqrt(superior[0] * superior[0] + superior[1] * superior[1]
                + superior[2] * superior[2]) : Double.NaN;
        if (!(Math.abs(norm - 1) < 1e-6)) {
            throw new IllegalArgumentException("superior is " + Arrays.toString(superior) + "; expected a unit"
                    + " vector of 3 numbers");
        }
        if (!Double.isFinite(endExhaleS) || !Double.isFinite(endInhaleS)) {
            throw new IllegalArgumentException("end-exhale at " + endExhaleS + " s, end-inhale at " + endInhaleS
                    + " s; expected finite times");
        }
        if (law != null && law.length != timesS.length) {
            throw new IllegalArgumentException("the breathing law has " + law.length + " values for "
                    + timesS.length + " instants; expected one per instant");
        }
        // Periodic interpolation needs the samples to span a cycle, up to one sampling interval at its end.
        double span = timesS[timesS.length - 1] - timesS[0];
        double step = 0;
        for (int k = 1; k < timesS.length; k++) {
            step = Math.max(step, timesS[k] - timesS[k - 1]);
        }
        if (span + step < periodS * (1 - 1e-9)) {
            throw new IllegalArgumentException("the instants span " + span + " s, less than the period " + periodS
                    + " s; expected at least one whole cycle");
        }
    }

    /** The motion without a breathing law. */
    public ModelMotion(double[] timesS, double[][] positionsM, String[] lung, double endExhaleS, double endInhaleS,
            double periodS, double[] superior) {
        this(timesS, positionsM, lung, endExhaleS, endInhaleS, periodS, superior, null);
    }

    /** Number of points. */
    public int points() {
        return lung.length;
    }

    /** The indices of the points in lung {@code name} ("right" or "left"), ascending. */
    public int[] pointsOf(String name) {
        return java.util.stream.IntStream.range(0, lung.length).filter(i -> lung[i].equals(name)).toArray();
    }

    /** The positions at time {@code tS} (m, {@code 3 i + a}), interpolated (see the class comment). */
    public double[] positionsAt(double tS) {
        double[] out = new double[positionsM[0].length];
        interpolate(tS, (k0, k1, w) -> {
            for (int j = 0; j < out.length; j++) {
                out[j] = (1 - w) * positionsM[k0][j] + w * positionsM[k1][j];
            }
        });
        return out;
    }

    /** The breathing law at time {@code tS}, interpolated as the positions are; NaN when the run gives no law. */
    public double lawAt(double tS) {
        if (law == null) {
            return Double.NaN;
        }
        double[] v = new double[1];
        interpolate(tS, (k0, k1, w) -> v[0] = (1 - w) * law[k0] + w * law[k1]);
        return v[0];
    }

    private interface Blend {
        void at(int k0, int k1, double w);
    }

    private void interpolate(double tS, Blend blend) {
        int last = timesS.length - 1;
        double t0 = timesS[0];
        double t = tS;
        if (t < t0 || t > timesS[last]) {
            t = t0 + (((t - t0) % periodS) + periodS) % periodS;
        }
        if (t > timesS[last]) {
            // In the gap between the last instant and the first one period on.
            blend.at(last, 0, (t - timesS[last]) / (t0 + periodS - timesS[last]));
            return;
        }
        int k = Arrays.binarySearch(timesS, t);
        if (k >= 0) {
            blend.at(k, k, 0);
            return;
        }
        int hi = -k - 1;
        int lo = hi - 1;
        blend.at(lo, hi, (t - timesS[lo]) / (timesS[hi] - timesS[lo]));
    }
}
