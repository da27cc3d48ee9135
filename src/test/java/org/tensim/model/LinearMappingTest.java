package org.tensim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** A linear mapping carries affine motions exactly and its transpose conserves force, moment and work. */
class LinearMappingTest {
    private static final int NODES = 6;
    private static final int POINTS = 9;

    /** Points on 1-4 random nodes, weights random (some negative: extrapolated points) and summing to 1. */
    private static LinearMapping random(Random r) {
        int[] start = new int[POINTS + 1];
        java.util.List<Integer> nodes = new java.util.ArrayList<>();
        java.util.List<Double> weights = new java.util.ArrayList<>();
        for (int i = 0; i < POINTS; i++) {
            int k = 1 + r.nextInt(4);
            double sum = 0;
            double[] w = new double[k];
            for (int e = 0; e < k; e++) {
                w[e] = r.nextDouble() * 1.5 - 0.25;
                sum += w[e];
            }
            for (int e = 0; e < k; e++) {
                nodes.add(r.nextInt(NODES));
                weights.add(e == k - 1 ? 1 - (sum - w[e]) : w[e]);
            }
            start[i + 1] = nodes.size();
        }
        return new LinearMapping(NODES, start, nodes.stream().mapToInt(Integer::intValue).toArray(),
                weights.stream().mapToDouble(Double::doubleValue).toArray());
    }

    private static double[] randomVector(Random r, int n) {
        double[] v = new double[3 * n];
        for (int i = 0; i < v.length; i++) {
            v[i] = r.nextGaussian();
        }
        return v;
    }

    @Test
    void anAffineMotionOfTheNodesMovesEveryPointByTheSameMap() {
        Random r = new Random(7);
        for (int trial = 0; trial < 20; trial++) {
            LinearMapping m = random(r);
            double[] x = randomVector(r, NODES);
            double[] p = new double[3 * POINTS];
            m.apply(x, p);
            double[][] a = new double[3][3];
            double[] b = {r.nextGaussian(), r.nextGaussian(), r.nextGaussian()};
            for (double[] row : a) {
                for (int j = 0; j < 3; j++) {
                    row[j] = r.nextGaussian();
                }
            }
            double[] moved = new double[3 * NODES];
            affine(a, b, x, moved);
            double[] mapped = new double[3 * POINTS];
            m.apply(moved, mapped);
            double[] expected = new double[3 * POINTS];
            affine(a, b, p, expected);
            for (int i = 0; i < mapped.length; i++) {
                assertEquals(expected[i], mapped[i], 1e-12, "trial " + trial + ", coordinate " + i);
            }
        }
    }

    private static void affine(double[][] a, double[] b, double[] in, double[] out) {
        for (int i = 0; i < in.length / 3; i++) {
            for (int r = 0; r < 3; r++) {
                out[3 * i + r] = b[r] + a[r][0] * in[3 * i] + a[r][1] * in[3 * i + 1] + a[r][2] * in[3 * i + 2];
            }
        }
    }

    @Test
    void theTransposeConservesForceMomentAndWork() {
        Random r = new Random(11);
        for (int trial = 0; trial < 20; trial++) {
            LinearMapping m = random(r);
            double[] x = randomVector(r, NODES);
            double[] p = new double[3 * POINTS];
            m.apply(x, p);
            double[] f = randomVector(r, POINTS);
            double[] fn = new double[3 * NODES];
            m.addTranspose(f, fn);
            double[] total = sum(f);
            double[] nodal = sum(fn);
            double[] moment = moment(p, f);
            double[] nodalMoment = moment(x, fn);
            for (int a = 0; a < 3; a++) {
                assertEquals(total[a], nodal[a], 1e-12, "force component " + a);
                assertEquals(moment[a], nodalMoment[a], 1e-12, "moment component " + a);
            }
            // virtual work: nodal forces on any nodal motion do the work the point forces do on the mapped motion
            double[] u = randomVector(r, NODES);
            double[] up = new double[3 * POINTS];
            m.apply(u, up);
            assertEquals(dot(f, up), dot(fn, u), 1e-12);
        }
    }

    @Test
    void theTransposeAddsToTheForcesAlreadyThere() {
        LinearMapping m = new LinearMapping(2, new int[] {0, 2}, new int[] {0, 1}, new double[] {0.25, 0.75});
        double[] fn = {1, 0, 0, 0, 2, 0};
        m.addTranspose(new double[] {4, 0, 0}, fn);
        assertEquals(2, fn[0], 1e-15);
        assertEquals(3, fn[3], 1e-15);
        assertEquals(2, fn[4], 1e-15);
    }

    @Test
    void theBuilderMakesTheMappingOfItsRows() {
        LinearMapping.Builder b = new LinearMapping.Builder(3);
        for (int i = 0; i < 40; i++) {
            assertEquals(i, b.add(new int[] {i % 3, (i + 1) % 3, (i + 2) % 3}, new double[] {0.2, 0.3, 0.5}));
        }
        LinearMapping m = b.build();
        assertEquals(40, m.pointCount());
        assertEquals(3, m.entries(39));
        assertEquals(39 % 3, m.node(39, 0));
        assertEquals(0.5, m.weight(39, 2), 0);
        double[] p = new double[3 * 40];
        m.apply(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, p);
        assertEquals(0.2, p[0], 1e-15);
        assertEquals(0.3, p[1], 1e-15);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new LinearMapping.Builder(2).add(new int[] {0, 1}, new double[] {1}));
        assertTrue(e.getMessage().contains("2 nodes but 1 weights"), e.getMessage());
    }

    @Test
    void badWeightsAreRefusedNamingThePoint() {
        IllegalArgumentException sum = assertThrows(IllegalArgumentException.class, () -> new LinearMapping(2,
                new int[] {0, 1, 3}, new int[] {0, 0, 1}, new double[] {1, 0.5, 0.4}));
        assertTrue(sum.getMessage().contains("mapped point 1") && sum.getMessage().contains("0.9"),
                sum.getMessage());
        IllegalArgumentException empty = assertThrows(IllegalArgumentException.class, () -> new LinearMapping(2,
                new int[] {0, 1, 1}, new int[] {0}, new double[] {1}));
        assertTrue(empty.getMessage().contains("mapped point 1 has no node"), empty.getMessage());
        RuntimeException range = assertThrows(RuntimeException.class, () -> new LinearMapping(2,
                new int[] {0, 1}, new int[] {2}, new double[] {1}));
        assertTrue(range.getMessage().contains("mapped point 0's node 2"), range.getMessage());
    }

    private static double[] sum(double[] f) {
        double[] s = new double[3];
        for (int i = 0; i < f.length; i++) {
            s[i % 3] += f[i];
        }
        return s;
    }

    private static double[] moment(double[] x, double[] f) {
        double[] m = new double[3];
        for (int i = 0; i < x.length / 3; i++) {
            double px = x[3 * i], py = x[3 * i + 1], pz = x[3 * i + 2];
            double fx = f[3 * i], fy = f[3 * i + 1], fz = f[3 * i + 2];
            m[0] += py * fz - pz * fy;
            m[1] += pz * fx - px * fz;
            m[2] += px * fy - py * fx;
        }
        return m;
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) {
            s += a[i] * b[i];
        }
        return s;
    }
}
