package org.tensim.analysis.lungs;

/**
 * How a cloud of points moves superior-inferior (SI) from its apex to its base, in normalised terms: what can be
 * compared between different people's lungs (docs/lungs.md).
 *
 * <p>Given each point's position at end-exhale {@code x_i} and its displacement to end-inhale {@code d_i}, and the
 * frame's unit superior direction s:
 * <ul>
 * <li>normalised height {@code eta_i = (max_j x_j.s - x_i.s) / (max_j x_j.s - min_j x_j.s)}: 0 at the apex (the
 * highest point), 1 at the base (the lowest);</li>
 * <li>SI displacement {@code u_i = -d_i.s}, positive towards the feet (the way the base moves on inhaling);</li>
 * <li>five bins of equal width in eta, {@code [0, 0.2), [0.2, 0.4), ..., [0.8, 1]}, apex to base; the mean u of
 * each ({@link #binMeanM}); each bin's mean over the basal bin's ({@link #ratio}, 1 for the basal bin);</li>
 * <li>basal SI displacement: the basal bin's mean ({@link #basalSiM}), the lowest fifth of the cloud's height;</li>
 * <li>mean 3D displacement {@code mean |d_i|} ({@link #mean3dM}).</li>
 * </ul>
 * The basal bin is the lowest fifth of the height, not the lowest fifth of the points by count: with these bins the
 * five DIR-Lab cases give basal 7.56-14.74 mm and the ratios quoted in docs/lungs.md; the lowest 60 of 300 landmarks
 * give 7.25-14.17 mm ({@link #lowestFifthByCountM}, reported beside it).
 *
 * @param points     number of points
 * @param binCount   points in each bin, apex to base
 * @param binMeanM   mean SI displacement u of each bin, m (NaN for an empty bin)
 * @param ratio      each bin's mean over the basal bin's (NaN where the bin is empty)
 * @param basalSiM   mean SI displacement of the basal bin, m
 * @param lowestFifthByCountM mean SI displacement of the lowest fifth of the points by count (ties by order), m
 * @param mean3dM    mean 3D displacement length, m
 * @param heightM    the cloud's height {@code max x.s - min x.s}, m
 */
public record SiProfile(int points, int[] binCount, double[] binMeanM, double[] ratio, double basalSiM,
        double lowestFifthByCountM, double mean3dM, double heightM) {
    /** Number of height bins. */
    public static final int BINS = 5;

    /**
     * The profile of the points {@code subset} (indices; null for all) of positions {@code x} and displacements
     * {@code d} (m, {@code 3 i + a}), with unit superior direction {@code superior}.
     *
     * @throws IllegalArgumentException when fewer than 2 points are given, the arrays differ in length, the
     *                                  points have no height along {@code superior} or the basal bin is empty
     */
    public static SiProfile of(double[] x, double[] d, double[] superior, int[] subset) {
        if (x.length != d.length || x.length % 3 != 0) {
            throw new IllegalArgumentException("positions and displacements must be 3 numbers a point alike, got "
                    + x.length + " and " + d.length);
        }
        int[] idx = subset != null ? subset : java.util.stream.IntStream.range(0, x.length / 3).toArray();
        int n = idx.length;
        if (n < 2) {
            throw new IllegalArgumentException("an SI profile needs at least 2 points, got " + n);
        }
        double[] up = new double[n];
        double[] si = new double[n];
        double hi = Double.NEGATIVE_INFINITY;
        double lo = Double.POSITIVE_INFINITY;
        double mean3d = 0;
        for (int k = 0; k < n; k++) {
            int i = 3 * idx[k];
            up[k] = x[i] * superior[0] + x[i + 1] * superior[1] + x[i + 2] * superior[2];
            si[k] = -(d[i] * superior[0] + d[i + 1] * superior[1] + d[i + 2] * superior[2]);
            hi = Math.max(hi, up[k]);
            lo = Math.min(lo, up[k]);
            mean3d += Math.sqrt(d[i] * d[i] + d[i + 1] * d[i + 1] + d[i + 2] * d[i + 2]);
        }
        double height = hi - lo;
        if (!(height > 0)) {
            throw new IllegalArgumentException("the " + n + " points have no height along the superior direction"
                    + " (all at " + hi + " m): expected a cloud spanning apex to base");
        }
        int[] count = new int[BINS];
        double[] sum = new double[BINS];
        for (int k = 0; k < n; k++) {
            double eta = (hi - up[k]) / height;
            int b = Math.min(BINS - 1, (int) Math.floor(eta * BINS));
            count[b]++;
            sum[b] += si[k];
        }
        double[] mean = new double[BINS];
        for (int b = 0; b < BINS; b++) {
            mean[b] = count[b] == 0 ? Double.NaN : sum[b] / count[b];
        }
        double basal = mean[BINS - 1];
        double[] ratio = new double[BINS];
        for (int b = 0; b < BINS; b++) {
            ratio[b] = mean[b] / basal;
        }
        // Lowest fifth by count: the points sorted by height, lowest first (a stable sort: ties keep their order).
        Integer[] order = new Integer[n];
        for (int k = 0; k < n; k++) {
            order[k] = k;
        }
        java.util.Arrays.sort(order, (a, b) -> Double.compare(up[a], up[b]));
        int fifth = Math.max(1, n / BINS);
        double low = 0;
        for (int k = 0; k < fifth; k++) {
            low += si[order[k]];
        }
        return new SiProfile(n, count, mean, ratio, basal, low / fifth, mean3d / n, height);
    }

    /** The ratios of the four bins above the basal one, apex first (the basal bin's is 1 by definition). */
    public double[] ratiosAboveBase() {
        return java.util.Arrays.copyOf(ratio, BINS - 1);
    }
}
