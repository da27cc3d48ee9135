package org.tensim.solver;

import java.util.Arrays;
import org.tensim.model.LinearMapping;

/**
 * Follower nodes sliding on (or touching) a moving, deforming surface carried by other nodes of the same state: the
 * frictionless coupling of two deformable bodies (the lung on the pleura carried by the diaphragm and the ribs, the
 * liver pushed by the diaphragm's lower surface). The surface's points are {@code p = W x}, a {@link LinearMapping}
 * of the state's nodes (driven and fixed nodes may carry points: the forces they receive are ignored by their zero
 * inverse mass); its triangles join the points, outward normal by the right-hand rule on the winding.
 *
 * <p>The followers are nodes of the state or points mapped from its nodes, {@code y = V x} (a lung's surface
 * vertices carried by its lattice, {@link #mapped}); a mapped follower's force reaches its nodes by {@code V^T}, as
 * the surface's does by {@code W^T}, so the pair's total force and moment still vanish at the nodes.
 *
 * <p>Follower i (position y, stiffness k_i in N/m, gap g_i in m) is paired with a triangle (a, b, c) of unit normal
 * n; with {@code d = n . (y - a)} its signed distance to the triangle's plane (m, + outside) and {@code pen = g - d}:
 * <pre>
 *   SLIDING (bilateral):  E = k pen^2 / 2            (held at distance g, on both sides)
 *   CONTACT (one-sided):  E = k max(0, pen)^2 / 2    (pushed out to the gap along +n, free to leave)
 *   f_follower = -dE/dd n = k pen n                  (along n only: frictionless)
 *   f_corner_j = -k pen beta_j n,  j = a, b, c        (beta: barycentric coordinates of the projection y - d n)
 *   F_nodes   += W^T f_corners + V^T f_followers      ({@link LinearMapping#addTranspose})
 * </pre>
 * These are exactly minus the gradient of E for the pairing held: moving a corner along the plane leaves the plane,
 * so d, unchanged, and moving corner j by e along n raises the plane under the projection by beta_j e, so
 * {@code dd/dx_j = -beta_j n} with n's rotation included (nothing neglected). The reaction is equal and opposite to
 * the follower's force and acts at the projection, on the force's line: the total force and the total moment vanish
 * at the points, and so at the nodes (the mapping's weights sum to 1 and carry moments exactly).
 *
 * <p>Pairing: each follower with its nearest triangle (closest point), by brute force at construction, then kept up
 * to date at every force pass by a local walk over triangles sharing a vertex ({@link SurfacePairing}, which says
 * why). The pairing is the one state this term changes; {@link #energy} and the read-outs walk from it without
 * storing. A pairing change moves a follower to another plane, continuous where the surface is flat and a jump of
 * the energy of order {@code k pen^2 theta} at an edge of angle theta. A CONTACT follower whose projection is past
 * a border edge of an open surface is off the surface and takes no force (otherwise the extended plane of the rim
 * triangle would push nodes that are nowhere near); a SLIDING follower stays held to that plane.
 *
 * <p>Stability: for an explicit step the stiffness counts against the followers' and the surface nodes' masses,
 * {@code dt < 2 sqrt(m / k)}. {@code bdf2}'s Newton-Krylov products take the term's tangent ({@link #linearise},
 * {@link #multiplyAdd}: the Gauss-Newton part along the normals, {@link SlidingTangent}) and its prefactored
 * preconditioner the isotropic part at the rest pairing ({@link #addIsotropicStiffness}), so a stiff coupling is as
 * stable under it as the body's own springs. Allocation-free in {@link #addForces} and the products; {@link #energy}
 * and the read-outs use their own scratch under a lock, and may run on another thread on a copy of the positions.
 */
public final class SurfaceSliding implements ForceTerm {
    /** How a follower is held: {@link #SLIDING} bilateral, {@link #CONTACT} one-sided. */
    public enum Mode {
        /** E = k (g - d)^2 / 2: kept at the gap from both sides, free tangentially (the pleura). */
        SLIDING,
        /** E = k max(0, g - d)^2 / 2: pushed out along +n when closer than the gap, free to separate. */
        CONTACT
    }

    private final LinearMapping followers; // y = V x: a node per row for node followers
    private final double[] stiffness; // N/m per follower
    private final double[] gap; // m per follower
    private final Mode mode;
    private final LinearMapping mapping;
    private final SurfacePairing surface;
    private final int[] pair; // triangle per follower
    private final double[] points; // force pass: p = W x, 3 per point
    private final double[] pointForces; // force pass: 3 per point, N
    private final double[] ys; // force pass: follower positions, 3 per follower, m
    private final double[] followerForces; // force pass: 3 per follower, N
    private final double[] readYs; // energy and read-outs (under readLock)
    private final double[] linYs; // linearisation
    private final double[] plane = new double[8]; // force pass: n, d, beta, beyond a border
    private final double[] readPoints; // energy and read-outs (under readLock)
    private final double[] readPlane = new double[8];
    private final Object readLock = new Object();
    private final double[] linPoints; // linearisation: p = W x
    private final double[] linPlane = new double[8];
    private final SlidingTangent tangent; // the planes of the last linearisation
    private final SlidingTangent restTangent; // every follower's plane at construction, for the preconditioner

    /**
     * A term with one gap for all followers.
     *
     * @see #SurfaceSliding(int[], LinearMapping, int[], double[], Mode, double[], double[])
     */
    public SurfaceSliding(int[] followers, LinearMapping surfacePoints, int[] triangles, double[] stiffness, Mode mode,
            double gapM, double[] x) {
        this(followers, surfacePoints, triangles, stiffness, mode, filled(followers.length, gapM), x);
    }

    /**
     * @param followers     node ids (of the state x belongs to) that slide, each once, none carrying a surface point
     * @param surfacePoints the surface's points as a mapping of the same state's nodes
     * @param triangles     3 point ids each, outward normal by the right-hand rule on the winding
     * @param stiffness     per follower, N/m, positive ({@link SlidingStiffness} makes them from Pa/m and areas)
     * @param mode          bilateral {@link Mode#SLIDING} or one-sided {@link Mode#CONTACT}
     * @param gapsM         per follower, the distance g it is held at (SLIDING) or kept beyond (CONTACT), m, finite
     * @param x             the state's positions to pair the followers at, m, 3 per node
     * @throws IllegalArgumentException naming the value: a follower out of range, repeated or carrying a surface
     *                                  point; a stiffness or gap not positive or finite; a degenerate triangle
     */
    public SurfaceSliding(int[] followers, LinearMapping surfacePoints, int[] triangles, double[] stiffness, Mode mode,
            double[] gapsM, double[] x) {
        this(SlidingChecks.nodeFollowers(followers, x.length / 3), surfacePoints, triangles, stiffness, mode, gapsM,
                x);
    }

    /**
     * A term whose followers are points mapped from the state's nodes, {@code y = V x} (a lung's surface vertices
     * carried by its lattice): each follower's force reaches its nodes by V's transpose.
     *
     * @param followers the followers' points on the state's nodes, none of whose nodes carries a surface point
     * @see #SurfaceSliding(int[], LinearMapping, int[], double[], Mode, double[], double[]) the other arguments
     */
    public static SurfaceSliding mapped(LinearMapping followers, LinearMapping surfacePoints, int[] triangles,
            double[] stiffness, Mode mode, double[] gapsM, double[] x) {
        return new SurfaceSliding(followers, surfacePoints, triangles, stiffness, mode, gapsM, x);
    }

    private SurfaceSliding(LinearMapping followers, LinearMapping surfacePoints, int[] triangles,
            double[] stiffness, Mode mode, double[] gapsM, double[] x) {
        SlidingChecks.refuse(followers, surfacePoints, stiffness, gapsM, mode, x.length / 3);
        this.followers = followers;
        this.stiffness = stiffness.clone();
        this.gap = gapsM.clone();
        this.mode = mode;
        this.mapping = surfacePoints;
        this.surface = new SurfacePairing(triangles, surfacePoints.pointCount());
        this.points = new double[3 * surfacePoints.pointCount()];
        this.pointForces = new double[points.length];
        this.readPoints = new double[points.length];
        this.linPoints = new double[points.length];
        int n = followers.pointCount();
        this.ys = new double[3 * n];
        this.followerForces = new double[3 * n];
        this.readYs = new double[3 * n];
        this.linYs = new double[3 * n];
        mapping.apply(x, points);
        for (int t = 0; t < surface.triangleCount(); t++) {
            if (!surface.plane(points, t, x, 0, plane)) {
                throw new IllegalArgumentException("sliding surface triangle " + t + " (points "
                        + surface.corner(t, 0) + ", " + surface.corner(t, 1) + ", " + surface.corner(t, 2)
                        + ") has zero area: expected a triangle with three distinct corners");
            }
        }
        this.pair = new int[n];
        repair(x);
        this.tangent = new SlidingTangent(followers, this.stiffness, mapping, surface);
        this.restTangent = new SlidingTangent(followers, this.stiffness, mapping, surface);
        followers.apply(x, ys);
        for (int e = 0; e < n; e++) {
            int tri = surface.walk(points, pair[e], ys, 3 * e, plane);
            restTangent.set(e, tri, plane);
        }
    }

    /**
     * A term whose followers are held where they are at x, as a scene's conditions hold them: a SLIDING follower at
     * its rest distance d0 to the surface (gap d0), a CONTACT follower beyond min(gap, d0) (one that starts closer
     * than the gap is held from going deeper, not thrown out); one off the surface at x gets {@code gapM}. Pairs
     * once (the constructor's arguments and refusals otherwise).
     */
    public static SurfaceSliding heldAtRest(int[] followers, LinearMapping surfacePoints, int[] triangles,
            double[] stiffness, Mode mode, double gapM, double[] x) {
        SurfaceSliding s = new SurfaceSliding(followers, surfacePoints, triangles, stiffness, mode, 0, x);
        s.holdAtRest(gapM, x);
        return s;
    }

    private void holdAtRest(double gapM, double[] x) {
        double[] d0 = new double[gap.length];
        distancesM(x, d0);
        for (int e = 0; e < d0.length; e++) {
            double d = Double.isNaN(d0[e]) ? gapM : d0[e];
            gap[e] = mode == Mode.SLIDING ? d : Math.min(gapM, d);
        }
    }

    private static double[] filled(int n, double v) {
        double[] a = new double[n];
        Arrays.fill(a, v);
        return a;
    }

    /**
     * Pairs every follower anew with its nearest triangle by testing all triangles, O(followers x triangles):
     * for construction and after a jump (a reset of the positions), not for every step. Allocation-free.
     */
    public void repair(double[] x) {
        synchronized (readLock) {
            mapping.apply(x, readPoints);
            followers.apply(x, readYs);
            surface.bound(readPoints);
            for (int e = 0; e < pair.length; e++) {
                pair[e] = surface.nearest(readPoints, readYs, 3 * e);
            }
        }
    }

    @Override
    public void addForces(double t, double[] x, double[] v, double[] f) {
        mapping.apply(x, points);
        followers.apply(x, ys);
        Arrays.fill(pointForces, 0);
        Arrays.fill(followerForces, 0);
        final double[] pl = plane;
        for (int e = 0; e < pair.length; e++) {
            int i = 3 * e;
            int tri = surface.walk(points, pair[e], ys, i, pl);
            if (tri < 0) {
                continue; // a triangle crushed to zero area has no normal: no force until it opens again
            }
            pair[e] = tri;
            double pen = gap[e] - pl[3];
            if (mode == Mode.CONTACT && (pen <= 0 || SurfacePairing.beyondBorder(pl))) {
                continue;
            }
            double s = stiffness[e] * pen;
            double fx = s * pl[0], fy = s * pl[1], fz = s * pl[2];
            followerForces[i] += fx;
            followerForces[i + 1] += fy;
            followerForces[i + 2] += fz;
            for (int c = 0; c < 3; c++) {
                int o = 3 * surface.corner(tri, c);
                double b = pl[4 + c];
                pointForces[o] -= b * fx;
                pointForces[o + 1] -= b * fy;
                pointForces[o + 2] -= b * fz;
            }
        }
        mapping.addTranspose(pointForces, f);
        followers.addTranspose(followerForces, f);
    }

    /**
     * {@inheritDoc} Each follower's plane walked from its current pairing (the pairing itself is left to the force
     * passes); a CONTACT follower off the surface or not touching takes no tangent.
     */
    @Override
    public void linearise(double t, double[] x) {
        mapping.apply(x, linPoints);
        followers.apply(x, linYs);
        for (int e = 0; e < pair.length; e++) {
            int tri = surface.walk(linPoints, pair[e], linYs, 3 * e, linPlane);
            if (tri >= 0 && mode == Mode.CONTACT
                    && (gap[e] - linPlane[3] <= 0 || SurfacePairing.beyondBorder(linPlane))) {
                tri = -1;
            }
            tangent.set(e, tri, linPlane);
        }
    }

    /** {@inheritDoc} The Gauss-Newton tangent along the normals ({@link SlidingTangent}). */
    @Override
    public void multiplyAdd(double[] z, double[] y, int[] offset, double weight) {
        tangent.multiplyAdd(z, y, offset, weight);
    }

    /** {@inheritDoc} At the pairing of construction, every follower counted as touching. */
    @Override
    public void addIsotropicStiffness(double[] perNode) {
        restTangent.addIsotropicStiffness(perNode);
    }

    /** {@inheritDoc} The sum over followers of E above, J, for the pairing walked from the current one. */
    @Override
    public double energy(double t, double[] x) {
        synchronized (readLock) {
            mapping.apply(x, readPoints);
            followers.apply(x, readYs);
            double sum = 0;
            for (int e = 0; e < pair.length; e++) {
                double pen = penetration(e);
                if (!Double.isNaN(pen) && (mode == Mode.SLIDING || pen > 0)) {
                    sum += 0.5 * stiffness[e] * pen * pen;
                }
            }
            return sum;
        }
    }

    /** g - d of follower e with readPoints and readYs mapped; NaN when off the surface (CONTACT) or degenerate. */
    private double penetration(int e) {
        int tri = surface.walk(readPoints, pair[e], readYs, 3 * e, readPlane);
        if (tri < 0 || mode == Mode.CONTACT && SurfacePairing.beyondBorder(readPlane)) {
            return Double.NaN;
        }
        return gap[e] - readPlane[3];
    }

    /**
     * Each follower's signed distance d to its paired triangle's plane at positions x, m (+ outside), into out (one
     * per follower); NaN for one off the surface (CONTACT, past a border) or whose triangle has no area. For a
     * scene's rest distances.
     */
    public void distancesM(double[] x, double[] out) {
        synchronized (readLock) {
            mapping.apply(x, readPoints);
            followers.apply(x, readYs);
            for (int e = 0; e < pair.length; e++) {
                out[e] = gap[e] - penetration(e);
            }
        }
    }

    /** The largest penetration over followers, max(0, g - d), m, at positions x (0 if none); off-surface ignored. */
    public double maxPenetrationM(double[] x) {
        return extreme(x, 1);
    }

    /** The largest separation over followers, max(0, d - g), m, at positions x (0 if none); off-surface ignored. */
    public double maxSeparationM(double[] x) {
        return extreme(x, -1);
    }

    private double extreme(double[] x, double sign) {
        return extremeAt(x, sign)[0];
    }

    /**
     * Where the followers depart most at positions x: {@code {m, y_x, y_y, y_z}} with m the largest penetration
     * (sign 1) or separation (sign -1), m, and y that follower's position, m; m = 0 and y NaN if none departs.
     */
    public double[] extremeAt(double[] x, double sign) {
        synchronized (readLock) {
            mapping.apply(x, readPoints);
            followers.apply(x, readYs);
            double[] m = {0, Double.NaN, Double.NaN, Double.NaN};
            for (int e = 0; e < pair.length; e++) {
                double pen = sign * penetration(e);
                if (pen > m[0]) {
                    m[0] = pen;
                    System.arraycopy(readYs, 3 * e, m, 1, 3);
                }
            }
            return m;
        }
    }

    /** Number of follower-triangle pairs (one per follower). */
    public int pairCount() {
        return pair.length;
    }

    /**
     * Node id of follower e, whose row is one node (weight 1, as every node follower's is).
     *
     * @throws IllegalStateException when follower e is a point on several nodes ({@link #followers} gives them)
     */
    public int follower(int e) {
        if (followers.entries(e) != 1) {
            throw new IllegalStateException("follower " + e + " is a mapped point, not a node: read followers()");
        }
        return followers.node(e, 0);
    }

    /** The followers as points of the state's nodes (a node per row for node followers). */
    public LinearMapping followers() {
        return followers;
    }

    /** The triangle follower e is paired with now (its index in the triangles given). */
    public int pairedTriangle(int e) {
        return pair[e];
    }

    /** Stiffness of follower e, N/m. */
    public double stiffness(int e) {
        return stiffness[e];
    }

    /** Gap of follower e, m. */
    public double gapM(int e) {
        return gap[e];
    }

    /** The mode: bilateral or one-sided. */
    public Mode mode() {
        return mode;
    }

    @Override
    public String toString() {
        return "SurfaceSliding[" + mode + ", " + pair.length + " followers on " + surface.triangleCount()
                + " triangles of " + mapping.pointCount() + " points]";
    }
}
