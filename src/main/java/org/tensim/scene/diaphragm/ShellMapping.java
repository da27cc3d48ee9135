package org.tensim.scene.diaphragm;

import org.tensim.model.LinearMapping;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.scene.thorax.TriangleTree;

/**
 * Points carried by a coarse two-surface shell ({@link TwoSurfaces}): the fine mesh of the same organ, drawn,
 * measured and touched while the coarse shell's nodes run the mechanics, or the fine model of a resolution study
 * onto which a coarse model's field is carried. Builds the {@link LinearMapping} (model layer) from the shell.
 *
 * <p>The shell's elements are wedges: a face triangle with corners {@code F_k} (k = 0, 1, 2) and, across the
 * thickness, the corners' partners on the other face {@code G_k} ({@link TwoSurfaces#partner}). A point p is given
 * the wedge coordinates (w, t) with {@code p = sum_k w_k ((1 - t) F_k + t G_k)}, {@code sum_k w_k = 1}: w the
 * barycentric weights along the faces (the shape functions of a linear triangle), t the position through the
 * thickness, 0 on the face and 1 on the other. Its weights are then {@code (1 - t) w_k} on {@code F_k} and
 * {@code t w_k} on {@code G_k}, summing to 1; they reproduce p at rest exactly, so that an affine motion of the
 * shell moves every point by the same map (the mapping's affine property holds for the points themselves, not for
 * their projections on a face).
 *
 * <p>The wedge: the face triangle nearest the point on the point's own side (its face), or on either side for a
 * point without one. The coordinates: Newton's method on the three equations, started from the closest point of
 * that triangle ({@code w}) and the point's depth along the blended column there ({@code t}); the equations are
 * bilinear in (w, t) and converge in 2-4 iterations. A point beyond the triangle's edges (over the rim, or where
 * the coarse faces are chords of a curved fine one) gets weights outside [0, 1]: an extrapolation of the nearest
 * wedge, exact for affine motions still, down to node weights of {@code -}{@link #MAX_EXTRAPOLATION}. Where a
 * corner has no partner (a one-sided surface), the wedge is degenerate, or farther out, the point takes the closest
 * point's weights on the face, and its depth along the column there (its projection on the column, within
 * {@code [-MAX_EXTRAPOLATION, 1 + MAX_EXTRAPOLATION]}; 0 on a one-sided surface): the distance between the point
 * and where it is carried is reported ({@link #residualM}). On the paper's mesh carried by 20 rings that is 27 of
 * 11,354 nodes, 23 of them on the rim where the shell turns over ({@code ShellMappingTest}).
 */
public final class ShellMapping {
    /**
     * The most negative node weight a point's wedge coordinates may give (dimensionless): a point about one element
     * beyond its wedge. Farther (a wedge whose column lies nearly along its face, at a shell's turned-over rim), the
     * extrapolation would amplify the nodes' motion several times, and the point is carried on the face instead.
     */
    public static final double MAX_EXTRAPOLATION = 1;
    /** Newton iterations before giving up on the wedge coordinates (they converge in 2-4). */
    private static final int ITERATIONS = 30;
    /** The wedge coordinates are accepted when they reproduce the point to this fraction of the wedge's size. */
    private static final double EXACT = 1e-10;

    private final LinearMapping mapping;
    private final double[] depth;
    private final double[] residual;
    private final double[] outside;
    private final double[] minWeight;

    private ShellMapping(LinearMapping mapping, double[] depth, double[] residual, double[] outside,
            double[] minWeight) {
        this.mapping = mapping;
        this.depth = depth;
        this.residual = residual;
        this.outside = outside;
        this.minWeight = minWeight;
    }

    /**
     * The fine shell's vertices carried by the coarse one; node ids of the mapping are the coarse mesh's vertex
     * indices (a diaphragm scene's first nodes: the mapping applies to, and its transpose adds into, the scene's
     * whole state arrays), rest positions the coarse mesh's coordinates. Each fine vertex goes in the wedge of its
     * own face.
     */
    public static ShellMapping of(TwoSurfaces coarse, TwoSurfaces fine) {
        int n = fine.mesh().vertexCount();
        boolean[] up = new boolean[n];
        for (int v = 0; v < n; v++) {
            up[v] = fine.isUpper(v);
        }
        return of(coarse, fine.mesh().coordinates(), up);
    }

    /** Points (m, 3 each) carried by the coarse shell, each on the face {@code pointUpper} says (null: nearest). */
    public static ShellMapping of(TwoSurfaces coarse, double[] points, boolean[] pointUpper) {
        int n = coarse.mesh().vertexCount();
        boolean[] up = new boolean[n];
        int[] partner = new int[n];
        for (int v = 0; v < n; v++) {
            up[v] = coarse.isUpper(v);
            partner[v] = coarse.partner(v);
        }
        return of(coarse.mesh().coordinates(), coarse.mesh().triangles(), up, partner, points, pointUpper);
    }

    /**
     * The general form, on arrays.
     *
     * @param rest       the coarse nodes' rest positions, m, 3 per node
     * @param triangles  the coarse mesh's triangles (node ids, 3 each); those with three corners on one side are
     *                   that side's face, the others (where a closed shell turns over) are not used
     * @param upper      per coarse node, whether it is on the upper face
     * @param partner    per coarse node, its partner across the thickness (-1: none; the face is then carried alone)
     * @param points     the points to carry, m, 3 each
     * @param pointUpper per point, the face it belongs to (null, or a side without a face: the nearer face)
     * @throws IllegalArgumentException when the coarse shell has no face triangle
     */
    public static ShellMapping of(double[] rest, int[] triangles, boolean[] upper, int[] partner, double[] points,
            boolean[] pointUpper) {
        int nodes = upper.length;
        if (rest.length < 3 * nodes || partner.length != nodes) {
            throw new IllegalArgumentException("a coarse shell needs 3 coordinates, a side and a partner per node: got "
                    + rest.length + " coordinates, " + nodes + " sides, " + partner.length + " partners");
        }
        Face[] faces = {Face.of(rest, triangles, upper, false), Face.of(rest, triangles, upper, true)};
        if (faces[0] == null && faces[1] == null) {
            throw new IllegalArgumentException("the coarse shell has no triangle with its three corners on one face ("
                    + triangles.length / 3 + " triangles): nothing to carry the points by");
        }
        int np = points.length / 3;
        LinearMapping.Builder b = new LinearMapping.Builder(nodes);
        double[] depth = new double[np];
        double[] residual = new double[np];
        double[] outside = new double[np];
        double[] minWeight = new double[np];
        double[] closest = new double[4];
        double[] wt = new double[4];
        int[] none = new int[0];
        int[][] stacks = {faces[0] == null ? none : faces[0].tree.newStack(),
            faces[1] == null ? none : faces[1].tree.newStack()};
        for (int i = 0; i < np; i++) {
            double px = points[3 * i];
            double py = points[3 * i + 1];
            double pz = points[3 * i + 2];
            int side = -1;
            if (pointUpper != null && faces[pointUpper[i] ? 1 : 0] != null) {
                side = pointUpper[i] ? 1 : 0;
            }
            int t = -1;
            if (side >= 0) {
                t = faces[side].tree.nearest(px, py, pz, stacks[side], closest);
            } else {
                double best = Double.POSITIVE_INFINITY;
                for (int s = 0; s < 2; s++) {
                    if (faces[s] != null) {
                        int ts = faces[s].tree.nearest(px, py, pz, stacks[s], wt);
                        if (wt[3] < best) {
                            best = wt[3];
                            t = ts;
                            side = s;
                            System.arraycopy(wt, 0, closest, 0, 4);
                        }
                    }
                }
            }
            int[] f = new int[3];
            int[] g = new int[3];
            boolean wedge = true;
            for (int k = 0; k < 3; k++) {
                f[k] = faces[side].corners[3 * t + k];
                g[k] = partner[f[k]];
                wedge &= g[k] >= 0;
            }
            Wedge.Solution s = wedge ? Wedge.solve(rest, f, g, px, py, pz, closest, EXACT, ITERATIONS) : null;
            int[] nodeIds = wedge ? new int[] {f[0], f[1], f[2], g[0], g[1], g[2]} : f;
            double[] w;
            double tt;
            if (s != null && floor(merged(nodeIds, weights(s.weights(), s.depth(), wedge))) >= -MAX_EXTRAPOLATION) {
                w = s.weights();
                tt = s.depth();
                residual[i] = s.residualM();
                outside[i] = Math.max(0, Math.max(-tt, tt - 1)) * s.columnM();
            } else {
                // the closest point's weights on the face, and its depth along the column there within the bound
                // (the column's projection): what the mapping leaves out is the offset across the column
                w = new double[] {closest[0], closest[1], closest[2]};
                tt = wedge ? Math.max(-MAX_EXTRAPOLATION, Math.min(1 + MAX_EXTRAPOLATION,
                        Wedge.columnDepth(rest, f, g, w, px, py, pz))) : 0;
                double[] q = Wedge.point(rest, f, wedge ? g : f, w, tt);
                residual[i] = Math.sqrt(sq(q[0] - px) + sq(q[1] - py) + sq(q[2] - pz));
                outside[i] = residual[i];
            }
            double[] merged = merged(nodeIds, weights(w, tt, wedge));
            int kept = 0;
            for (double m : merged) {
                kept += Double.isNaN(m) ? 0 : 1;
            }
            int[] ids = new int[kept];
            double[] ws = new double[kept];
            for (int k = 0, e = 0; k < merged.length; k++) {
                if (!Double.isNaN(merged[k])) {
                    ids[e] = nodeIds[k];
                    ws[e++] = merged[k];
                }
            }
            b.add(ids, ws);
            // depth from the upper face: t on an upper face's wedge, 1 - t on a lower one's
            depth[i] = side == 1 ? tt : 1 - tt;
            minWeight[i] = floor(ws);
        }
        return new ShellMapping(b.build(), depth, residual, outside, minWeight);
    }

    /** Weights on the face corners then, for a wedge, on their partners: {@code (1 - t) w_k}, {@code t w_k}. */
    private static double[] weights(double[] w, double t, boolean wedge) {
        return wedge ? new double[] {(1 - t) * w[0], (1 - t) * w[1], (1 - t) * w[2], t * w[0], t * w[1], t * w[2]}
                : w.clone();
    }

    /**
     * The weights of a node named twice (two corners sharing a partner, as where a shell's faces close) summed on
     * its first entry, the later ones NaN: the mapping's weight of a node, not of a corner.
     */
    private static double[] merged(int[] ids, double[] w) {
        double[] m = w.clone();
        for (int k = 0; k < ids.length; k++) {
            for (int j = 0; j < k; j++) {
                if (ids[j] == ids[k] && !Double.isNaN(m[j])) {
                    m[j] += m[k];
                    m[k] = Double.NaN;
                    break;
                }
            }
        }
        return m;
    }

    private static double sq(double v) {
        return v * v;
    }

    private static double floor(double[] w) {
        double min = Double.POSITIVE_INFINITY;
        for (double x : w) {
            min = Double.isNaN(x) ? min : Math.min(min, x);
        }
        return min;
    }

    /** The mapping: fine point i from the coarse nodes ({@link LinearMapping#apply}, {@code addTranspose}). */
    public LinearMapping mapping() {
        return mapping;
    }

    /** Number of points carried. */
    public int pointCount() {
        return depth.length;
    }

    /**
     * Point i's depth through the thickness, from the upper face (0) to the lower (1), dimensionless; outside
     * [0, 1] above or below the shell. 0 or 1 for a point carried on a face alone.
     */
    public double depth(int point) {
        return depth[point];
    }

    /**
     * Distance of point i from the shell's thickness band, m, measured along the wedge's column: 0 between the
     * faces, {@code -t} or {@code t - 1} column lengths above or below them; for a point carried at the closest
     * point of its face, the offset left out ({@link #residualM}).
     */
    public double outsideM(int point) {
        return outside[point];
    }

    /**
     * Distance between point i and where the mapping puts it at rest, m: round-off for a point in a wedge (its
     * coordinates are exact), the offset left out for a point carried at the closest point of its face (a one-sided
     * surface, a degenerate wedge, or an extrapolation beyond {@link #MAX_EXTRAPOLATION}).
     */
    public double residualM(int point) {
        return residual[point];
    }

    /**
     * The smallest of point i's node weights (dimensionless): negative for a point carried by extrapolation, beyond
     * its triangle's edges or outside the thickness; at least {@code -}{@link #MAX_EXTRAPOLATION} in a wedge.
     */
    public double minWeight(int point) {
        return minWeight[point];
    }

    /** One face's triangles (node ids, 3 each) and their search tree at rest. */
    private record Face(int[] corners, TriangleTree tree) {
        static Face of(double[] rest, int[] triangles, boolean[] upper, boolean side) {
            int[] c = new int[triangles.length];
            int n = 0;
            for (int t = 0; 3 * t + 2 < triangles.length; t++) {
                int a = triangles[3 * t];
                int b = triangles[3 * t + 1];
                int d = triangles[3 * t + 2];
                if (upper[a] == side && upper[b] == side && upper[d] == side) {
                    c[n++] = a;
                    c[n++] = b;
                    c[n++] = d;
                }
            }
            if (n == 0) {
                return null;
            }
            int[] corners = java.util.Arrays.copyOf(c, n);
            // far-field ratio unused: the tree is searched for distances only
            return new Face(corners, new TriangleTree(rest, corners, 2));
        }
    }
}
