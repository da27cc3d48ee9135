package org.tensim.scene.thorax;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Vec3;

/**
 * A closed triangle surface swept along a polyline: an elliptic cross-section carried along the line, closed by a
 * flat cap at each end; metres, in the polyline's frame. It gives a bone drawn as a line (a rib, a costal cartilage,
 * the sternum, a vertebral body) a surface for the signed distance that attachment and contact use
 * ({@link DistanceGrid}).
 *
 * <p><b>Construction.</b> At each polyline point {@code p_i} the tangent {@code t_i} is the direction from the point
 * before to the point after (at the ends, along the end segment); the cross-section's first axis is a reference
 * direction {@code r} made perpendicular to it, {@code u_i = (r - (r . t_i) t_i) / |...|}, and its second
 * {@code v_i = t_i x u_i}. Ring i holds {@code around} vertices
 * <pre>
 *   x_ik = p_i + a cos(theta_k) u_i + b sin(theta_k) v_i,   theta_k = 2 pi k / around
 * </pre>
 * with {@code a}, {@code b} the section's semi-axes along u and v. Consecutive rings are joined by two triangles per
 * quadrilateral; each end is closed by a fan about the end point. Triangles are counter-clockwise seen from outside
 * ({@code (u, v, t)} is right-handed), so the normals point out and the signed distance is negative inside. A ring
 * lies in the plane through its point perpendicular to the mean tangent (a mitre), so a bend of a few tens of degrees
 * between segments keeps the section's size; the polyline must not turn back on itself within a section's size.
 *
 * <p><b>Sources.</b> Vertex {@code i * around + k} was swept from polyline point i ({@link #sourcePoint}); the two cap
 * centres, the last two vertices, from the end points. A rigid motion applied to the polyline and to the surface
 * keeps each vertex at its place in its point's section.
 */
public final class TubeSweep {
    /** Fewest vertices around a section. */
    public static final int MIN_AROUND = 3;

    private TubeSweep() {
    }

    /**
     * The closed surface swept along {@code points}.
     *
     * @param points    the polyline, m, at least two points, consecutive points apart
     * @param reference the direction the section's first axis is taken along (made perpendicular to the line; must
     *                  not be parallel to any tangent)
     * @param a         semi-axis of the section along the reference direction, m (> 0)
     * @param b         semi-axis across it, m (> 0)
     * @param around    vertices around a section, at least {@link #MIN_AROUND}
     */
    public static TriangleMesh sweep(Vec3[] points, Vec3 reference, double a, double b, int around) {
        if (points.length < 2) {
            throw new IllegalArgumentException("a swept tube needs at least 2 polyline points, got " + points.length);
        }
        if (!(a > 0 && b > 0 && Double.isFinite(a) && Double.isFinite(b))) {
            throw new IllegalArgumentException("a swept tube's semi-axes must be positive finite lengths in m, got "
                    + a + " and " + b);
        }
        if (around < MIN_AROUND) {
            throw new IllegalArgumentException("a swept tube needs at least " + MIN_AROUND
                    + " vertices around its section, got " + around);
        }
        int n = points.length;
        double[] xyz = new double[3 * (n * around + 2)];
        for (int i = 0; i < n; i++) {
            Vec3 t = tangent(points, i);
            Vec3 u = reference.minus(t.times(reference.dot(t)));
            if (!(u.norm() > 1e-9 * reference.norm())) {
                throw new IllegalArgumentException("swept tube: the reference direction " + reference
                        + " is parallel to the line at point " + i + " " + points[i] + "; give one across the line");
            }
            u = u.normalized();
            Vec3 v = t.cross(u);
            for (int k = 0; k < around; k++) {
                double th = 2 * Math.PI * k / around;
                Vec3 x = points[i].plus(u.times(a * Math.cos(th))).plus(v.times(b * Math.sin(th)));
                int o = 3 * (i * around + k);
                xyz[o] = x.x();
                xyz[o + 1] = x.y();
                xyz[o + 2] = x.z();
            }
        }
        int c0 = n * around;
        int c1 = c0 + 1;
        put(xyz, c0, points[0]);
        put(xyz, c1, points[n - 1]);
        int[] tri = new int[3 * (2 * (n - 1) * around + 2 * around)];
        int q = 0;
        for (int i = 0; i + 1 < n; i++) {
            for (int k = 0; k < around; k++) {
                int k1 = (k + 1) % around;
                int p00 = i * around + k;
                int p01 = i * around + k1;
                int p10 = (i + 1) * around + k;
                int p11 = (i + 1) * around + k1;
                q = triangle(tri, q, p00, p01, p10);
                q = triangle(tri, q, p01, p11, p10);
            }
        }
        for (int k = 0; k < around; k++) {
            int k1 = (k + 1) % around;
            q = triangle(tri, q, c0, k1, k);
            q = triangle(tri, q, c1, (n - 1) * around + k, (n - 1) * around + k1);
        }
        return new TriangleMesh(xyz, tri);
    }

    /** The polyline point vertex v of a tube swept with {@code around} vertices a section was swept from. */
    public static int sourcePoint(int v, int points, int around) {
        int rings = points * around;
        if (v < rings) {
            return v / around;
        }
        return v == rings ? 0 : points - 1;
    }

    private static Vec3 tangent(Vec3[] p, int i) {
        Vec3 d = p[Math.min(i + 1, p.length - 1)].minus(p[Math.max(i - 1, 0)]);
        if (!(d.norm() > 0)) {
            throw new IllegalArgumentException("swept tube: polyline points around point " + i + " " + p[i]
                    + " coincide; expected consecutive points apart");
        }
        return d.normalized();
    }

    private static void put(double[] xyz, int v, Vec3 p) {
        xyz[3 * v] = p.x();
        xyz[3 * v + 1] = p.y();
        xyz[3 * v + 2] = p.z();
    }

    private static int triangle(int[] tri, int q, int a, int b, int c) {
        tri[q] = a;
        tri[q + 1] = b;
        tri[q + 2] = c;
        return q + 3;
    }
}
