package org.tensim.model;

/**
 * Transverse shear of a two-surface shell over one triangle of its upper face (Mindlin-Reissner's
 * shear energy, with the shear strain assumed along the triangle's edges, as MITC / DSG shells do).
 * The triangle's corners a_0, a_1, a_2 (upper face) carry columns to their partners b_0, b_1, b_2 on
 * the lower face. For its edge k, from corner k to corner k+1 (mod 3), with {@code e = x_{a_{k+1}} - x_{a_k}},
 * the columns {@code c = x_b - x_a} at both ends and {@code S = c_k + c_{k+1}}:
 *
 * <pre>
 *   g_k = e . S   (= (|d1|^2 - |d2|^2) / 2 for the prism side's two diagonals, columns of equal length),
 *   r_k = (g_k - g0_k) / (2 s_k)   (= gamma . e_k, gamma the shear strain; s_k the mean over the edge's ends of
 *                                  the columns' components along the triangle's normal at rest: the faces' distance),
 *   W = 1/2 kappa G t r^T Q r = 1/2 (g - g0)^T K (g - g0),   K_kl = kappa G t Q_kl / (4 s_k s_l)
 * </pre>
 *
 * Sliding the upper face by delta over the lower one gives {@code g_k - g0_k = -2 e_k . delta}, so r
 * is the shear strain delta / s projected on the edges.
 *
 * <p><b>Q.</b> A uniform shear strain costs {@code 1/2 kappa G t A |gamma|^2} on a triangle of area A.
 * For any triangle {@code sum_k cot(theta_k) e_k e_k^T = 2 A I} (theta_k the angle opposite edge k),
 * so {@code C = diag(cot theta_k) / 2} gives {@code r^T C r = A |gamma|^2} exactly for every r that a
 * shear strain can make (those with {@code sum_k r_k = 0}, since the edges add to zero). C alone is
 * not positive on an obtuse triangle (one cotangent is negative), and an edge-by-edge split
 * ({@code 2 A / 3} per edge, or the cotangents summed per edge, which are negative across a
 * non-Delaunay edge) is exact only on equilateral triangles or must drop edges. So
 * {@code Q = P C P + alpha n n^T}, {@code n = (1, 1, 1) / sqrt 3}, {@code P = I - n n^T},
 * {@code alpha = sum_k cot(theta_k) / 6 > 0}: exact on the shear strains (P r = r there, where
 * {@code r^T C r = A |gamma|^2 >= 0}), positive on the one incompatible direction n, and Q = C on
 * an equilateral triangle (where it is the edge-by-edge {@code 2 A / 3}).
 *
 * <p>Damping (optional) is Kelvin-Voigt, {@code rho = K (g - g0 + beta dg/dt)} in the forces, as the
 * triangles' and the springs' stiffness-proportional damping: it dissipates
 * {@code beta (dg/dt)^T K dg/dt >= 0} and does not resist rigid motions (dg/dt = 0 there).
 *
 * <p>g is bilinear and invariant under rigid motions; under pure bending of a cylinder or sphere
 * with the columns on the normals, the mean of an edge's two end normals is perpendicular to its
 * chord, so {@code g = g0}: no shear locking.
 */
public final class TransverseShear {
    private final int[] nodes;
    private final double[] restG = new double[3];
    private final double[] stiffness = new double[9];
    private final double dampingS;

    /**
     * @param nodes      a_0, a_1, a_2 (upper face), b_0, b_1, b_2 (their partners on the lower face)
     * @param rest       the rest positions of those six nodes, m
     * @param kappaGPa   kappa G, the shear modulus with the shear correction factor, Pa (&gt; 0)
     * @param thicknessM t, m (&gt; 0)
     * @param dampingS   Kelvin-Voigt damping time beta, s (&gt;= 0): the viscous part {@code beta dg/dt} is added
     *                   to {@code g - g0} in the forces, as the triangles' and springs' stiffness-proportional damping
     */
    TransverseShear(int[] nodes, Vec3[] rest, double kappaGPa, double thicknessM, double dampingS) {
        String name = "transverse shear " + nodes[0] + "-" + nodes[1] + "-" + nodes[2] + "/" + nodes[3] + "-"
                + nodes[4] + "-" + nodes[5];
        Check.positive(name + " kappa G", "Pa", kappaGPa);
        Check.positive(name + " thickness", "m", thicknessM);
        this.dampingS = Check.nonNegative(name + " damping time beta", "s", dampingS);
        // The partners may repeat (a mesh whose faces have different vertex counts pairs several upper
        // corners with one lower vertex; g_k is then the difference of the squared distances from the
        // edge's ends to that vertex, still -2 e_k . delta under a sliding delta); nothing else may.
        for (int a = 0; a < 6; a++) {
            for (int b = a + 1; b < 6; b++) {
                if (nodes[a] == nodes[b] && a < 3) {
                    throw new IllegalArgumentException(name + " uses node " + nodes[a]
                            + " twice; expected three distinct upper corners, each different from the partners");
                }
            }
        }
        double[] cot = new double[3];
        double[] s = new double[3];
        Vec3 normal = rest[1].minus(rest[0]).cross(rest[2].minus(rest[0])).normalized();
        for (int k = 0; k < 3; k++) {
            Vec3 a = rest[k];
            Vec3 b = rest[(k + 1) % 3];
            Vec3 e = b.minus(a);
            Vec3 ca = rest[3 + k].minus(a);
            Vec3 cb = rest[3 + (k + 1) % 3].minus(b);
            restG[k] = e.dot(ca.plus(cb));
            s[k] = 0.5 * (leverArm(ca, normal, thicknessM) + leverArm(cb, normal, thicknessM));
            // The angle opposite edge k is at corner k + 2.
            Vec3 o = rest[(k + 2) % 3];
            Vec3 u = a.minus(o);
            Vec3 w = b.minus(o);
            double cross = u.cross(w).norm();
            if (!(cross > 1e-12 * u.norm() * w.norm()) || !(s[k] > 0)) {
                throw new IllegalArgumentException(name + " is degenerate: its upper corners are collinear or a "
                        + "column has zero length (" + s[k] + " m); expected a triangle and columns of positive size");
            }
            cot[k] = u.dot(w) / cross;
        }
        double alpha = (cot[0] + cot[1] + cot[2]) / 6;
        // Q = P C P + alpha n n^T, with P = I - J / 3 (J all ones): (P C P)_kl = C_kl - (C_k. + C_.l) / 3 + sum C / 9.
        double sum = 0.5 * (cot[0] + cot[1] + cot[2]);
        for (int k = 0; k < 3; k++) {
            for (int l = 0; l < 3; l++) {
                double q = (k == l ? 0.5 * cot[k] : 0) - (0.5 * cot[k] + 0.5 * cot[l]) / 3 + sum / 9 + alpha / 3;
                stiffness[3 * k + l] = kappaGPa * thicknessM * q / (4 * s[k] * s[l]);
            }
        }
        this.nodes = nodes.clone();
    }

    /**
     * A column's lever arm for the shear strain: its component along the triangle's normal (the local distance
     * between the faces), so that sliding the faces by delta gives r = delta / distance exactly even where a
     * partner is not straight below its corner (faces of different resolutions); at least half the shell's
     * thickness, so that a partner met almost sideways cannot make the element arbitrarily stiff.
     */
    private static double leverArm(Vec3 column, Vec3 normal, double thicknessM) {
        return Math.max(Math.abs(column.dot(normal)), 0.5 * thicknessM);
    }

    /** Node a of the element: 0..2 the upper corners, 3..5 their partners on the lower face. */
    public int node(int a) {
        return nodes[a];
    }

    /** {@code K_kl = kappa G t Q_kl / (4 s_k s_l)}, J/m^4, for edges k, l (0..2); the energy is {@code (g - g0)^T K (g - g0) / 2}. */
    public double stiffness(int k, int l) {
        return stiffness[3 * k + l];
    }

    /** Kelvin-Voigt damping time beta, s (0: undamped). */
    public double dampingS() {
        return dampingS;
    }

    /** g0 of edge k (0..2) at rest, m^2. */
    public double restG(int k) {
        return restG[k];
    }
}
