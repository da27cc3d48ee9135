package org.tensim.solver;

import java.util.Random;
import org.tensim.model.LinearMapping;

/**
 * Seeded random configurations for the sliding term's tests: a bumpy grid surface of g x g points, each point a
 * 0.6 / 0.4 mix of two carrier nodes jittered around it (so the mapping is not the identity), followers scattered
 * above and below it, the whole turned by a random rotation and shifted.
 */
final class SlidingCases {
    static final double SPACING = 0.01; // m

    /** A configuration: positions (3 per node), followers, the surface's mapping and triangles, k and gaps. */
    record Case(double[] x, int[] followers, LinearMapping mapping, int[] triangles, double[] stiffness,
            double[] gaps) {
        SurfaceSliding term(SurfaceSliding.Mode mode) {
            return new SurfaceSliding(followers, mapping, triangles, stiffness, mode, gaps, x);
        }
    }

    private SlidingCases() {
    }

    static Case random(long seed, int g, int followerCount) {
        Random r = new Random(seed);
        int points = g * g;
        int nodes = 2 * points + followerCount;
        double[] x = new double[3 * nodes];
        LinearMapping.Builder map = new LinearMapping.Builder(nodes);
        for (int i = 0; i < g; i++) {
            for (int j = 0; j < g; j++) {
                int p = i * g + j;
                double px = i * SPACING, py = j * SPACING, pz = 0.002 * r.nextDouble();
                double[] jitter = {0.003 * r.nextGaussian(), 0.003 * r.nextGaussian(), 0.003 * r.nextGaussian()};
                double[] at = {px, py, pz};
                for (int a = 0; a < 3; a++) {
                    x[6 * p + a] = at[a] + jitter[a];
                    x[6 * p + 3 + a] = (at[a] - 0.6 * (at[a] + jitter[a])) / 0.4; // 0.6 A + 0.4 B = point
                }
                map.add(new int[] {2 * p, 2 * p + 1}, new double[] {0.6, 0.4});
            }
        }
        int[] tris = new int[6 * (g - 1) * (g - 1)];
        int k = 0;
        for (int i = 0; i + 1 < g; i++) {
            for (int j = 0; j + 1 < g; j++) {
                int a = i * g + j, b = (i + 1) * g + j, c = (i + 1) * g + j + 1, d = i * g + j + 1;
                int[] two = {a, b, c, a, c, d}; // counter-clockwise seen from +z: normal +z
                System.arraycopy(two, 0, tris, k, 6);
                k += 6;
            }
        }
        int[] followers = new int[followerCount];
        double[] stiffness = new double[followerCount];
        double[] gaps = new double[followerCount];
        double extent = (g - 1) * SPACING;
        for (int e = 0; e < followerCount; e++) {
            int n = 2 * points + e;
            followers[e] = n;
            x[3 * n] = extent * (0.1 + 0.8 * r.nextDouble());
            x[3 * n + 1] = extent * (0.1 + 0.8 * r.nextDouble());
            x[3 * n + 2] = 0.001 + 0.003 * (2 * r.nextDouble() - 1);
            stiffness[e] = 50 + 100 * r.nextDouble();
            gaps[e] = 0.001 * (2 * r.nextDouble() - 1);
        }
        rotate(x, r);
        return new Case(x, followers, map.build(), tris, stiffness, gaps);
    }

    /** Turns all positions by a random rotation (a random unit quaternion) and shifts them by up to 0.1 m. */
    private static void rotate(double[] x, Random r) {
        double qw = r.nextGaussian(), qx = r.nextGaussian(), qy = r.nextGaussian(), qz = r.nextGaussian();
        double q = Math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
        qw /= q;
        qx /= q;
        qy /= q;
        qz /= q;
        double[] m = {
            1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw),
            2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw),
            2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)};
        double[] shift = {0.1 * r.nextDouble(), 0.1 * r.nextDouble(), 0.1 * r.nextDouble()};
        for (int i = 0; i < x.length; i += 3) {
            double a = x[i], b = x[i + 1], c = x[i + 2];
            for (int k = 0; k < 3; k++) {
                x[i + k] = m[3 * k] * a + m[3 * k + 1] * b + m[3 * k + 2] * c + shift[k];
            }
        }
    }

    /** Unit normal of triangle t of the case at positions x (independent of the term's code), and its corner a. */
    static double[] normalAndCorner(Case c, double[] x, int t) {
        double[] p = new double[3 * c.mapping().pointCount()];
        c.mapping().apply(x, p);
        int a = 3 * c.triangles()[3 * t], b = 3 * c.triangles()[3 * t + 1], d = 3 * c.triangles()[3 * t + 2];
        double[] u = {p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]};
        double[] v = {p[d] - p[a], p[d + 1] - p[a + 1], p[d + 2] - p[a + 2]};
        double[] n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        return new double[] {n[0] / len, n[1] / len, n[2] / len, p[a], p[a + 1], p[a + 2]};
    }

    /**
     * The follower's frame against triangle t, computed independently of {@link SurfacePairing}: {@code {u, d}} with
     * d the signed distance (m) and u the unit direction of its force. Over the triangle's inside, its plane (u = n,
     * d = n . (y - a)); outside, the closest point c on the nearest of its three edges (segments), d = s |y - c| and
     * u = s (y - c) / |y - c|, s the sign of (n + the normal across that edge) . (y - c).
     */
    static double[] frame(Case c, double[] x, int t, int yo) {
        double[] p = new double[3 * c.mapping().pointCount()];
        c.mapping().apply(x, p);
        double[] na = normalAndCorner(c, x, t);
        double[] y = {x[yo], x[yo + 1], x[yo + 2]};
        double d = 0;
        for (int a = 0; a < 3; a++) {
            d += na[a] * (y[a] - na[3 + a]);
        }
        double[][] corner = new double[3][];
        for (int k = 0; k < 3; k++) {
            int o = 3 * c.triangles()[3 * t + k];
            corner[k] = new double[] {p[o], p[o + 1], p[o + 2]};
        }
        double[] proj = {y[0] - d * na[0], y[1] - d * na[1], y[2] - d * na[2]};
        boolean inside = true;
        for (int k = 0; k < 3; k++) {
            double[] e = sub(corner[(k + 1) % 3], corner[k]);
            double[] r = sub(proj, corner[k]);
            double[] cr = {e[1] * r[2] - e[2] * r[1], e[2] * r[0] - e[0] * r[2], e[0] * r[1] - e[1] * r[0]};
            inside &= cr[0] * na[0] + cr[1] * na[1] + cr[2] * na[2] >= 0;
        }
        if (inside) {
            return new double[] {na[0], na[1], na[2], d};
        }
        double best = Double.POSITIVE_INFINITY;
        double[] cp = null;
        int edge = -1;
        for (int k = 0; k < 3; k++) {
            double[] a = corner[k];
            double[] e = sub(corner[(k + 1) % 3], a);
            double[] r = sub(y, a);
            double tt = Math.max(0, Math.min(1, (r[0] * e[0] + r[1] * e[1] + r[2] * e[2])
                    / (e[0] * e[0] + e[1] * e[1] + e[2] * e[2])));
            double[] q = {a[0] + tt * e[0], a[1] + tt * e[1], a[2] + tt * e[2]};
            double[] dq = sub(y, q);
            double dist = Math.sqrt(dq[0] * dq[0] + dq[1] * dq[1] + dq[2] * dq[2]);
            if (dist < best) {
                best = dist;
                cp = q;
                edge = k;
            }
        }
        double[] sn = {na[0], na[1], na[2]};
        int ea = c.triangles()[3 * t + edge];
        int eb = c.triangles()[3 * t + (edge + 1) % 3];
        for (int o = 0; 3 * o < c.triangles().length; o++) {
            java.util.Set<Integer> ids = java.util.Set.of(c.triangles()[3 * o], c.triangles()[3 * o + 1],
                    c.triangles()[3 * o + 2]);
            if (o != t && ids.contains(ea) && ids.contains(eb)) {
                double[] no = normalAndCorner(c, x, o);
                for (int a = 0; a < 3; a++) {
                    sn[a] += no[a];
                }
            }
        }
        double[] dq = sub(y, cp);
        double sign = sn[0] * dq[0] + sn[1] * dq[1] + sn[2] * dq[2] < 0 ? -1 : 1;
        return new double[] {sign * dq[0] / best, sign * dq[1] / best, sign * dq[2] / best, sign * best};
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    /**
     * Puts every follower over the inside of its paired triangle (barycentric coordinates at least 0.1 from its
     * edges), 3 mm either side: there the walk keeps the pairing under any small displacement, so the energy is the
     * one smooth function whose gradient the forces claim to be. (Across a ridge or a rim, where the projection is
     * outside both triangles, the pairing may switch, and the energy jumps, as the class comment says.)
     */
    static void overPairedTriangles(Case c, SurfaceSliding s, double[] x, java.util.Random r) {
        double[] p = new double[3 * c.mapping().pointCount()];
        c.mapping().apply(x, p);
        for (int e = 0; e < s.pairCount(); e++) {
            int t = s.pairedTriangle(e);
            double[] na = normalAndCorner(c, x, t);
            double b1 = 0.1 + 0.4 * r.nextDouble();
            double b2 = 0.1 + 0.4 * r.nextDouble();
            double d = 0.003 * (2 * r.nextDouble() - 1);
            int i = 3 * c.followers()[e];
            for (int a = 0; a < 3; a++) {
                double pa = p[3 * c.triangles()[3 * t] + a];
                double pb = p[3 * c.triangles()[3 * t + 1] + a];
                double pc = p[3 * c.triangles()[3 * t + 2] + a];
                x[i + a] = (1 - b1 - b2) * pa + b1 * pb + b2 * pc + d * na[a];
            }
        }
    }
}
