package org.tensim.scene.diaphragm;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Vec3;

/**
 * The action lines' load on the nodes, as a weight per node (m^2) that the live pressure
 * {@code P s(t)} multiplies (package-private; see {@link BoundaryConditions.MuscleLoad}).
 *
 * <p>{@link BoundaryConditions.MuscleLoad#PRESSURE}: the traction {@code -P s(t) w(d(x)) m(x) e_z},
 * with w the action lines' intensity at the horizontal position of x (Nedel and Thalmann's
 * weighting, {@link ActionLines#weight}) and m(x) = 1 on the muscle's side of the tendon plane, 0 on
 * the tendon's, is integrated over every triangle, half per face (P is a force per unit area of the
 * diaphragm). A triangle cut by the tendon plane is clipped to its muscle part (a triangle or a
 * quadrilateral, fanned into triangles). The rule splits each (part of a) triangle into
 * {@value #DIVISIONS}^2 similar triangles and takes their centroids; each point's share of the area
 * goes to the triangle's corners by its barycentric coordinates (linear shape functions: the
 * consistent load vector). The total force is {@code P s(t)} times the integral of w m over the
 * mid-surface whatever the mesh.
 *
 * <p>{@link BoundaryConditions.MuscleLoad#PAPER_NODES}: the paper's per-node force, weight
 * {@code w(d_i) A_i / 2} on muscle nodes.
 */
final class MusclePressure {
    /** Subdivisions per triangle edge of the integration rule. */
    static final int DIVISIONS = 4;

    private MusclePressure() {
    }

    /**
     * Area weights per mesh vertex, m^2.
     *
     * @param normal   the tendon plane's normal (unit)
     * @param cut      the plane's offset: points with {@code normal . x >= cut} are tendon, m
     * @param labels   node labels (for the paper's nodal rule)
     * @param area     vertex area shares, m^2 (for the paper's nodal rule)
     */
    static double[] weights(TriangleMesh m, ActionLines lines, BoundaryConditions.MuscleLoad model, Vec3 normal,
            double cut, int[] labels, double[] area) {
        int nv = m.vertexCount();
        double[] w = new double[nv];
        if (model == BoundaryConditions.MuscleLoad.PAPER_NODES) {
            for (int v = 0; v < nv; v++) {
                if (labels[v] == DiaphragmScene.MUSCLE) {
                    w[v] = lines.weight(m.coord(v, 0), m.coord(v, 1)) * area[v] / 2;
                }
            }
            return w;
        }
        double[] h = new double[3];
        double[][] poly = new double[4][];
        for (int t = 0; t < m.triangleCount(); t++) {
            int[] c = {m.corner(t, 0), m.corner(t, 1), m.corner(t, 2)};
            for (int k = 0; k < 3; k++) {
                h[k] = normal.x() * m.coord(c[k], 0) + normal.y() * m.coord(c[k], 1) + normal.z() * m.coord(c[k], 2)
                        - cut;
            }
            // the muscle's part of the triangle (h < 0), as a polygon in barycentric coordinates
            int np = 0;
            for (int k = 0; k < 3; k++) {
                int l = (k + 1) % 3;
                if (h[k] < 0) {
                    poly[np++] = unit(k);
                }
                if ((h[k] < 0) != (h[l] < 0)) {
                    double f = h[k] / (h[k] - h[l]);
                    double[] b = new double[3];
                    b[k] = 1 - f;
                    b[l] = f;
                    poly[np++] = b;
                }
            }
            for (int k = 1; k + 1 < np; k++) {
                integrate(m, lines, c, 0.5 * m.area(t), poly[0], poly[k], poly[k + 1], w);
            }
        }
        return w;
    }

    private static double[] unit(int k) {
        double[] b = new double[3];
        b[k] = 1;
        return b;
    }

    /**
     * Adds to {@code w} the rule's integral of the lines' weight over the sub-triangle (p, q, r) of
     * triangle c (barycentric corners), times {@code halfArea} (half the triangle's area: half per face).
     */
    private static void integrate(TriangleMesh m, ActionLines lines, int[] c, double halfArea, double[] p,
            double[] q, double[] r, double[] w) {
        double ratio = Math.abs((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
        double share = halfArea * ratio / (DIVISIONS * DIVISIONS);
        double[] b = new double[3];
        for (int i = 0; i < DIVISIONS; i++) {
            for (int j = 0; i + j < DIVISIONS; j++) {
                // the upright sub-triangle at (i, j) and, where there is room, the inverted one next to it
                for (int flip = 0; flip < (i + j < DIVISIONS - 1 ? 2 : 1); flip++) {
                    double off = flip == 0 ? 1.0 / 3 : 2.0 / 3;
                    double lq = (i + off) / DIVISIONS;
                    double lr = (j + off) / DIVISIONS;
                    double lp = 1 - lq - lr;
                    double x = 0;
                    double y = 0;
                    for (int k = 0; k < 3; k++) {
                        b[k] = lp * p[k] + lq * q[k] + lr * r[k];
                        x += b[k] * m.coord(c[k], 0);
                        y += b[k] * m.coord(c[k], 1);
                    }
                    double f = share * lines.weight(x, y);
                    for (int k = 0; k < 3; k++) {
                        w[c[k]] += b[k] * f;
                    }
                }
            }
        }
    }
}
