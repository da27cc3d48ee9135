package org.tensim.solver;

import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/**
 * A triangulated surface's connectivity and the geometry a follower node needs against it: the plane of a triangle
 * (unit normal, signed distance, barycentric coordinates of the projection), the closest point's distance, the
 * nearest triangle by brute force and by a local walk. Positions of the surface's points are passed in at each call
 * (3 doubles per point, m), so the same connectivity serves a moving, deforming surface.
 *
 * <p><b>Walk (why).</b> A follower keeps its triangle while its projection onto the triangle's plane stays inside
 * it (all barycentric coordinates &gt;= 0): the pairing then does not change, so the forces are exactly minus the
 * gradient of one smooth energy, and no tie between two triangles makes it chatter. When the projection leaves the
 * triangle, the follower moves to the triangle sharing a vertex with it whose closest point is strictly nearer,
 * repeated up to {@link #MAX_STEPS} times per call (a descent on the distance over the surface's triangles). A
 * follower moves a small fraction of a triangle per step, so one or two moves suffice; the walk costs a few
 * closest-point tests per follower and reads only arrays built here, once, so it never allocates. A re-pairing by
 * brute force ({@link #nearest}) is for construction and for a follower that jumped far (O(triangles)).
 */
final class SurfacePairing {
    /** Moves of the walk per call at most (the rest continues at the next call). */
    static final int MAX_STEPS = 16;

    private final int[] tri; // 3 point ids per triangle
    private final int[] around; // triangles sharing a vertex with triangle t: around[aroundStart[t]..]
    private final int[] aroundStart;
    private final int[] across; // 3 per triangle: the triangle across the edge opposite corner c, or -1 (border)

    /**
     * @param triangles  3 point ids per triangle (outward normal by the right-hand rule on the winding)
     * @param pointCount number of surface points
     * @throws IllegalArgumentException naming the triangle whose point id is out of range or repeated
     */
    SurfacePairing(int[] triangles, int pointCount) {
        if (triangles.length == 0 || triangles.length % 3 != 0) {
            throw new IllegalArgumentException("a sliding surface needs triangles, 3 point ids each: got "
                    + triangles.length + " ids");
        }
        tri = triangles.clone();
        int n = tri.length / 3;
        Map<Long, Integer> edges = new HashMap<>();
        across = new int[3 * n];
        Arrays.fill(across, -1);
        @SuppressWarnings("unchecked")
        Set<Integer>[] byPoint = new Set[pointCount];
        for (int t = 0; t < n; t++) {
            for (int c = 0; c < 3; c++) {
                int p = tri[3 * t + c];
                if (p < 0 || p >= pointCount) {
                    throw new IllegalArgumentException("sliding surface triangle " + t + " has point " + p
                            + ": expected a point id in [0, " + pointCount + ")");
                }
                if (p == tri[3 * t + (c + 1) % 3]) {
                    throw new IllegalArgumentException("sliding surface triangle " + t + " repeats point " + p);
                }
                (byPoint[p] == null ? byPoint[p] = new LinkedHashSet<>() : byPoint[p]).add(t);
            }
            for (int c = 0; c < 3; c++) {
                int a = tri[3 * t + (c + 1) % 3];
                int b = tri[3 * t + (c + 2) % 3];
                long key = (long) Math.min(a, b) * pointCount + Math.max(a, b);
                Integer other = edges.putIfAbsent(key, 3 * t + c);
                if (other != null) {
                    across[3 * t + c] = other / 3;
                    across[other] = t;
                }
            }
        }
        aroundStart = new int[n + 1];
        int[][] lists = new int[n][];
        for (int t = 0; t < n; t++) {
            Set<Integer> s = new LinkedHashSet<>();
            for (int c = 0; c < 3; c++) {
                s.addAll(byPoint[tri[3 * t + c]]);
            }
            s.remove(t);
            lists[t] = s.stream().mapToInt(Integer::intValue).toArray();
            aroundStart[t + 1] = aroundStart[t] + lists[t].length;
        }
        around = new int[aroundStart[n]];
        for (int t = 0; t < n; t++) {
            System.arraycopy(lists[t], 0, around, aroundStart[t], lists[t].length);
        }
    }

    int triangleCount() {
        return tri.length / 3;
    }

    /** Point id of triangle t's corner c (0..2). */
    int corner(int t, int c) {
        return tri[3 * t + c];
    }

    /**
     * The plane of triangle t at point positions p against the point y = (x[yo], x[yo+1], x[yo+2]) (m): writes
     * {@code out[0..2]} = unit normal n (right-hand rule on the winding), {@code out[3]} = d = n . (y - a) (m, +
     * outside), {@code out[4..6]} = barycentric coordinates of the projection y - d n (they sum to 1; one is negative
     * when the projection is outside the triangle).
     *
     * @return false (out untouched) when the triangle is degenerate (zero area)
     */
    boolean plane(double[] p, int t, double[] x, int yo, double[] out) {
        int a = 3 * tri[3 * t];
        int b = 3 * tri[3 * t + 1];
        int c = 3 * tri[3 * t + 2];
        double e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
        double e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
        double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
        double n2 = nx * nx + ny * ny + nz * nz;
        if (!(n2 > 0)) {
            return false;
        }
        double rx = x[yo] - p[a], ry = x[yo + 1] - p[a + 1], rz = x[yo + 2] - p[a + 2];
        // beta_b = (r x e2) . N / |N|^2 and beta_c = (e1 x r) . N / |N|^2: the normal part of r drops out.
        double bb = ((ry * e2z - rz * e2y) * nx + (rz * e2x - rx * e2z) * ny + (rx * e2y - ry * e2x) * nz) / n2;
        double bc = ((e1y * rz - e1z * ry) * nx + (e1z * rx - e1x * rz) * ny + (e1x * ry - e1y * rx) * nz) / n2;
        double inv = 1 / Math.sqrt(n2);
        out[0] = nx * inv;
        out[1] = ny * inv;
        out[2] = nz * inv;
        out[3] = (rx * nx + ry * ny + rz * nz) * inv;
        out[4] = 1 - bb - bc;
        out[5] = bb;
        out[6] = bc;
        return true;
    }

    /**
     * True when the projection whose barycentric coordinates are {@code bary[4..6]} (as {@link #plane} writes them)
     * lies beyond a border edge of triangle t: its most negative coordinate is opposite an edge no other triangle
     * shares. Such a follower is off the (open) surface, past its rim.
     */
    boolean beyondBorder(int t, double[] bary) {
        int c = bary[4] <= bary[5] ? (bary[4] <= bary[6] ? 0 : 2) : (bary[5] <= bary[6] ? 1 : 2);
        return bary[4 + c] < 0 && across[3 * t + c] < 0;
    }

    /**
     * Squared distance (m^2) from y = (x[yo..yo+2]) to the closest point of triangle t at point positions p
     * (Ericson, Real-Time Collision Detection, 2005, section 5.1.5: the Voronoi regions of the corners, edges and
     * face). Allocation-free.
     */
    double closestDistance2(double[] p, int t, double[] x, int yo) {
        int ia = 3 * tri[3 * t];
        int ib = 3 * tri[3 * t + 1];
        int ic = 3 * tri[3 * t + 2];
        double ax = p[ia], ay = p[ia + 1], az = p[ia + 2];
        double abx = p[ib] - ax, aby = p[ib + 1] - ay, abz = p[ib + 2] - az;
        double acx = p[ic] - ax, acy = p[ic + 1] - ay, acz = p[ic + 2] - az;
        double apx = x[yo] - ax, apy = x[yo + 1] - ay, apz = x[yo + 2] - az;
        double d1 = abx * apx + aby * apy + abz * apz;
        double d2 = acx * apx + acy * apy + acz * apz;
        if (d1 <= 0 && d2 <= 0) {
            return apx * apx + apy * apy + apz * apz; // corner a
        }
        double bpx = apx - abx, bpy = apy - aby, bpz = apz - abz;
        double d3 = abx * bpx + aby * bpy + abz * bpz;
        double d4 = acx * bpx + acy * bpy + acz * bpz;
        if (d3 >= 0 && d4 <= d3) {
            return bpx * bpx + bpy * bpy + bpz * bpz; // corner b
        }
        double vc = d1 * d4 - d3 * d2;
        double v;
        double w;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            v = d1 / (d1 - d3); // edge ab
            return dist2(apx, apy, apz, v * abx, v * aby, v * abz);
        }
        double cpx = apx - acx, cpy = apy - acy, cpz = apz - acz;
        double d5 = abx * cpx + aby * cpy + abz * cpz;
        double d6 = acx * cpx + acy * cpy + acz * cpz;
        if (d6 >= 0 && d5 <= d6) {
            return cpx * cpx + cpy * cpy + cpz * cpz; // corner c
        }
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            w = d2 / (d2 - d6); // edge ac
            return dist2(apx, apy, apz, w * acx, w * acy, w * acz);
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
            w = (d4 - d3) / ((d4 - d3) + (d5 - d6)); // edge bc
            return dist2(apx, apy, apz, abx + w * (acx - abx), aby + w * (acy - aby), abz + w * (acz - abz));
        }
        double denom = 1 / (va + vb + vc); // face
        v = vb * denom;
        w = vc * denom;
        return dist2(apx, apy, apz, v * abx + w * acx, v * aby + w * acy, v * abz + w * acz);
    }

    private static double dist2(double ax, double ay, double az, double bx, double by, double bz) {
        double dx = ax - bx, dy = ay - by, dz = az - bz;
        return dx * dx + dy * dy + dz * dz;
    }

    /** The triangle whose closest point to y = (x[yo..yo+2]) is nearest, by testing all of them (the first of ties). */
    int nearest(double[] p, double[] x, int yo) {
        int best = 0;
        double bestD = Double.POSITIVE_INFINITY;
        for (int t = 0, n = triangleCount(); t < n; t++) {
            double d = closestDistance2(p, t, x, yo);
            if (d < bestD) {
                bestD = d;
                best = t;
            }
        }
        return best;
    }

    /**
     * The walk from triangle {@code start} for y = (x[yo..yo+2]) (see the class comment); {@code scratch} (7
     * doubles) receives the {@link #plane} of the triangle returned. Allocation-free.
     *
     * @return the triangle the follower is paired with now; -1 if it is degenerate (zero area)
     */
    int walk(double[] p, int start, double[] x, int yo, double[] scratch) {
        int t = start;
        for (int step = 0; step <= MAX_STEPS; step++) {
            if (!plane(p, t, x, yo, scratch)) {
                return -1;
            }
            if (step == MAX_STEPS || (scratch[4] >= 0 && scratch[5] >= 0 && scratch[6] >= 0)) {
                return t;
            }
            int best = t;
            double bestD = closestDistance2(p, t, x, yo);
            for (int k = aroundStart[t]; k < aroundStart[t + 1]; k++) {
                double d = closestDistance2(p, around[k], x, yo);
                if (d < bestD) {
                    bestD = d;
                    best = around[k];
                }
            }
            if (best == t) {
                return t; // a local minimum of the distance: the follower is nearest this triangle's rim
            }
            t = best;
        }
        return t;
    }
}
