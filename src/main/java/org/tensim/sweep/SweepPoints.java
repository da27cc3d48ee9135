package org.tensim.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/**
 * The points of a sweep, in a fixed order, so that a sweep started again finds its
 * finished points by number.
 *
 * <p><b>Grid</b>: the Cartesian product of every range's values, the last parameter
 * varying fastest. <b>Latin hypercube</b> of N points: each parameter's interval is cut
 * into N equal strata; every stratum is used exactly once per parameter, at a uniformly
 * drawn position inside it, and the strata of different parameters are paired by
 * independent random permutations (McKay, Beckman and Conover 1979). The generator is
 * {@link java.util.Random}, whose sequence the Java specification fixes, so a seed gives the
 * same points on every JVM.
 */
public final class SweepPoints {
    private SweepPoints() {
    }

    /** All points of the spec. */
    public static List<Point> of(SweepSpec spec) {
        return spec.sampling().latinHypercube()
                ? latinHypercube(spec.parameters(), spec.sampling().points(), spec.sampling().seed())
                : grid(spec.parameters());
    }

    /** The full grid, last parameter fastest. */
    public static List<Point> grid(List<SweepSpec.Range> ranges) {
        double[][] axes = new double[ranges.size()][];
        long count = 1;
        for (int d = 0; d < axes.length; d++) {
            axes[d] = ranges.get(d).gridValues();
            count *= axes[d].length;
        }
        List<Point> points = new ArrayList<>();
        int[] index = new int[axes.length];
        for (int id = 0; id < count; id++) {
            double[] v = new double[axes.length];
            for (int d = 0; d < axes.length; d++) {
                v[d] = axes[d][index[d]];
            }
            points.add(new Point(id, v));
            for (int d = axes.length - 1; d >= 0; d--) {
                if (++index[d] < axes[d].length) {
                    break;
                }
                index[d] = 0;
            }
        }
        return points;
    }

    /** A Latin hypercube of {@code n} points over the ranges' [min, max]. */
    public static List<Point> latinHypercube(List<SweepSpec.Range> ranges, int n, long seed) {
        Random r = new Random(seed);
        int dims = ranges.size();
        double[][] v = new double[n][dims];
        for (int d = 0; d < dims; d++) {
            int[] perm = new int[n];
            for (int i = 0; i < n; i++) {
                perm[i] = i;
            }
            for (int i = n - 1; i > 0; i--) { // Fisher-Yates
                int j = r.nextInt(i + 1);
                int t = perm[i];
                perm[i] = perm[j];
                perm[j] = t;
            }
            SweepSpec.Range g = ranges.get(d);
            for (int i = 0; i < n; i++) {
                double u = (perm[i] + r.nextDouble()) / n;
                v[i][d] = Math.min(g.max(), g.min() + u * (g.max() - g.min()));
            }
        }
        List<Point> points = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            points.add(new Point(i, v[i]));
        }
        return points;
    }
}
