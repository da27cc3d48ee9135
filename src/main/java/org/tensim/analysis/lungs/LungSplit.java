package org.tensim.analysis.lungs;

import java.util.Arrays;

/**
 * Splits a cloud of points in both lungs into its two lungs along the axis across the body: at the widest gap
 * between consecutive points' coordinates in the middle 40 % of the cloud's width, where the mediastinum (the
 * heart, the great vessels) leaves no lung. On the five DIR-Lab cases that gap is 39-60 mm wide, and splitting
 * there or at the middle of the cloud's width puts the same landmarks on each side.
 *
 * @param axis      the axis split along (0, 1, 2)
 * @param planeM    the coordinate of the split, m (the middle of the gap)
 * @param gapM      the gap's width, m
 * @param low       indices of the points below the plane (ascending)
 * @param high      indices of the points above it
 */
public record LungSplit(int axis, double planeM, double gapM, int[] low, int[] high) {
    /**
     * Splits the points {@code x} (m, {@code 3 i + a}) along {@code axis}.
     *
     * @throws IllegalArgumentException when no two points lie in the middle 40 % of the width to leave a gap
     */
    public static LungSplit of(double[] x, int axis) {
        int n = x.length / 3;
        double[] c = new double[n];
        for (int i = 0; i < n; i++) {
            c[i] = x[3 * i + axis];
        }
        double[] s = c.clone();
        Arrays.sort(s);
        double lo = s[0];
        double w = s[n - 1] - lo;
        double best = -1;
        double plane = Double.NaN;
        for (int i = 0; i + 1 < n; i++) {
            double a = s[i];
            double b = s[i + 1];
            // A gap counts where it overlaps the middle 40 % of the width.
            if (b >= lo + 0.3 * w && a <= lo + 0.7 * w && b - a > best) {
                best = b - a;
                plane = (a + b) / 2;
            }
        }
        if (best < 0) {
            throw new IllegalArgumentException("no gap between the lungs can be found among " + n + " points along"
                    + " axis " + axis);
        }
        final double p = plane;
        int[] low = java.util.stream.IntStream.range(0, n).filter(i -> c[i] < p).toArray();
        int[] high = java.util.stream.IntStream.range(0, n).filter(i -> c[i] >= p).toArray();
        return new LungSplit(axis, plane, best, low, high);
    }
}
