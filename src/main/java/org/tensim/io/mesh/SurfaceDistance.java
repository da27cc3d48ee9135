package org.tensim.io.mesh;

import java.util.Arrays;

/**
 * Unsigned distances from points to a triangle surface, with no correspondence between
 * the points and the surface's vertices (the 4D-CT case: a segmented surface against the
 * model's nodes). For each point the closest point of every triangle is found by the
 * region test of Ericson (Real-Time Collision Detection, 2005, section 5.1.5); triangles
 * whose bounding sphere lies farther than the best distance so far are skipped, which keeps
 * the cost well below points x triangles on a surface.
 */
public final class SurfaceDistance {
    private final double[] v;
    private final int[] tri;
    private final double[] centre;
    private final double[] radius;
    private final int[] order;
    private final double maxR;

    /**
     * @param xyz       vertex coordinates, m (3 per vertex)
     * @param triangles vertex indices, 3 per triangle
     */
    public SurfaceDistance(double[] xyz, int[] triangles) {
        if (triangles.length == 0 || triangles.length % 3 != 0) {
            throw new IllegalArgumentException("a surface needs whole triangles, got " + triangles.length
                    + " indices");
        }
        v = xyz.clone();
        tri = triangles.clone();
        int n = tri.length / 3;
        centre = new double[3 * n];
        radius = new double[n];
        for (int t = 0; t < n; t++) {
            for (int a = 0; a < 3; a++) {
                centre[3 * t + a] = (v[3 * tri[3 * t] + a] + v[3 * tri[3 * t + 1] + a] + v[3 * tri[3 * t + 2] + a]) / 3;
            }
            double r = 0;
            for (int k = 0; k < 3; k++) {
                int p = tri[3 * t + k];
                r = Math.max(r, Math.sqrt(sq(v[3 * p] - centre[3 * t]) + sq(v[3 * p + 1] - centre[3 * t + 1])
                        + sq(v[3 * p + 2] - centre[3 * t + 2])));
            }
            radius[t] = r;
        }
        // Triangles sorted along x so that a search can start near the point.
        Integer[] idx = new Integer[n];
        for (int t = 0; t < n; t++) {
            idx[t] = t;
        }
        Arrays.sort(idx, (a, b) -> Double.compare(centre[3 * a], centre[3 * b]));
        order = Arrays.stream(idx).mapToInt(Integer::intValue).toArray();
        maxR = Arrays.stream(radius).max().orElse(0);
    }

    /** Distance from (px, py, pz) to the surface, m. */
    public double distance(double px, double py, double pz) {
        int n = order.length;
        // start at the triangle whose centre's x is nearest, then walk both ways while it can matter
        int lo = 0;
        int hi = n - 1;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (centre[3 * order[mid]] < px) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        double best = Double.POSITIVE_INFINITY;
        // Every point of triangle t has x within maxR of its centre's: once the centres are farther
        // than best + maxR along x, no triangle further along can be closer.
        for (int i = lo, j = lo - 1; i < n || j >= 0;) {
            if (i < n) {
                int t = order[i];
                if (centre[3 * t] - px - maxR <= best) {
                    best = Math.min(best, check(t, px, py, pz, best));
                    i++;
                } else {
                    i = n;
                }
            }
            if (j >= 0) {
                int t = order[j];
                if (px - centre[3 * t] - maxR <= best) {
                    best = Math.min(best, check(t, px, py, pz, best));
                    j--;
                } else {
                    j = -1;
                }
            }
        }
        return best;
    }

    private double check(int t, double px, double py, double pz, double best) {
        double dc = Math.sqrt(sq(px - centre[3 * t]) + sq(py - centre[3 * t + 1]) + sq(pz - centre[3 * t + 2]));
        if (dc - radius[t] > best) {
            return best;
        }
        return Math.sqrt(squaredToTriangle(px, py, pz, t));
    }

    /** Squared distance to triangle t (Ericson's closest point by Voronoi regions). */
    private double squaredToTriangle(double px, double py, double pz, int t) {
        return closest(v, tri, t, px, py, pz, null);
    }

    /**
     * Squared distance from (px, py, pz) to triangle t of a surface (vertex coordinates x, 3 per vertex;
     * corners tri, 3 per triangle), and in {@code w}, unless it is null, the barycentric weights of the
     * closest point: the region test of Ericson, Real-Time Collision Detection (2005), section 5.1.5.
     * Allocation-free.
     */
    public static double closest(double[] x, int[] tri, int t, double px, double py, double pz, double[] w) {
        int ia = 3 * tri[3 * t];
        int ib = 3 * tri[3 * t + 1];
        int ic = 3 * tri[3 * t + 2];
        double abx = x[ib] - x[ia], aby = x[ib + 1] - x[ia + 1], abz = x[ib + 2] - x[ia + 2];
        double acx = x[ic] - x[ia], acy = x[ic + 1] - x[ia + 1], acz = x[ic + 2] - x[ia + 2];
        double apx = px - x[ia], apy = py - x[ia + 1], apz = pz - x[ia + 2];
        double d1 = abx * apx + aby * apy + abz * apz;
        double d2 = acx * apx + acy * apy + acz * apz;
        if (d1 <= 0 && d2 <= 0) {
            return set(w, 1, 0, 0, x, ia, ib, ic, px, py, pz); // vertex A
        }
        double bpx = px - x[ib], bpy = py - x[ib + 1], bpz = pz - x[ib + 2];
        double d3 = abx * bpx + aby * bpy + abz * bpz;
        double d4 = acx * bpx + acy * bpy + acz * bpz;
        if (d3 >= 0 && d4 <= d3) {
            return set(w, 0, 1, 0, x, ia, ib, ic, px, py, pz); // vertex B
        }
        double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            double v = d1 / (d1 - d3); // edge AB
            return set(w, 1 - v, v, 0, x, ia, ib, ic, px, py, pz);
        }
        double cpx = px - x[ic], cpy = py - x[ic + 1], cpz = pz - x[ic + 2];
        double d5 = abx * cpx + aby * cpy + abz * cpz;
        double d6 = acx * cpx + acy * cpy + acz * cpz;
        if (d6 >= 0 && d5 <= d6) {
            return set(w, 0, 0, 1, x, ia, ib, ic, px, py, pz); // vertex C
        }
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            double v = d2 / (d2 - d6); // edge AC
            return set(w, 1 - v, 0, v, x, ia, ib, ic, px, py, pz);
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
            double v = (d4 - d3) / ((d4 - d3) + (d5 - d6)); // edge BC
            return set(w, 0, 1 - v, v, x, ia, ib, ic, px, py, pz);
        }
        double denom = 1 / (va + vb + vc); // inside the face
        double v = vb * denom;
        double u = vc * denom;
        return set(w, 1 - v - u, v, u, x, ia, ib, ic, px, py, pz);
    }

    private static double set(double[] w, double a, double b, double c, double[] x, int ia, int ib, int ic,
            double px, double py, double pz) {
        if (w != null) {
            w[0] = a;
            w[1] = b;
            w[2] = c;
        }
        double qx = a * x[ia] + b * x[ib] + c * x[ic] - px;
        double qy = a * x[ia + 1] + b * x[ib + 1] + c * x[ic + 1] - py;
        double qz = a * x[ia + 2] + b * x[ib + 2] + c * x[ic + 2] - pz;
        return qx * qx + qy * qy + qz * qz;
    }

    /** The value at the nearest-rank percentile q (0..100) of the values (sorted in place). */
    public static double percentile(double[] values, double q) {
        Arrays.sort(values);
        int rank = (int) Math.ceil(q / 100 * values.length);
        return values[Math.max(0, Math.min(values.length - 1, rank - 1))];
    }

    private static double sq(double x) {
        return x * x;
    }
}
