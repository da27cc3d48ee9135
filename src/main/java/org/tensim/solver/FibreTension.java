package org.tensim.solver;

import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.tensim.model.ActiveFibre;
import org.tensim.model.ForceLength;

/**
 * The active fibre tensions of a {@link SystemState} ({@link ActiveFibre}) on flat arrays allocated
 * once: forces, energy and tangent stiffness. Fibre e has corner weights {@code g = (-(c_1 + c_2),
 * c_1, c_2)} (each shared equally by a corner's two nodes), volume {@code V = t A0} (m^3) and active
 * stress sigma_a(t) (Pa), scaled by the force-length relation f_L ({@link ForceLength}, with its
 * integral Phi):
 *
 * <pre>
 *   a = sum_k g_k y_k = F f0,   lambda = |a|,   u = a / lambda,   W = sigma_a V Phi(lambda),
 *   f_k = -sigma_a V f_L(lambda) g_k u,
 *   K_kl = d^2 W / dy_k dy_l = sigma_a V g_k g_l (f_L(lambda) (I - u u^T) / lambda + f_L'(lambda) u u^T)
 * </pre>
 *
 * K is positive semi-definite for sigma_a &gt;= 0: a tensed string's geometric stiffness plus the
 * ascending limb's axial stiffness (f_L' &gt;= 0).
 */
public final class FibreTension {
    private final int[] p3; // per fibre and corner: 3 x node id
    private final int[] q3;
    private final double[] coef; // per fibre: c1, c2
    private final double[] volume; // per fibre: t A0, m^3
    private final DoubleUnaryOperator[] stress;
    private final double[] dir; // tangent: u per fibre
    private final double[] scale; // tangent: sigma_a V f_L / lambda per fibre, N/m
    private final double[] axial; // tangent: sigma_a V f_L' per fibre, N/m
    private final double[] scratch = new double[3];

    FibreTension(List<ActiveFibre> fibres) {
        int n = fibres.size();
        p3 = new int[3 * n];
        q3 = new int[3 * n];
        coef = new double[2 * n];
        volume = new double[n];
        stress = new DoubleUnaryOperator[n];
        dir = new double[3 * n];
        scale = new double[n];
        axial = new double[n];
        for (int e = 0; e < n; e++) {
            ActiveFibre f = fibres.get(e);
            for (int k = 0; k < 3; k++) {
                p3[3 * e + k] = 3 * f.p(k);
                q3[3 * e + k] = 3 * f.q(k);
            }
            coef[2 * e] = f.c(1);
            coef[2 * e + 1] = f.c(2);
            volume[e] = f.volumeM3();
            stress[e] = f.stressPa();
        }
    }

    /** Number of fibres. */
    public int count() {
        return volume.length;
    }

    /** a = F f0 of fibre e at positions x, into out[0..2] (m/m). */
    private void image(int e, double[] x, double[] out) {
        final int o = 3 * e;
        final double c1 = coef[2 * e];
        final double c2 = coef[2 * e + 1];
        for (int d = 0; d < 3; d++) {
            final double y0 = x[p3[o] + d] + x[q3[o] + d];
            out[d] = 0.5 * (c1 * (x[p3[o + 1] + d] + x[q3[o + 1] + d] - y0)
                    + c2 * (x[p3[o + 2] + d] + x[q3[o + 2] + d] - y0));
        }
    }

    /** Adds the fibres' forces (N) at time t (s) and positions x (m) to f. Allocation-free. */
    public void forces(double t, double[] x, double[] f) {
        final double[] a = scratch;
        // Fibres usually share one law: evaluate it once per pass, not once per fibre.
        DoubleUnaryOperator law = null;
        double s = 0;
        for (int e = 0; e < volume.length; e++) {
            if (stress[e] != law) {
                law = stress[e];
                s = law.applyAsDouble(t);
            }
            if (s == 0) {
                continue;
            }
            image(e, x, a);
            final double len = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            if (!(len > 0)) {
                continue;
            }
            final double m = s * volume[e] * ForceLength.value(len) / len;
            final double c1 = coef[2 * e];
            final double c2 = coef[2 * e + 1];
            final int o = 3 * e;
            for (int d = 0; d < 3; d++) {
                final double fu = m * a[d];
                addHalf(f, p3[o] + d, q3[o] + d, (c1 + c2) * fu);
                addHalf(f, p3[o + 1] + d, q3[o + 1] + d, -c1 * fu);
                addHalf(f, p3[o + 2] + d, q3[o + 2] + d, -c2 * fu);
            }
        }
    }


    private static void addHalf(double[] f, int p, int q, double v) {
        f[p] += 0.5 * v;
        f[q] += 0.5 * v;
    }

    /** The fibres' energy {@code sum sigma_a(t) V lambda} at time t and positions x, J. */
    public double energy(double t, double[] x) {
        final double[] a = scratch;
        double sum = 0;
        for (int e = 0; e < volume.length; e++) {
            image(e, x, a);
            sum += stress[e].applyAsDouble(t) * volume[e]
                    * ForceLength.integral(Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
        }
        return sum;
    }

    /** Linearises the tangent at time t (s) and positions px (m). */
    public void linearise(double t, double[] px) {
        final double[] a = scratch;
        for (int e = 0; e < volume.length; e++) {
            image(e, px, a);
            final double len = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            final double s = stress[e].applyAsDouble(t);
            final double sv = Math.max(0, s) * volume[e];
            scale[e] = len > 0 ? sv * ForceLength.value(len) / len : 0;
            axial[e] = len > 0 ? sv * ForceLength.slope(len) : 0;
            for (int d = 0; d < 3; d++) {
                dir[3 * e + d] = len > 0 ? a[d] / len : 0;
            }
        }
    }

    /**
     * {@code y += weight K z} with K linearised by {@link #linearise}; {@code offset[i]} is the index of node
     * i's x in z and y, or -1 for a node left out (fixed or driven: its z is taken as 0, its y not written).
     */
    public void multiplyAdd(double[] z, double[] y, int[] offset, double weight) {
        for (int e = 0; e < volume.length; e++) {
            fibre(e, ALL_NODES, z, y, offset, weight);
        }
    }

    /** The six node slots of a fibre (corner k's two nodes at bits 2k and 2k + 1), all set. */
    private static final int ALL_NODES = 0x3F;

    /**
     * The fibres that part {@code part} of a partition of the nodes must go through for its nodes' share of
     * {@link #multiplyAdd(int[], double[], double[], int[], double)}: those with a node it owns, in increasing
     * order, each as {@code 64 e + slots}, bit 2k + end of slots set when the part owns that node of corner k.
     *
     * @param offset as in {@link #multiplyAdd(double[], double[], int[], double)}
     * @param owner  per node of the compact vectors (offset / 3): its part
     */
    public int[] ownedFibres(int[] offset, int[] owner, int part) {
        int[] codes = new int[volume.length];
        int n = 0;
        for (int e = 0; e < volume.length; e++) {
            int slots = 0;
            for (int k = 0; k < 3; k++) {
                for (int end = 0; end < 2; end++) {
                    final int i = offset[(end == 0 ? p3[3 * e + k] : q3[3 * e + k]) / 3];
                    if (i >= 0 && owner[i / 3] == part) {
                        slots |= 1 << (2 * k + end);
                    }
                }
            }
            if (slots != 0) {
                codes[n++] = 64 * e + slots;
            }
        }
        return java.util.Arrays.copyOf(codes, n);
    }

    /**
     * The share of {@link #multiplyAdd(double[], double[], int[], double)} of the nodes of one part (codes of
     * {@link #ownedFibres}): each of them receives the same terms in the same order as there (owner computes; a
     * fibre shared by two parts is computed by both, each keeping its own nodes).
     */
    public void multiplyAdd(int[] codes, double[] z, double[] y, int[] offset, double weight) {
        for (int c : codes) {
            fibre(c >>> 6, c & ALL_NODES, z, y, offset, weight);
        }
    }

    /** y += weight K_e z at the node slots set in {@code slots} (bit 2k + end: corner k's node p or q). */
    private void fibre(int e, int slots, double[] z, double[] y, int[] offset, double weight) {
        final double sc = scale[e] * weight;
        final double sa = axial[e] * weight;
        if (sc == 0 && sa == 0) {
            return;
        }
        final int o = 3 * e;
        final double g0 = -(coef[2 * e] + coef[2 * e + 1]);
        final double g1 = coef[2 * e];
        final double g2 = coef[2 * e + 1];
        double wx = 0;
        double wy = 0;
        double wz = 0;
        for (int k = 0; k < 3; k++) {
            final double g = 0.5 * (k == 0 ? g0 : k == 1 ? g1 : g2);
            for (int end = 0; end < 2; end++) {
                final int i = offset[(end == 0 ? p3[o + k] : q3[o + k]) / 3];
                if (i >= 0) {
                    wx += g * z[i];
                    wy += g * z[i + 1];
                    wz += g * z[i + 2];
                }
            }
        }
        final double ux = dir[o];
        final double uy = dir[o + 1];
        final double uz = dir[o + 2];
        final double uw = ux * wx + uy * wy + uz * wz;
        final double px = sc * (wx - uw * ux) + sa * uw * ux;
        final double py = sc * (wy - uw * uy) + sa * uw * uy;
        final double pz = sc * (wz - uw * uz) + sa * uw * uz;
        for (int k = 0; k < 3; k++) {
            final double g = 0.5 * (k == 0 ? g0 : k == 1 ? g1 : g2);
            for (int end = 0; end < 2; end++) {
                final int i = offset[(end == 0 ? p3[o + k] : q3[o + k]) / 3];
                if (i >= 0 && (slots & 1 << (2 * k + end)) != 0) {
                    y[i] += g * px;
                    y[i + 1] += g * py;
                    y[i + 2] += g * pz;
                }
            }
        }
    }
}
