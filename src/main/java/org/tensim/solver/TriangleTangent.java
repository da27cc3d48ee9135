package org.tensim.solver;

import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * The tangent stiffness {@code K = d^2 W / dx^2} of the membrane triangles of a {@link SystemState}
 * ({@link TriangleKernels}), linearised at given positions and applied matrix-free. Per element,
 * with {@code dF = [dy_1 - dy_0, dy_2 - dy_0] R}:
 *
 * <pre>
 *   dE = sym(F^T dF),   dS = 2 mu dE + lambda tr(dE) I,   dP = dF S + F dS,   K dy = dP R^T (on the edges)
 * </pre>
 *
 * The material part {@code F dS} is positive semi-definite (2 mu |dE|^2 + lambda tr(dE)^2 &gt;= 0 since
 * mu + lambda = E / (2 (1 - nu)) &gt; 0); the geometric part {@code dF S} is not where the element is
 * compressed. {@link #linearise(double[], boolean)} can keep only the positive part of S (its
 * negative eigenvalues set to zero), which makes K positive semi-definite for conjugate gradients
 * and preconditioners (as the springs' clamped transverse term, Baraff and Witkin 1998). At rest
 * S = 0 and K is the linear constant-strain triangle's stiffness. Arrays allocated once.
 */
public final class TriangleTangent implements ExtraStiffness {
    private final SystemState s;
    private final double[] grad; // per element: F's columns u, w (6)
    private final double[] stress; // per element: s00, s01, s11
    private final double[] corner = new double[9];
    private final double[] cornerOut = new double[9];
    private final double[] scratchF = new double[6];
    private final double[] scratchU = new double[3];
    private final double[] scratchW = new double[3];

    /** A tangent linearised at the state's rest positions (where it is the linear CST stiffness). */
    public TriangleTangent(SystemState state) {
        this.s = state;
        int n = state.triangleCount();
        grad = new double[6 * n];
        stress = new double[3 * n];
        linearise(state.x0, true);
    }

    /**
     * Linearises at positions px (m, full layout).
     *
     * @param psd keep only the positive part of the stress in the geometric term (K positive semi-definite)
     */
    public void linearise(double[] px, boolean psd) {
        final double[] fr = scratchF;
        for (int e = 0; e < s.triangleCount(); e++) {
            TriangleKernels.deformationGradient(s.triP3, s.triQ3, s.triRest, e, px, fr);
            System.arraycopy(fr, 0, grad, 6 * e, 6);
            stress(fr, 0, s.triMu[e], s.triLambda[e], psd, stress, 3 * e);
        }
    }

    /**
     * The second Piola-Kirchhoff stress {@code S = 2 mu E + lambda tr(E) I} (J, as {@code A t} times
     * Pa: mu and lambda are an element's {@code A t mu}, {@code A t lambda}) of the deformation gradient
     * whose columns u, w are {@code f[fo..fo+5]}, stored as s00, s01, s11 at {@code out[oo..oo+2]};
     * with {@code psd}, its negative eigenvalues set to zero (the positive part used by the clamped
     * tangent).
     */
    public static void stress(double[] f, int fo, double mu, double lambda, boolean psd, double[] out, int oo) {
        double e00 = 0.5 * (f[fo] * f[fo] + f[fo + 1] * f[fo + 1] + f[fo + 2] * f[fo + 2] - 1);
        double e11 = 0.5 * (f[fo + 3] * f[fo + 3] + f[fo + 4] * f[fo + 4] + f[fo + 5] * f[fo + 5] - 1);
        double e01 = 0.5 * (f[fo] * f[fo + 3] + f[fo + 1] * f[fo + 4] + f[fo + 2] * f[fo + 5]);
        double tr = lambda * (e00 + e11);
        double a = 2 * mu * e00 + tr;
        double b = 2 * mu * e01;
        double c = 2 * mu * e11 + tr;
        if (psd) {
            double m = 0.5 * (a + c);
            double r = Math.sqrt(0.25 * (a - c) * (a - c) + b * b);
            double hi = m + r;
            if (hi <= 0) {
                a = 0;
                b = 0;
                c = 0;
            } else if (m - r < 0) {
                // Keep hi v v^T, v the eigenvector of hi (the better conditioned of two forms).
                double vx = b;
                double vy = hi - a;
                if (Math.abs(hi - c) > Math.abs(vy)) {
                    vx = hi - c;
                    vy = b;
                }
                double n2 = vx * vx + vy * vy;
                if (n2 == 0) {
                    vx = a >= c ? 1 : 0;
                    vy = a >= c ? 0 : 1;
                    n2 = 1;
                }
                a = hi * vx * vx / n2;
                b = hi * vx * vy / n2;
                c = hi * vy * vy / n2;
            }
        }
        out[oo] = a;
        out[oo + 1] = b;
        out[oo + 2] = c;
    }

    /**
     * out += K p. {@code offset[node]} is the index of the node's x component in p and out, or -1
     * for a node that is not in them (fixed or eliminated: its displacement is zero and its row
     * dropped); null for the full layout (3 x node id). Allocation-free.
     */
    public void multiplyAdd(double[] p, double[] out, int[] offset) {
        multiplyAdd(p, out, offset, 1);
    }

    /** out += scale K p, offsets as in {@link #multiplyAdd(double[], double[], int[])}. */
    public void multiplyAdd(double[] p, double[] out, int[] offset, double scale) {
        multiplyAdd(p, out, offset, scale, 0);
    }

    /**
     * out += (scale + dampingScale beta_e) K_e p summed over the elements (beta_e an element's
     * damping time, s): the stiffness and damping terms of an implicit step's matrix, with the
     * damping matrix taken as beta_e times the tangent.
     */
    public void multiplyAdd(double[] p, double[] out, int[] offset, double scale, double dampingScale) {
        final double[] dy = corner;
        final double[] g = cornerOut;
        for (int e = 0; e < s.triangleCount(); e++) {
            boolean any = false;
            for (int k = 0; k < 3; k++) {
                int op = dof(s.triP[3 * e + k], offset);
                int oq = dof(s.triQ[3 * e + k], offset);
                any |= op >= 0 || oq >= 0;
                for (int d = 0; d < 3; d++) {
                    dy[3 * k + d] = 0.5 * ((op >= 0 ? p[op + d] : 0) + (oq >= 0 ? p[oq + d] : 0));
                }
            }
            if (!any) {
                continue;
            }
            cornerProduct(e, dy, g);
            final double half = 0.5 * (scale + dampingScale * s.triDamping[e]);
            for (int k = 0; k < 3; k++) {
                int op = dof(s.triP[3 * e + k], offset);
                int oq = dof(s.triQ[3 * e + k], offset);
                for (int d = 0; d < 3; d++) {
                    if (op >= 0) {
                        out[op + d] += half * g[3 * k + d];
                    }
                    if (oq >= 0) {
                        out[oq + d] += half * g[3 * k + d];
                    }
                }
            }
        }
    }

    /** The state this tangent belongs to. */
    public SystemState state() {
        return s;
    }

    /**
     * diag += the diagonal of the sum of {@code (scale + dampingScale beta_e) K_e} (full layout, 3 per
     * node), for a Jacobi preconditioner. Costs nine element products per element.
     */
    public void addDiagonal(double[] diag, double scale, double dampingScale) {
        final double[] dy = corner;
        final double[] g = cornerOut;
        for (int e = 0; e < s.triangleCount(); e++) {
            for (int h = 0; h < 6; h++) {
                int n = h < 3 ? s.triP[3 * e + h] : s.triQ[3 * e + h - 3];
                if (!firstAppearance(e, h, n)) {
                    continue; // each node of the element once
                }
                for (int d = 0; d < 3; d++) {
                    // A unit displacement of node n along d moves each corner it belongs to by 1/2 per share.
                    java.util.Arrays.fill(dy, 0);
                    for (int c = 0; c < 3; c++) {
                        dy[3 * c + d] = weight(e, c, n);
                    }
                    cornerProduct(e, dy, g);
                    double sum = 0;
                    for (int c = 0; c < 3; c++) {
                        sum += weight(e, c, n) * g[3 * c + d];
                    }
                    diag[3 * n + d] += (scale + dampingScale * s.triDamping[e]) * sum;
                }
            }
        }
    }

    /** How much of node n's displacement corner c of element e takes: 0, 1/2 or 1. */
    private double weight(int e, int c, int n) {
        return (s.triP[3 * e + c] == n ? 0.5 : 0) + (s.triQ[3 * e + c] == n ? 0.5 : 0);
    }

    private boolean firstAppearance(int e, int h, int n) {
        for (int j = 0; j < h; j++) {
            int m = j < 3 ? s.triP[3 * e + j] : s.triQ[3 * e + j - 3];
            if (m == n) {
                return false;
            }
        }
        return true;
    }

    private static int dof(int node, int[] offset) {
        return offset == null ? 3 * node : offset[node];
    }

    /** g = K_e dy on one element's corners (9 components each, corner-major). */
    void cornerProduct(int e, double[] dy, double[] g) {
        final double[] r = s.triRest;
        final double r00 = r[4 * e];
        final double r01 = r[4 * e + 1];
        final double r10 = r[4 * e + 2];
        final double r11 = r[4 * e + 3];
        final int o = 6 * e;
        double ue = 0;
        double we = 0;
        double uw = 0;
        double wu = 0;
        final double[] du = scratchU;
        final double[] dw = scratchW;
        for (int d = 0; d < 3; d++) {
            double da = dy[3 + d] - dy[d];
            double db = dy[6 + d] - dy[d];
            du[d] = da * r00 + db * r10;
            dw[d] = da * r01 + db * r11;
            ue += grad[o + d] * du[d];
            we += grad[o + 3 + d] * dw[d];
            uw += grad[o + d] * dw[d];
            wu += grad[o + 3 + d] * du[d];
        }
        final double mu2 = 2 * s.triMu[e];
        final double dtr = s.triLambda[e] * (ue + we);
        final double ds00 = mu2 * ue + dtr;
        final double ds11 = mu2 * we + dtr;
        final double ds01 = mu2 * 0.5 * (uw + wu);
        final double s00 = stress[3 * e];
        final double s01 = stress[3 * e + 1];
        final double s11 = stress[3 * e + 2];
        for (int d = 0; d < 3; d++) {
            double c0 = stressProduct(du[d], dw[d], grad[o + d], grad[o + 3 + d], s00, s01, ds00, ds01);
            double c1 = stressProduct(du[d], dw[d], grad[o + d], grad[o + 3 + d], s01, s11, ds01, ds11);
            g[3 + d] = c0 * r00 + c1 * r01;
            g[6 + d] = c0 * r10 + c1 * r11;
            g[d] = -g[3 + d] - g[6 + d];
        }
    }

    /**
     * One component of a column of {@code dP = dF S + F dS}: {@code du, dw} the component of dF's
     * columns, {@code u, w} of F's, {@code (sa, sb)} the column of S and {@code (dsa, dsb)} of dS.
     */
    static double stressProduct(double du, double dw, double u, double w, double sa, double sb, double dsa,
            double dsb) {
        return du * sa + dw * sb + u * dsa + w * dsb;
    }

    @Override
    public void multiplyAdd(double[] z, double[] y) {
        multiplyAdd(z, y, null);
    }

    /**
     * Block Gershgorin rows of the elements as linearised: the Frobenius norm (at least the spectral
     * norm) of every 3 x 3 node block {@code K_ij}, added as {@link CriticalTimeStep#gershgorin} adds
     * a spring's stiffness k (whose blocks have norm k): half of {@code sum_j |K_ij|} per node in the
     * rows form, {@code |K_ii| / m_i + sum_{j != i free} |K_ij| / sqrt(m_i m_j)} in the symmetric form.
     */
    @Override
    public void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
        double[] k = new double[81];
        double[] dy = new double[9];
        double[] g = new double[9];
        int[] node = new int[6];
        int[] cornerOf = new int[6];
        for (int e = 0; e < s.triangleCount(); e++) {
            for (int c = 0; c < 9; c++) {
                java.util.Arrays.fill(dy, 0);
                dy[c] = 1;
                cornerProduct(e, dy, g);
                for (int rr = 0; rr < 9; rr++) {
                    k[9 * rr + c] = g[rr];
                }
            }
            // Node entries: each corner's two nodes with weight 1/2 (one node with weight 1 when p = q).
            for (int h = 0; h < 6; h++) {
                node[h] = h < 3 ? s.triP[3 * e + h] : s.triQ[3 * e + h - 3];
                cornerOf[h] = h % 3;
            }
            for (int i = 0; i < 6; i++) {
                int ni = node[i];
                if (!free[ni]) {
                    continue;
                }
                for (int j = 0; j < 6; j++) {
                    int nj = node[j];
                    double norm = 0.25 * blockNorm(k, cornerOf[i], cornerOf[j]);
                    if (form == CriticalTimeStep.Form.ROWS) {
                        row[ni] += 0.5 * norm;
                    } else if (nj == ni) {
                        row[ni] += norm / mass[ni];
                    } else if (free[nj]) {
                        row[ni] += norm / Math.sqrt(mass[ni] * mass[nj]);
                    }
                }
            }
        }
    }

    private static double blockNorm(double[] k, int ci, int cj) {
        double sum = 0;
        for (int a = 0; a < 3; a++) {
            for (int b = 0; b < 3; b++) {
                double v = k[9 * (3 * ci + a) + 3 * cj + b];
                sum += v * v;
            }
        }
        return Math.sqrt(sum);
    }
}
