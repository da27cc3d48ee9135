package org.tensim.solver;

import java.util.List;
import org.tensim.model.TransverseShear;

/**
 * The transverse shear elements of a {@link SystemState} ({@link TransverseShear}) on flat arrays
 * allocated once: forces, energy and tangent stiffness. Element e has six nodes (upper corners 0..2,
 * their partners 3..5), the 3 x 3 stiffness K (J/m^4) and the rest values g0 (m^2) of its three edges.
 * Edge k runs from corner p = k to q = k + 1 (mod 3), with partners p', q'; with
 * {@code e_k = x_q - x_p} and {@code S_k = x_p' + x_q' - x_p - x_q}:
 *
 * <pre>
 *   g_k = e_k . S_k,   W = (g - g0)^T K (g - g0) / 2,   rho = K (g - g0),   f = -sum_k rho_k grad g_k,
 *   grad g_k = (-S_k - e_k, S_k - e_k, e_k, e_k)   on p, q, p', q' (sums to zero),
 *   tangent = sum_kl K_kl grad g_k grad g_l^T + sum_k rho_k H_k,
 *   H_k z = (-(B z) - (A z), (B z) - (A z), A z, A z),   A z = z_q - z_p,   B z = z_p' + z_q' - z_p - z_q
 * </pre>
 *
 * (g_k is bilinear, so H_k is constant). With Kelvin-Voigt damping beta (s) the forces use
 * {@code rho = K (g - g0 + beta dg/dt)}. The first term of the tangent is positive semi-definite (K
 * is); the second, indefinite, is kept only on request ({@link #linearise(double[], boolean)}), as the
 * triangles drop their compressive stress. As a stiffness for the critical step: {@link ShearStiffness}.
 */
public final class ShearElements {
    /** Per element: 6 node ids. */
    final int[] node;
    /** Per element: K row-major (9), J/m^4. */
    final double[] k;
    /** Per element: g0 of the 3 edges, m^2. */
    private final double[] g0;
    /** Per element: Kelvin-Voigt damping time beta, s. */
    final double[] beta;
    private boolean damped;
    /**
     * Tangent: per element, e_k and S_k of each edge k at the linearisation, at [18 e + 6 k + d] and
     * [18 e + 6 k + 3 + d]: grad g_k is made of them ({@link #gradient}), and a product needs no more.
     */
    final double[] es;
    /** Tangent: per element, rho (3; 0 when the geometric term is dropped). */
    final double[] rho;
    private final double[] dg = new double[3];
    private final double[] ev = new double[9];
    private final double[] sv = new double[9];
    /** The tangent's product, with its scratch. */
    private final ShearProduct product = new ShearProduct();

    ShearElements(List<TransverseShear> shears, double[] x0) {
        this(shears.size());
        for (int e = 0; e < shears.size(); e++) {
            TransverseShear ts = shears.get(e);
            beta[e] = ts.dampingS();
            damped |= beta[e] != 0;
            for (int a = 0; a < 6; a++) {
                node[6 * e + a] = ts.node(a);
            }
            for (int c = 0; c < 3; c++) {
                for (int l = 0; l < 3; l++) {
                    k[9 * e + 3 * c + l] = ts.stiffness(c, l);
                }
            }
            // g0 by the kernel's own arithmetic on the compiled positions (ts.restG(c) up to round-off):
            // the rest state is then free of force to the last bit.
            edges(e, x0);
            System.arraycopy(dg, 0, g0, 3 * e, 3);
        }
        linearise(x0, false);
    }

    /** n elements' arrays, all zero. */
    private ShearElements(int n) {
        node = new int[6 * n];
        k = new double[9 * n];
        g0 = new double[3 * n];
        beta = new double[n];
        es = new double[18 * n];
        rho = new double[3 * n];
    }

    private ShearElements(ShearElements other, double[] px) {
        node = other.node;
        k = other.k;
        g0 = other.g0;
        beta = other.beta;
        damped = other.damped;
        es = new double[other.es.length];
        rho = new double[other.rho.length];
        linearise(px, false);
    }

    /**
     * The same elements with their own tangent, linearised at px without the geometric term (for a
     * critical-step estimate or a statics solve, which must not disturb a solver's tangent).
     */
    ShearElements tangentAt(double[] px) {
        return new ShearElements(this, px);
    }

    /**
     * The elements {@code elements} (indices into this set) as a set of their own, with their own
     * arrays and scratch (for a thread of a parallel pass); {@link #copyStiffness} refreshes their K.
     */
    public ShearElements subset(int[] elements) {
        return new ShearElements(this, elements);
    }

    private ShearElements(ShearElements other, int[] elements) {
        this(elements.length);
        for (int i = 0; i < elements.length; i++) {
            System.arraycopy(other.node, 6 * elements[i], node, 6 * i, 6);
            System.arraycopy(other.g0, 3 * elements[i], g0, 3 * i, 3);
        }
        copyStiffness(other, elements);
    }

    /** Copies K and beta of {@code source}'s elements {@code elements} into this subset's (made by {@link #subset}). */
    public void copyStiffness(ShearElements source, int[] elements) {
        for (int i = 0; i < elements.length; i++) {
            System.arraycopy(source.k, 9 * elements[i], k, 9 * i, 9);
            beta[i] = source.beta[elements[i]];
            damped |= beta[i] != 0;
        }
    }

    /** Node a (0..5: upper corners, then their partners) of element e. */
    public int node(int e, int a) {
        return node[6 * e + a];
    }

    /** Gives element e the stiffness K of {@code ts}, whose nodes must be e's. */
    void setConstants(int e, TransverseShear ts) {
        org.tensim.model.Check.index("shear element", e, count());
        for (int a = 0; a < 6; a++) {
            if (ts.node(a) != node[6 * e + a]) {
                throw new IllegalArgumentException("shear element " + e + " has other nodes in the new constants: only"
                        + " constants may change, not the topology");
            }
        }
        for (int c = 0; c < 9; c++) {
            k[9 * e + c] = ts.stiffness(c / 3, c % 3);
        }
        beta[e] = ts.dampingS();
        damped |= beta[e] != 0;
    }

    /** The Kelvin-Voigt damping time beta_e of element e, s. */
    public double dampingS(int e) {
        return beta[e];
    }

    /** Whether any element is damped (its forces then depend on the velocities). */
    public boolean damped() {
        return damped;
    }

    /** {@code K_kl} of element e (edges k, l in 0..2), J/m^4. */
    public double stiffness(int e, int k, int l) {
        return this.k[9 * e + 3 * k + l];
    }

    /** Number of elements. */
    public int count() {
        return g0.length / 3;
    }

    /** e_k and S_k of element e's three edges at x into ev, sv (3 per edge); g_k - g0_k into dg. */
    private void edges(int e, double[] x) {
        edges(e, x, null);
    }

    /**
     * The same, and when {@code v} is not null and the element is damped, {@code beta dg_k/dt} added to
     * dg: {@code dg_k/dt = grad g_k . v} at velocities v (m/s), from the same e_k and S_k.
     */
    private void edges(int e, double[] x, double[] v) {
        final int o = 6 * e;
        final boolean rate = v != null && beta[e] != 0;
        for (int c = 0; c < 3; c++) {
            final int p = 3 * node[o + c];
            final int q = 3 * node[o + (c + 1) % 3];
            final int p2 = 3 * node[o + 3 + c];
            final int q2 = 3 * node[o + 3 + (c + 1) % 3];
            double g = 0;
            double dgdt = 0;
            for (int d = 0; d < 3; d++) {
                final double ed = x[q + d] - x[p + d];
                final double sd = x[p2 + d] + x[q2 + d] - x[p + d] - x[q + d];
                ev[3 * c + d] = ed;
                sv[3 * c + d] = sd;
                g += ed * sd;
                if (rate) {
                    dgdt += -(sd + ed) * v[p + d] + (sd - ed) * v[q + d] + ed * (v[p2 + d] + v[q2 + d]);
                }
            }
            dg[c] = g - g0[3 * e + c];
            if (rate) {
                dg[c] += beta[e] * dgdt;
            }
        }
    }

    /** Adds the elements' elastic forces (N) at positions x (m) to f. Allocation-free. */
    public void forces(double[] x, double[] f) {
        forces(x, null, f);
    }

    /**
     * Adds the elements' forces (N) at positions x (m) to f: elastic, and when {@code v} is not null the
     * Kelvin-Voigt damping of the elements whose beta is not 0, at velocities v (m/s):
     * {@code rho = K (g - g0 + beta dg/dt)}, {@code dg_k/dt = grad g_k . v}. Allocation-free.
     */
    public void forces(double[] x, double[] v, double[] f) {
        for (int e = 0; e < count(); e++) {
            edges(e, x, v);
            final int o = 6 * e;
            for (int c = 0; c < 3; c++) {
                final int r = 9 * e + 3 * c;
                final double m = -(k[r] * dg[0] + k[r + 1] * dg[1] + k[r + 2] * dg[2]);
                final int p = 3 * node[o + c];
                final int q = 3 * node[o + (c + 1) % 3];
                final int p2 = 3 * node[o + 3 + c];
                final int q2 = 3 * node[o + 3 + (c + 1) % 3];
                for (int d = 0; d < 3; d++) {
                    final double ed = ev[3 * c + d];
                    final double sd = sv[3 * c + d];
                    f[p + d] -= m * (sd + ed);
                    f[q + d] += m * (sd - ed);
                    f[p2 + d] += m * ed;
                    f[q2 + d] += m * ed;
                }
            }
        }
    }

    /** The elements' energy {@code sum (g - g0)^T K (g - g0) / 2} at positions x, J. */
    public double energy(double[] x) {
        double sum = 0;
        for (int e = 0; e < count(); e++) {
            edges(e, x);
            for (int c = 0; c < 3; c++) {
                final int r = 9 * e + 3 * c;
                sum += 0.5 * dg[c] * (k[r] * dg[0] + k[r + 1] * dg[1] + k[r + 2] * dg[2]);
            }
        }
        return sum;
    }

    /**
     * Linearises the tangent at positions px (m).
     *
     * @param geometric keep the indefinite term {@code sum rho_k H_k} (the exact Hessian); false keeps
     *                  the tangent positive semi-definite for conjugate gradients
     */
    public void linearise(double[] px, boolean geometric) {
        for (int e = 0; e < count(); e++) {
            edges(e, px);
            for (int c = 0; c < 3; c++) {
                final int r = 9 * e + 3 * c;
                rho[3 * e + c] = geometric ? k[r] * dg[0] + k[r + 1] * dg[1] + k[r + 2] * dg[2] : 0;
                final int base = 18 * e + 6 * c;
                for (int d = 0; d < 3; d++) {
                    es[base + d] = ev[3 * c + d];
                    es[base + 3 + d] = sv[3 * c + d];
                }
            }
        }
    }

    /**
     * Component d of grad g_c on slot a of element e, as linearised: {@code -S_c - e_c} on p = c,
     * {@code S_c - e_c} on q = c + 1, {@code e_c} on their partners, 0 on the third corner and its partner.
     */
    private double gradient(int e, int c, int a, int d) {
        final double ed = es[18 * e + 6 * c + d];
        final double sd = es[18 * e + 6 * c + 3 + d];
        final int p = c;
        final int q = (c + 1) % 3;
        if (a == p) {
            return -sd - ed;
        }
        if (a == q) {
            return sd - ed;
        }
        return a == 3 + p || a == 3 + q ? ed : 0;
    }

    /**
     * {@code y += weight K z} with the tangent linearised by {@link #linearise}; {@code offset[i]} is the
     * index of node i's x in z and y, or -1 for a node left out (its z taken as 0, its y not written);
     * null for the full layout (3 x node id). Allocation-free.
     */
    public void multiplyAdd(double[] z, double[] y, int[] offset, double weight) {
        multiplyAdd(z, y, offset, weight, 0);
    }

    /**
     * {@code y += (weight + dampingWeight beta_e) K_e z} summed over the elements: an implicit step's
     * stiffness and damping terms, the damping matrix taken as beta_e times the tangent (without the
     * geometric term); offsets as in {@link #multiplyAdd(double[], double[], int[], double)}.
     */
    public void multiplyAdd(double[] z, double[] y, int[] offset, double weight, double dampingWeight) {
        product.multiplyAdd(this, z, y, offset, weight, dampingWeight);
    }

    /**
     * One part's share of the product for a partition of the nodes ({@link #part}), with its own scratch: a
     * thread each.
     */
    public static final class Part {
        final int[] codes;
        final ShearProduct product = new ShearProduct();

        private Part(int[] codes) {
            this.codes = codes;
        }

        /** Elements the part goes through (those computed by two parts count in both). */
        public int elements() {
            return codes.length;
        }
    }

    /**
     * The share of part {@code part} of a partition of the nodes: the elements with a node it owns, in
     * increasing order, and which of their nodes it owns.
     *
     * @param offset as in {@link #multiplyAdd(double[], double[], int[], double, double)} (not null)
     * @param owner  per node of the compact vectors (offset / 3): its part
     */
    public Part part(int[] offset, int[] owner, int part) {
        int[] codes = new int[count()];
        int n = 0;
        for (int e = 0; e < count(); e++) {
            int slots = 0;
            for (int a = 0; a < 6; a++) {
                final int i = offset[node[6 * e + a]];
                if (i >= 0 && owner[i / 3] == part) {
                    slots |= 1 << a;
                }
            }
            if (slots != 0) {
                codes[n++] = 64 * e + slots;
            }
        }
        return new Part(java.util.Arrays.copyOf(codes, n));
    }

    /**
     * The share of {@link #multiplyAdd(double[], double[], int[], double, double)} of one part's nodes: each
     * of them receives the same terms in the same order as there (owner computes: an element shared by two
     * parts is computed by both, each keeping its own nodes). Parts may run at the same time.
     */
    public void multiplyAdd(Part part, double[] z, double[] y, int[] offset, double weight, double dampingWeight) {
        part.product.multiplyAdd(this, part.codes, z, y, offset, weight, dampingWeight);
    }

    /** diag += weight times the diagonal of {@code sum_kl K_kl grad g_k grad g_l^T} as linearised (full layout). */
    public void addDiagonal(double[] diag, double weight) {
        addDiagonal(diag, weight, 0);
    }

    /** diag += the diagonal of {@code (weight + dampingWeight beta_e) sum_kl K_kl grad g_k grad g_l^T} (full layout). */
    public void addDiagonal(double[] diag, double weight, double dampingWeight) {
        for (int e = 0; e < count(); e++) {
            final double w = weight + dampingWeight * beta[e];
            for (int a = 0; a < 6; a++) {
                for (int d = 0; d < 3; d++) {
                    diag[3 * node[6 * e + a] + d] += w * blockEntry(e, a, d, a, d);
                }
            }
        }
    }

    /** Entry (slot a, axis d; slot b, axis f) of element e's {@code sum_kl K_kl grad g_k grad g_l^T}. */
    double blockEntry(int e, int a, int d, int b, int f) {
        double sum = 0;
        for (int c = 0; c < 3; c++) {
            final double gc = gradient(e, c, a, d);
            if (gc == 0) {
                continue;
            }
            for (int l = 0; l < 3; l++) {
                sum += k[9 * e + 3 * c + l] * gc * gradient(e, l, b, f);
            }
        }
        return sum;
    }
}
