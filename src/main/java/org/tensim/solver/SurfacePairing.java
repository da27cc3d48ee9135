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
    private final double[] sphere; // 4 per triangle: bounding sphere's centre and radius, m ({@link #bound})

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
        sphere = new double[4 * n];
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
     * True when the follower whose frame {@link #walk} wrote into {@code frame} is beyond a border edge of its
     * triangle: its projection's most negative barycentric coordinate is opposite an edge no other triangle shares.
     * Such a follower is off the (open) surface, past its rim.
     */
    static boolean beyondBorder(double[] frame) {
        return frame[7] != 0;
    }

    private boolean projectionBeyondBorder(int t, double[] bary) {
        int c = smallest(bary);
        return bary[4 + c] < 0 && across[3 * t + c] < 0;
    }

    /** The corner (0..2) whose barycentric coordinate in {@code bary[4..6]} is the smallest: its opposite edge. */
    private static int smallest(double[] bary) {
        return bary[4] <= bary[5] ? (bary[4] <= bary[6] ? 0 : 2) : (bary[5] <= bary[6] ? 1 : 2);
    }

    /**
     * Turns the plane of triangle t in {@code out} (as {@link #plane} wrote it for y) into the follower's frame: where
     * the projection is inside the triangle, the plane itself; where it is outside (the follower nearest the
     * triangle's rim), the closest point's: {@code out[4..6]} its barycentric coordinates (>= 0), {@code out[3]} = d
     * = s |y - c| and {@code out[0..2]} = u = s (y - c) / |y - c|, the sign s that of the paired triangle's normal plus
     * the normal across the closest edge (an edge's pseudo-normal) dotted with y - c. So d is the signed distance to
     * the surface, continuous when the pairing moves across an edge at a fold: two triangles meeting at an edge have
     * the same closest point there, where their two extended planes would give distances that differ by about
     * |y - c| times the fold's angle. {@code E = k (g - d)^2 / 2} is still exactly minus the gradient of the forces
     * along u: the closest point minimises the distance over the triangle, so its own motion drops out (the envelope
     * theorem). {@code out[7]} = 1 when the projection is beyond a border edge ({@link #beyondBorder}), else 0.
     *
     * @return t
     */
    private int frame(double[] p, int t, double[] x, int yo, double[] out) {
        out[7] = projectionBeyondBorder(t, out) ? 1 : 0;
        if (out[4] >= 0 && out[5] >= 0 && out[6] >= 0) {
            return t;
        }
        double sx = out[0], sy = out[1], sz = out[2];
        double d2 = closest(p, t, x, yo, out);
        int o = across[3 * t + smallest(out)];
        if (o >= 0) {
            int a = 3 * tri[3 * o], b = 3 * tri[3 * o + 1], q = 3 * tri[3 * o + 2];
            double e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
            double e2x = p[q] - p[a], e2y = p[q + 1] - p[a + 1], e2z = p[q + 2] - p[a + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (len > 0) {
                sx += nx / len;
                sy += ny / len;
                sz += nz / len;
            }
        }
        int ia = 3 * tri[3 * t], ib = 3 * tri[3 * t + 1], ic = 3 * tri[3 * t + 2];
        double dx = x[yo] - (out[4] * p[ia] + out[5] * p[ib] + out[6] * p[ic]);
        double dy = x[yo + 1] - (out[4] * p[ia + 1] + out[5] * p[ib + 1] + out[6] * p[ic + 1]);
        double dz = x[yo + 2] - (out[4] * p[ia + 2] + out[5] * p[ib + 2] + out[6] * p[ic + 2]);
        double dist = Math.sqrt(d2);
        if (dist > 0) {
            double sign = sx * dx + sy * dy + sz * dz < 0 ? -1 : 1;
            out[0] = sign * dx / dist;
            out[1] = sign * dy / dist;
            out[2] = sign * dz / dist;
            out[3] = sign * dist;
        } else {
            out[3] = 0; // on the rim: the triangle's normal stands
        }
        return t;
    }

    /**
     * Squared distance (m^2) from y = (x[yo..yo+2]) to the closest point of triangle t at point positions p
     * (Ericson, Real-Time Collision Detection, 2005, section 5.1.5: the Voronoi regions of the corners, edges and
     * face). Allocation-free.
     */
    double closestDistance2(double[] p, int t, double[] x, int yo) {
        return closest(p, t, x, yo, null);
    }

    /**
     * As {@link #closestDistance2}, writing the closest point's barycentric coordinates (>= 0, summing to 1) into
     * {@code bary[4..6]} when bary is not null.
     */
    private double closest(double[] p, int t, double[] x, int yo, double[] bary) {
        int ia = 3 * tri[3 * t];
        int ib = 3 * tri[3 * t + 1];
        int ic = 3 * tri[3 * t + 2];
        double ax = p[ia], ay = p[ia + 1], az = p[ia + 2];
        double abx = p[ib] - ax, aby = p[ib + 1] - ay, abz = p[ib + 2] - az;
        double acx = p[ic] - ax, acy = p[ic + 1] - ay, acz = p[ic + 2] - az;
        double apx = x[yo] - ax, apy = x[yo + 1] - ay, apz = x[yo + 2] - az;
        double d1 = abx * apx + aby * apy + abz * apz;
        double d2 = acx * apx + acy * apy + acz * apz;
        double v;
        double w;
        // Ericson's order, each region's products computed only once the earlier regions are ruled out.
        region: {
            if (d1 <= 0 && d2 <= 0) {
                v = 0; // corner a
                w = 0;
                break region;
            }
            double bpx = apx - abx, bpy = apy - aby, bpz = apz - abz;
            double d3 = abx * bpx + aby * bpy + abz * bpz;
            double d4 = acx * bpx + acy * bpy + acz * bpz;
            if (d3 >= 0 && d4 <= d3) {
                v = 1; // corner b
                w = 0;
                break region;
            }
            double vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) {
                v = d1 / (d1 - d3); // edge ab
                w = 0;
                break region;
            }
            double cpx = apx - acx, cpy = apy - acy, cpz = apz - acz;
            double d5 = abx * cpx + aby * cpy + abz * cpz;
            double d6 = acx * cpx + acy * cpy + acz * cpz;
            if (d6 >= 0 && d5 <= d6) {
                v = 0; // corner c
                w = 1;
                break region;
            }
            double vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) {
                v = 0; // edge ac
                w = d2 / (d2 - d6);
                break region;
            }
            double va = d3 * d6 - d5 * d4;
            if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
                w = (d4 - d3) / ((d4 - d3) + (d5 - d6)); // edge bc
                v = 1 - w;
                break region;
            }
            double denom = 1 / (va + vb + vc); // face
            v = vb * denom;
            w = vc * denom;
        }
        if (bary != null) {
            bary[4] = 1 - v - w;
            bary[5] = v;
            bary[6] = w;
        }
        return dist2(apx, apy, apz, v * abx + w * acx, v * aby + w * acy, v * abz + w * acz);
    }

    private static double dist2(double ax, double ay, double az, double bx, double by, double bz) {
        double dx = ax - bx, dy = ay - by, dz = az - bz;
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * Bounds every triangle at point positions p by a sphere (its centroid, and its farthest corner's distance from
     * it), for {@link #nearest}. Allocation-free.
     */
    void bound(double[] p) {
        for (int t = 0, n = triangleCount(); t < n; t++) {
            int a = 3 * tri[3 * t], b = 3 * tri[3 * t + 1], c = 3 * tri[3 * t + 2];
            double r2 = 0;
            for (int k = 0; k < 3; k++) {
                sphere[4 * t + k] = (p[a + k] + p[b + k] + p[c + k]) / 3;
            }
            for (int k = 0; k < 3; k++) {
                int corner = 3 * tri[3 * t + k];
                double dx = p[corner] - sphere[4 * t], dy = p[corner + 1] - sphere[4 * t + 1];
                double dz = p[corner + 2] - sphere[4 * t + 2];
                r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
            }
            sphere[4 * t + 3] = Math.sqrt(r2);
        }
    }

    /**
     * The triangle whose closest point to y = (x[yo..yo+2]) is nearest, by testing all of them (the first of ties),
     * at the positions p last {@link #bound bounded}: a triangle whose sphere is farther than the best distance so far
     * cannot be nearer and is not tested further.
     */
    int nearest(double[] p, double[] x, int yo) {
        int best = 0;
        double bestD = Double.POSITIVE_INFINITY;
        for (int t = 0, n = triangleCount(); t < n; t++) {
            double cx = x[yo] - sphere[4 * t], cy = x[yo + 1] - sphere[4 * t + 1], cz = x[yo + 2] - sphere[4 * t + 2];
            double lower = Math.sqrt(cx * cx + cy * cy + cz * cz) - sphere[4 * t + 3];
            if (lower > 0 && lower * lower >= bestD) {
                continue;
            }
            double d = closestDistance2(p, t, x, yo);
            if (d < bestD) {
                bestD = d;
                best = t;
            }
        }
        return best;
    }

    /**
     * The walk from triangle {@code start} for y = (x[yo..yo+2]) (see the class comment); {@code scratch} (8
     * doubles) receives the follower's frame against the triangle returned ({@link #frame}: its plane where the
     * projection is inside it, its closest point's otherwise). Allocation-free.
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
                return frame(p, t, x, yo, scratch);
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
                return frame(p, t, x, yo, scratch); // a local minimum of the distance: nearest this triangle's rim
            }
            t = best;
        }
        return t;
    }
}
