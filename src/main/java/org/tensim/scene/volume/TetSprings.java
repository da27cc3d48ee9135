package org.tensim.scene.volume;

import org.hipparchus.linear.Array2DRowRealMatrix;
import org.hipparchus.linear.ArrayRealVector;
import org.hipparchus.linear.CholeskyDecomposition;
import org.hipparchus.linear.RealVector;
import org.tensim.model.Check;

/**
 * The six edge springs of one tetrahedron from Young's modulus: the identification of a tetrahedral volume, by the
 * energy matching of Lloyd, Székely and Harders (2007, "Identification of spring parameters for deformable object
 * simulation", IEEE TVCG 13(5): 1081-1094), as {@link LatticeMaterial} does for cubic cells.
 *
 * <p>A spring of stiffness k and rest length L along the unit vector n stores {@code k (L n.eps.n)^2 / 2} under a
 * small homogeneous strain eps, so a tet of volume V with edge springs k_e stores {@code V eps:C_t:eps / 2} with
 * <pre>
 *   C_t = sum_e k'_e n_e n_e n_e n_e,    k'_e = k_e L_e^2 / V.
 * </pre>
 * Since the six edge lengths fix a tet's affine deformation, a spring tet is exactly a linear finite element with the
 * material C_t. C_t is totally symmetric (Cauchy's relation: central springs have {@code lambda = mu}), and a tet
 * has six springs for the 15 components of such a tensor, so C_t cannot equal an isotropic C in general. The
 * springs are the least-squares fit in the tensors' Frobenius norm {@code |A|^2 = A_ijkl A_ijkl} (the mean square
 * misfit of the stress {@code (C_t - C):eps} over strains of unit norm drawn isotropically), whose normal equations
 * are
 * <pre>
 *   sum_f (n_e . n_f)^4 k'_f = n_e n_e : C : n_e n_e = lambda + 2 mu     (e = 1..6).
 * </pre>
 * The target C is the isotropic material of the requested E and Poisson's ratio 1/4 (lambda = mu = 2E/5,
 * {@code lambda + 2 mu = 6E/5}): the only isotropic material central springs can have. (The fit to another nu would
 * land on its totally symmetric part, lambda = mu = (lambda + 2 mu)/3, of Young's modulus
 * {@code 5 (lambda + 2 mu) / 6}: 1.79 E at nu = 0.4.) For a regular tet of edge l the six springs are equal,
 * {@code k = 2 sqrt(2) E l / 25}. An edge whose fitted k' is negative (a flat, sliver-like tet) gets no spring, the
 * most negative first, and the others are fitted again, so no spring is negative; such edges are counted
 * ({@link #negativeDropped}). A spring shared by several tets sums their shares, as finite elements are assembled.
 */
public final class TetSprings {
    /** The corner pairs of a tet's six edges, in the order of the stiffness arrays. */
    public static final int[][] EDGES = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

    private final double youngPa;
    private int dropped;

    /** @param youngPa E, Pa (&gt; 0) */
    public TetSprings(double youngPa) {
        this.youngPa = Check.positive("volume Young's modulus", "Pa", youngPa);
    }

    /** The isotropic target's {@code lambda + 2 mu = 6E/5}, Pa. */
    public double pWaveModulusPa() {
        return 1.2 * youngPa;
    }

    /** Edges left without a spring so far because their unconstrained fit was negative. */
    public int negativeDropped() {
        return dropped;
    }

    /**
     * The stiffnesses of the six edge springs of a positively oriented tet, N/m, in {@link #EDGES} order.
     *
     * @param xyz the corners' coordinates, m, 12 values (x, y, z of corner 0, then 1, 2, 3)
     */
    public double[] stiffness(double[] xyz) {
        double[][] n = new double[6][3];
        double[] len2 = new double[6];
        for (int e = 0; e < 6; e++) {
            int a = EDGES[e][0];
            int b = EDGES[e][1];
            for (int ax = 0; ax < 3; ax++) {
                n[e][ax] = xyz[3 * b + ax] - xyz[3 * a + ax];
                len2[e] += n[e][ax] * n[e][ax];
            }
            double l = Math.sqrt(len2[e]);
            for (int ax = 0; ax < 3; ax++) {
                n[e][ax] /= l;
            }
        }
        double v = volume(xyz);
        double[][] g = new double[6][6];
        for (int e = 0; e < 6; e++) {
            for (int f = 0; f < 6; f++) {
                double c = n[e][0] * n[f][0] + n[e][1] * n[f][1] + n[e][2] * n[f][2];
                g[e][f] = c * c * c * c;
            }
        }
        boolean[] free = {true, true, true, true, true, true};
        double[] kp = null;
        for (int pass = 0; pass < 6; pass++) {
            kp = solve(g, free, pWaveModulusPa());
            int worst = -1;
            for (int e = 0; e < 6; e++) {
                if (free[e] && kp[e] < 0 && (worst < 0 || kp[e] < kp[worst])) {
                    worst = e;
                }
            }
            if (worst < 0) {
                break;
            }
            free[worst] = false;
            dropped++;
        }
        double[] k = new double[6];
        for (int e = 0; e < 6; e++) {
            k[e] = free[e] ? kp[e] * v / len2[e] : 0;
        }
        return k;
    }

    /** Signed volume of the tet of 12 coordinates, m^3. */
    static double volume(double[] x) {
        double[] u = new double[9];
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) {
                u[3 * k + a] = x[3 * (k + 1) + a] - x[a];
            }
        }
        return (u[0] * (u[4] * u[8] - u[5] * u[7]) - u[1] * (u[3] * u[8] - u[5] * u[6])
                + u[2] * (u[3] * u[7] - u[4] * u[6])) / 6;
    }

    /** Solves the normal equations restricted to the free edges (Cholesky: the Gram matrix is positive definite). */
    private static double[] solve(double[][] g, boolean[] free, double rhs) {
        int m = 0;
        int[] idx = new int[6];
        for (int e = 0; e < 6; e++) {
            if (free[e]) {
                idx[m++] = e;
            }
        }
        double[][] a = new double[m][m];
        double[] b = new double[m];
        for (int i = 0; i < m; i++) {
            for (int j = 0; j < m; j++) {
                a[i][j] = g[idx[i]][idx[j]];
            }
            b[i] = rhs;
        }
        RealVector x = new CholeskyDecomposition(new Array2DRowRealMatrix(a, false), 1e-12, 1e-14).getSolver()
                .solve(new ArrayRealVector(b, false));
        double[] out = new double[6];
        for (int i = 0; i < m; i++) {
            out[idx[i]] = x.getEntry(i);
        }
        return out;
    }
}
