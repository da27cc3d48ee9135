package org.tensim.scene.thorax;

import org.tensim.io.mesh.SurfaceDistance;

/**
 * A bounding-volume hierarchy over a triangle surface for the two queries a distance grid is built from: the
 * distance to the nearest triangle (exact: Ericson's closest point, pruned by box distance; also as the triangle
 * and the closest point's barycentric weights, {@link #nearest}) and the generalised
 * winding number (Jacobson, Kavan and Sorkine-Hornung, SIGGRAPH 2013), summed exactly over nearby triangles and,
 * for clusters seen from farther than {@code beta} times their radius, by their dipole term (the first-order
 * approximation of Barill et al., "Fast winding numbers for soups and clouds", SIGGRAPH 2018). The winding number is
 * 1 inside a closed, outward-wound surface, 0 outside, and changes smoothly across a small hole, so "inside where
 * it exceeds 1/2" tolerates the holes and non-manifold edges of segmented bones.
 *
 * <p>Used by {@link DistanceGrid} (signs of a bone's distance field), by the volume body's clipping of a lattice
 * to a closed surface ({@code org.tensim.scene.volume}) and by the shell mapping's search for the wedge a fine
 * point lies in ({@code org.tensim.scene.diaphragm.ShellMapping}).
 *
 * <p>Queries do not allocate beyond the stack the caller passes ({@link #newStack()}), so one tree can be queried
 * from several threads, each with its own stack.
 */
public final class TriangleTree {
    private static final int LEAF = 8;
    private static final double FOUR_PI = 4 * Math.PI;

    private final double[] x;
    private final int[] tri;
    /** Triangle ids in tree order: node n covers order[start[n] .. start[n] + count[n]). */
    private final int[] order;
    private final double[] lo;
    private final double[] hi;
    private final int[] start;
    private final int[] count;
    /** Index of the first child (the second is the next node built after the first's subtree): -1 for leaves. */
    private final int[] left;
    private final int[] right;
    /** Area-weighted normal sum (half the cross products), area-weighted centroid, and radius about it. */
    private final double[] dipole;
    private final double[] centre;
    private final double[] radius;
    private int nodes;
    private final double beta;

    /**
     * @param xyz       vertex coordinates, m, 3 per vertex
     * @param triangles vertex indices, 3 per triangle, counter-clockwise seen from outside
     * @param beta      far-field ratio: a cluster is summed as one dipole when the point is farther than beta times
     *                  its radius from its centroid (2 in Barill et al.; larger is more exact and slower)
     */
    public TriangleTree(double[] xyz, int[] triangles, double beta) {
        if (triangles.length == 0) {
            throw new IllegalArgumentException("a distance grid needs at least one triangle");
        }
        this.x = xyz;
        this.tri = triangles;
        this.beta = beta;
        int n = triangles.length / 3;
        order = new int[n];
        for (int t = 0; t < n; t++) {
            order[t] = t;
        }
        int cap = n + 1; // median splits leave at least LEAF / 2 triangles a leaf: far fewer nodes than this
        lo = new double[3 * cap];
        hi = new double[3 * cap];
        start = new int[cap];
        count = new int[cap];
        left = new int[cap];
        right = new int[cap];
        dipole = new double[3 * cap];
        centre = new double[3 * cap];
        radius = new double[cap];
        double[] tc = new double[3 * n];
        for (int t = 0; t < n; t++) {
            for (int a = 0; a < 3; a++) {
                tc[3 * t + a] = (c(t, 0, a) + c(t, 1, a) + c(t, 2, a)) / 3;
            }
        }
        build(0, n, tc);
    }

    /** A traversal stack for one thread's queries. */
    public int[] newStack() {
        return new int[Math.max(64, 2 * nodes)];
    }

    int nodeCount() {
        return nodes;
    }

    private double c(int t, int k, int a) {
        return x[3 * tri[3 * t + k] + a];
    }

    /** Builds the subtree over order[from, to): split at the median centroid along the box's longest axis. */
    private int build(int from, int to, double[] tc) {
        int id = nodes++;
        start[id] = from;
        count[id] = to - from;
        double[] b = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double nx = 0, ny = 0, nz = 0, cx = 0, cy = 0, cz = 0, area = 0;
        for (int i = from; i < to; i++) {
            int t = order[i];
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++) {
                    b[a] = Math.min(b[a], c(t, k, a));
                    b[a + 3] = Math.max(b[a + 3], c(t, k, a));
                }
            }
            double ux = c(t, 1, 0) - c(t, 0, 0), uy = c(t, 1, 1) - c(t, 0, 1), uz = c(t, 1, 2) - c(t, 0, 2);
            double vx = c(t, 2, 0) - c(t, 0, 0), vy = c(t, 2, 1) - c(t, 0, 1), vz = c(t, 2, 2) - c(t, 0, 2);
            double ax = 0.5 * (uy * vz - uz * vy), ay = 0.5 * (uz * vx - ux * vz), az = 0.5 * (ux * vy - uy * vx);
            double a = Math.sqrt(ax * ax + ay * ay + az * az);
            nx += ax;
            ny += ay;
            nz += az;
            cx += a * tc[3 * t];
            cy += a * tc[3 * t + 1];
            cz += a * tc[3 * t + 2];
            area += a;
        }
        if (area > 0) {
            cx /= area;
            cy /= area;
            cz /= area;
        } else {
            cx = (b[0] + b[3]) / 2;
            cy = (b[1] + b[4]) / 2;
            cz = (b[2] + b[5]) / 2;
        }
        double r = 0;
        for (int i = from; i < to; i++) {
            for (int k = 0; k < 3; k++) {
                int t = order[i];
                r = Math.max(r, Math.sqrt(sq(c(t, k, 0) - cx) + sq(c(t, k, 1) - cy) + sq(c(t, k, 2) - cz)));
            }
        }
        for (int a = 0; a < 3; a++) {
            lo[3 * id + a] = b[a];
            hi[3 * id + a] = b[a + 3];
        }
        dipole[3 * id] = nx;
        dipole[3 * id + 1] = ny;
        dipole[3 * id + 2] = nz;
        centre[3 * id] = cx;
        centre[3 * id + 1] = cy;
        centre[3 * id + 2] = cz;
        radius[id] = r;
        if (to - from <= LEAF) {
            left[id] = -1;
            right[id] = -1;
            return id;
        }
        int axis = 0;
        for (int a = 1; a < 3; a++) {
            if (b[a + 3] - b[a] > b[axis + 3] - b[axis]) {
                axis = a;
            }
        }
        int mid = (from + to) >>> 1;
        select(from, to - 1, mid, axis, tc);
        left[id] = build(from, mid, tc);
        right[id] = build(mid, to, tc);
        return id;
    }

    /** Quickselect: puts the triangle of rank k (by centroid along axis) at order[k], smaller ones before it. */
    private void select(int l, int r, int k, int axis, double[] tc) {
        while (l < r) {
            double pivot = tc[3 * order[(l + r) >>> 1] + axis];
            int i = l;
            int j = r;
            while (i <= j) {
                while (tc[3 * order[i] + axis] < pivot) {
                    i++;
                }
                while (tc[3 * order[j] + axis] > pivot) {
                    j--;
                }
                if (i <= j) {
                    int s = order[i];
                    order[i] = order[j];
                    order[j] = s;
                    i++;
                    j--;
                }
            }
            if (k <= j) {
                r = j;
            } else if (k >= i) {
                l = i;
            } else {
                return;
            }
        }
    }

    /** Distance from the point to the nearest triangle, m. */
    public double distance(double px, double py, double pz, int[] stack) {
        int t = nearest(px, py, pz, stack, null);
        return Math.sqrt(SurfaceDistance.closest(x, tri, t, px, py, pz, null));
    }

    /**
     * The triangle nearest the point (its index in the triangles given), with in {@code out} (length at least 4,
     * or null) the barycentric weights of the closest point on it, of its corners in their order (out[0..2]), and
     * the squared distance to it (out[3], m^2). Of triangles at the same distance, the first searched is taken.
     */
    public int nearest(double px, double py, double pz, int[] stack, double[] out) {
        double best = Double.POSITIVE_INFINITY;
        int bestT = -1;
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            int n = stack[--top];
            if (boxSq(n, px, py, pz) >= best) {
                continue;
            }
            if (left[n] < 0) {
                for (int i = start[n], e = start[n] + count[n]; i < e; i++) {
                    double d = SurfaceDistance.closest(x, tri, order[i], px, py, pz, null);
                    if (d < best) {
                        best = d;
                        bestT = order[i];
                    }
                }
                continue;
            }
            // the nearer child is pushed last so that it is searched first and prunes the other
            int a = left[n];
            int b = right[n];
            if (boxSq(a, px, py, pz) < boxSq(b, px, py, pz)) {
                stack[top++] = b;
                stack[top++] = a;
            } else {
                stack[top++] = a;
                stack[top++] = b;
            }
        }
        if (out != null) {
            out[3] = SurfaceDistance.closest(x, tri, bestT, px, py, pz, out);
        }
        return bestT;
    }

    private double boxSq(int n, double px, double py, double pz) {
        double dx = Math.max(0, Math.max(lo[3 * n] - px, px - hi[3 * n]));
        double dy = Math.max(0, Math.max(lo[3 * n + 1] - py, py - hi[3 * n + 1]));
        double dz = Math.max(0, Math.max(lo[3 * n + 2] - pz, pz - hi[3 * n + 2]));
        return dx * dx + dy * dy + dz * dz;
    }

    /** Generalised winding number at the point: about 1 inside, 0 outside (dimensionless). */
    public double winding(double px, double py, double pz, int[] stack) {
        double w = 0;
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            int n = stack[--top];
            double dx = centre[3 * n] - px, dy = centre[3 * n + 1] - py, dz = centre[3 * n + 2] - pz;
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 > sq(beta * radius[n])) {
                // far field: the cluster's solid angle is that of its summed area vector at its centroid
                w += (dipole[3 * n] * dx + dipole[3 * n + 1] * dy + dipole[3 * n + 2] * dz) / (d2 * Math.sqrt(d2));
            } else if (left[n] < 0) {
                for (int i = start[n], e = start[n] + count[n]; i < e; i++) {
                    w += solidAngle(order[i], px, py, pz);
                }
            } else {
                stack[top++] = left[n];
                stack[top++] = right[n];
            }
        }
        return w / FOUR_PI;
    }

    /**
     * Signed solid angle of triangle t seen from the point (Van Oosterom and Strackee 1983), sr: positive when the
     * point lies behind the triangle (on the side opposite its counter-clockwise normal).
     */
    private double solidAngle(int t, double px, double py, double pz) {
        int ia = 3 * tri[3 * t], ib = 3 * tri[3 * t + 1], ic = 3 * tri[3 * t + 2];
        double ax = x[ia] - px, ay = x[ia + 1] - py, az = x[ia + 2] - pz;
        double bx = x[ib] - px, by = x[ib + 1] - py, bz = x[ib + 2] - pz;
        double cx = x[ic] - px, cy = x[ic + 1] - py, cz = x[ic + 2] - pz;
        double la = Math.sqrt(ax * ax + ay * ay + az * az);
        double lb = Math.sqrt(bx * bx + by * by + bz * bz);
        double lc = Math.sqrt(cx * cx + cy * cy + cz * cz);
        double det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
        double den = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (ax * cx + ay * cy + az * cz) * lb
                + (bx * cx + by * cy + bz * cz) * la;
        return 2 * Math.atan2(det, den);
    }

    private static double sq(double v) {
        return v * v;
    }
}
