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
 * diaphragm). The rule splits each triangle into {@value #DIVISIONS}^2 similar triangles and takes
 * their centroids; each point's share {@code A_T / DIVISIONS^2} goes to the triangle's corners by
 * their barycentric coordinates (linear shape functions: the consistent load vector). The total
 * force is {@code P s(t)} times the integral of w m over the mid-surface whatever the mesh; the
 * tendon plane may cut a triangle (the rule resolves the cut to a quarter of an element).
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
        double[] x = new double[3];
        double n2 = (double) DIVISIONS * DIVISIONS;
        for (int t = 0; t < m.triangleCount(); t++) {
            double share = 0.5 * m.area(t) / n2;
            int a = m.corner(t, 0);
            int b = m.corner(t, 1);
            int c = m.corner(t, 2);
            for (int i = 0; i < DIVISIONS; i++) {
                for (int j = 0; i + j < DIVISIONS; j++) {
                    // the upright sub-triangle at (i, j) and, where there is room, the inverted one next to it
                    for (int flip = 0; flip < (i + j < DIVISIONS - 1 ? 2 : 1); flip++) {
                        double off = flip == 0 ? 1.0 / 3 : 2.0 / 3;
                        double la = (i + off) / DIVISIONS;
                        double lb = (j + off) / DIVISIONS;
                        double lc = 1 - la - lb;
                        for (int k = 0; k < 3; k++) {
                            x[k] = la * m.coord(a, k) + lb * m.coord(b, k) + lc * m.coord(c, k);
                        }
                        if (normal.x() * x[0] + normal.y() * x[1] + normal.z() * x[2] >= cut) {
                            continue; // tendon: not contractile
                        }
                        double f = share * lines.weight(x[0], x[1]);
                        w[a] += la * f;
                        w[b] += lb * f;
                        w[c] += lc * f;
                    }
                }
            }
        }
        return w;
    }
}
