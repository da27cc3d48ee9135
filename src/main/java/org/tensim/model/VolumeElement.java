package org.tensim.model;

/**
 * A penalty on the change of volume of a cell of 4 nodes (a linear tet) or 8 (a hexahedral cell, trilinear),
 * the volumetric part of a volume material: with the rest shape functions' gradients {@code g_n} at the cell's
 * centre (1/m; exact for a tet, the one-point rule for a hexahedron), the deformation gradient, its determinant and
 * the energy are
 * <pre>
 *   F = sum_n x_n g_n^T,    J = det F,    W = K V (J - 1)^2 / 2,
 * </pre>
 * with V the rest volume (m^3) and K the modulus (Pa). The force on node n is minus the gradient of W,
 * {@code f_n = -K V (J - 1) cof(F) g_n} ({@code cof(F) = dJ/dF = J F^-T}); with the damping time beta
 * (Kelvin-Voigt, as a spring's {@code c = beta k}) it is {@code f_n = -K V ((J - 1) + beta dJ/dt) cof(F) g_n},
 * {@code dJ/dt = cof(F) : sum_n v_n g_n^T}, which dissipates {@code beta K V (dJ/dt)^2 >= 0}.
 *
 * <p>Under a small homogeneous strain eps, {@code J - 1 = tr eps} to first order: the element stores
 * {@code K V (tr eps)^2 / 2}, which adds K to Lamé's lambda of whatever else the cell holds. Central springs alone
 * obey Cauchy's relation lambda = mu (Poisson's ratio 1/4 when isotropic); springs of shear modulus mu with such
 * an element of {@code K = lambda - mu} give any Poisson's ratio from 1/4 to 1/2 (the volumetric fit of
 * {@code scene.volume.SpringFit}; Golec et al. 2020, The Visual Computer 36: 809-825, add a volume term per cell
 * for the same reason). The element is invariant under rigid motions (J is), and has no stiffness of its own
 * against volume-preserving (shear or, for a hexahedron, hourglass) modes: those are the springs'.
 */
public final class VolumeElement {
    private final int[] nodes;
    private final double[] gradients;
    private final double restVolumeM3;
    private final double modulusPa;
    private final double dampingS;

    /**
     * @param nodes     4 (a tet) or 8 node ids (a hexahedron: corner c at bits (c &amp; 1, c &gt;&gt; 1 &amp; 1,
     *                  c &gt;&gt; 2 &amp; 1) of its local x, y, z)
     * @param rest      the nodes' rest positions, m
     * @param modulusPa K, Pa (&gt; 0)
     * @param dampingS  beta, s (&gt;= 0)
     */
    VolumeElement(int[] nodes, Vec3[] rest, double modulusPa, double dampingS) {
        String name = "volume element on nodes " + java.util.Arrays.toString(nodes);
        this.modulusPa = Check.positive(name + " modulus", "Pa", modulusPa);
        this.dampingS = Check.nonNegative(name + " damping time beta", "s", dampingS);
        int k = nodes.length;
        // dN_n/dxi at the centre, on the reference cell: [0,1]^3 tet corners, or [-1,1]^3 for a hexahedron.
        double[][] dn = new double[k][3];
        if (k == 4) {
            for (int a = 0; a < 3; a++) {
                dn[0][a] = -1;
                dn[a + 1][a] = 1;
            }
        } else if (k == 8) {
            for (int c = 0; c < 8; c++) {
                for (int a = 0; a < 3; a++) {
                    dn[c][a] = ((c >> a & 1) == 1 ? 1 : -1) / 8.0;
                }
            }
        } else {
            throw new IllegalArgumentException("a volume element needs 4 nodes (a tet) or 8 (a hexahedron), got "
                    + k);
        }
        // J0 = dX/dxi = sum X_n dN_n/dxi^T; g_n = J0^-T dN_n/dxi; V = det J0 times the reference volume.
        double[] j0 = new double[9];
        for (int n = 0; n < k; n++) {
            double[] x = {rest[n].x(), rest[n].y(), rest[n].z()};
            for (int a = 0; a < 3; a++) {
                for (int b = 0; b < 3; b++) {
                    j0[3 * a + b] += x[a] * dn[n][b];
                }
            }
        }
        double det = det(j0);
        double reference = k == 4 ? 1.0 / 6 : 8;
        double scale = 0;
        for (Vec3 r : rest) {
            scale = Math.max(scale, r.minus(rest[0]).norm());
        }
        if (!(det > 1e-9 * scale * scale * scale / reference)) {
            throw new IllegalArgumentException(name + " is inverted or flat: its rest volume is " + det * reference
                    + " m^3; expected corners ordered for a positive volume");
        }
        double[] inv = inverse(j0, det);
        this.gradients = new double[3 * k];
        for (int n = 0; n < k; n++) {
            for (int a = 0; a < 3; a++) {
                // (J0^-T dN)_a = sum_b inv[b][a] dN_b
                gradients[3 * n + a] = inv[a] * dn[n][0] + inv[3 + a] * dn[n][1] + inv[6 + a] * dn[n][2];
            }
        }
        this.nodes = nodes.clone();
        this.restVolumeM3 = det * reference;
    }

    private static double det(double[] m) {
        return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
                + m[2] * (m[3] * m[7] - m[4] * m[6]);
    }

    private static double[] inverse(double[] m, double det) {
        return new double[] {
            (m[4] * m[8] - m[5] * m[7]) / det, (m[2] * m[7] - m[1] * m[8]) / det, (m[1] * m[5] - m[2] * m[4]) / det,
            (m[5] * m[6] - m[3] * m[8]) / det, (m[0] * m[8] - m[2] * m[6]) / det, (m[2] * m[3] - m[0] * m[5]) / det,
            (m[3] * m[7] - m[4] * m[6]) / det, (m[1] * m[6] - m[0] * m[7]) / det, (m[0] * m[4] - m[1] * m[3]) / det};
    }

    /** Number of nodes, 4 or 8. */
    public int size() {
        return nodes.length;
    }

    /** Node id of corner c. */
    public int node(int c) {
        return nodes[c];
    }

    /** Component a of the rest gradient g_c of corner c's shape function at the centre, 1/m. */
    public double gradient(int c, int a) {
        return gradients[3 * c + a];
    }

    /** Rest volume V, m^3 (a hexahedron's by the one-point rule: exact for a parallelepiped). */
    public double restVolumeM3() {
        return restVolumeM3;
    }

    /** K, Pa. */
    public double modulusPa() {
        return modulusPa;
    }

    /** beta, s. */
    public double dampingS() {
        return dampingS;
    }
}
