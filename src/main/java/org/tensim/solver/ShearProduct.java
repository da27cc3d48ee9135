package org.tensim.solver;

/**
 * The product of the transverse shear elements' tangent ({@link ShearElements}, as linearised by
 * {@link ShearElements#linearise}) with a vector, {@code y += (weight + dampingWeight beta_e) K_e z}
 * summed over the elements, with its scratch: one per element set (so one per thread of a parallel
 * pass, each with its own subset). Scratch allocated once; allocation-free.
 */
final class ShearProduct {
    /** The element's six nodes' offsets, their z (18) and what they receive (18). */
    private final int[] slot = new int[6];
    private final double[] zs = new double[18];
    private final double[] ys = new double[18];
    /** grad g_c . z of the element's three edges. */
    private final double[] dg = new double[3];

    /** See {@link ShearElements#multiplyAdd(double[], double[], int[], double, double)}. */
    void multiplyAdd(ShearElements s, double[] z, double[] y, int[] offset, double weight, double dampingWeight) {
        if (weight == 0 && dampingWeight == 0) {
            return;
        }
        // Per element: its six nodes' offsets resolved once, z gathered once, and with
        // A_c z = z_q - z_p and B_c z = z_p' + z_q' - z_p - z_q (p = c, q = c + 1):
        //   grad g_c . z = S_c . A_c z + e_c . B_c z,
        //   y += m_c grad g_c,  m_c = (weight + dampingWeight beta_e) (K dg)_c,
        // plus weight rho_c H_c z; what the nodes receive is summed in ys and scattered once.
        for (int e = 0; e < s.count(); e++) {
            element(s, e, ALL_NODES, z, y, offset, weight, dampingWeight);
        }
    }

    /** The six nodes of an element, all set. */
    static final int ALL_NODES = 0x3F;

    /**
     * {@link #multiplyAdd(ShearElements, double[], double[], int[], double, double)}'s terms of the elements of
     * {@code codes} ({@code 64 e + slots}) at their nodes whose bit is set in slots: one part's share of the
     * product (owner computes), the same terms in the same order at each of its nodes.
     */
    void multiplyAdd(ShearElements s, int[] codes, double[] z, double[] y, int[] offset, double weight,
            double dampingWeight) {
        if (weight == 0 && dampingWeight == 0) {
            return;
        }
        for (int c : codes) {
            element(s, c >>> 6, c & ALL_NODES, z, y, offset, weight, dampingWeight);
        }
    }

    /** Element e's terms, scattered to its nodes whose bit is set in {@code nodes}. */
    private void element(ShearElements s, int e, int nodes, double[] z, double[] y, int[] offset, double weight,
            double dampingWeight) {
        final int[] sl = slot;
        final double[] zl = zs;
        final double[] yl = ys;
        final int o = 6 * e;
        for (int a = 0; a < 6; a++) {
            final int i = dof(s.node[o + a], offset);
            sl[a] = i;
            for (int d = 0; d < 3; d++) {
                zl[3 * a + d] = i < 0 ? 0 : z[i + d];
                yl[3 * a + d] = 0;
            }
        }
        final int b = 18 * e;
        for (int c = 0; c < 3; c++) {
            final int p = 3 * c;
            final int q = 3 * ((c + 1) % 3);
            double sum = 0;
            for (int d = 0; d < 3; d++) {
                final double az = zl[q + d] - zl[p + d];
                final double bz = zl[9 + p + d] + zl[9 + q + d] - zl[p + d] - zl[q + d];
                sum += s.es[b + 6 * c + 3 + d] * az + s.es[b + 6 * c + d] * bz;
            }
            dg[c] = sum;
        }
        final double w = weight + dampingWeight * s.beta[e];
        for (int c = 0; c < 3; c++) {
            final int r = 9 * e + 3 * c;
            final double m = w * (s.k[r] * dg[0] + s.k[r + 1] * dg[1] + s.k[r + 2] * dg[2]);
            final double wr = weight * s.rho[3 * e + c];
            final int p = 3 * c;
            final int q = 3 * ((c + 1) % 3);
            for (int d = 0; d < 3; d++) {
                final double ed = s.es[b + 6 * c + d];
                final double sd = s.es[b + 6 * c + 3 + d];
                double fp = m * (-sd - ed);
                double fq = m * (sd - ed);
                double fe = m * ed;
                if (wr != 0) { // y += wr H_c z
                    final double az = zl[q + d] - zl[p + d];
                    final double bz = zl[9 + p + d] + zl[9 + q + d] - zl[p + d] - zl[q + d];
                    fp -= wr * (bz + az);
                    fq += wr * (bz - az);
                    fe += wr * az;
                }
                yl[p + d] += fp;
                yl[q + d] += fq;
                yl[9 + p + d] += fe;
                yl[9 + q + d] += fe;
            }
        }
        for (int a = 0; a < 6; a++) {
            final int i = sl[a];
            if (i >= 0 && (nodes & 1 << a) != 0) {
                y[i] += yl[3 * a];
                y[i + 1] += yl[3 * a + 1];
                y[i + 2] += yl[3 * a + 2];
            }
        }
    }

    private static int dof(int n, int[] offset) {
        return offset == null ? 3 * n : offset[n];
    }
}
