package org.tensim.solver;

/**
 * The clamped tangent stiffness of the membrane triangles ({@link TriangleTangent}: the same matrix,
 * to round-off) as an implicit step's Newton-Krylov solver applies it many times per linearisation:
 * on compact vectors of the free nodes, in one fused loop per element, split among threads.
 *
 * <p>Why a second form: the general one reads each corner's two nodes through the caller's offset
 * table, once to gather and once to scatter, and tests every node; here every element's six
 * compact offsets are resolved once, at construction, elements without a free node are dropped,
 * and the per-element data (rest-frame inverse, moduli, F's columns, clamped stress) lie in the
 * order in which the product reads them. The elements are grouped by {@link TriangleSlabs}: the
 * slabs have disjoint node sets and are shared among the threads of {@link NodeLoops#runTasks};
 * the seam follows on the calling thread. The grouping does not depend on the thread count, so the
 * product is the same to the last bit with one thread or several.
 *
 * <p>Per element, with {@code a = y_1 - y_0}, {@code b = y_2 - y_0} the corners' displacements
 * ({@code y_k} the mean of the displacements of its two nodes), {@code dF = [a b] R}:
 *
 * <pre>
 *   dS = 2 mu sym(F^T dF) + lambda tr(F^T dF) I,   [g_1 g_2] = (dF S + F dS) R^T,   g_0 = -g_1 - g_2
 * </pre>
 *
 * and {@code (scale + dampingScale beta_e) g_k / 2} is added to each of corner k's two nodes.
 * Arrays allocated once; {@link #linearise} and {@link #multiplyAdd} allocate nothing.
 */
public final class PartitionedTriangleTangent {
    /** Slabs of the partition (fixed: the summation order must not depend on the thread count). */
    public static final int BLOCKS = 8;
    /**
     * Elements from which the slabs are dispatched to the threads (below, the caller runs them: a
     * dispatch, and on a loaded machine the wait for the other thread, cost more); the force pass's
     * threshold ({@code ParallelTrianglePass.MIN_PARALLEL_TRIANGLES}).
     */
    public static final int MIN_PARALLEL_ELEMENTS = 2048;

    private final SystemState s;
    private final int[] element; // source element of each entry, grouped by slab, the seam last
    private final int[] start; // entries of slab b: [start[b], start[b + 1]); the seam: [start[BLOCKS], n)
    private final int[] dof; // per entry: compact offsets of p0, q0, p1, q1, p2, q2 (-1: not free)
    private final double[] rest; // per entry: R row-major (1/m)
    private final double[] mu2; // per entry: 2 A t mu (J)
    private final double[] lambda; // per entry: A t lambda (J)
    private final double[] damping; // per entry: beta_e (s)
    private final double[] grad; // per entry: F's columns u, w
    private final double[] stress; // per entry: s00, s01, s11 (clamped)
    private long version = -1;
    private double[] pIn;
    private double[] pOut;
    private double productScale;
    private double productDampingScale;
    private final NodeLoops.Body slabs = this::slabs;
    private final NodeLoops.Body lineariseRange = this::lineariseRange;

    /**
     * @param offset per node: the index of its x component in the compact vectors, -1 for a node that
     *               is not in them (fixed or eliminated: zero displacement, row dropped)
     */
    public PartitionedTriangleTangent(SystemState state, int[] offset) {
        this.s = state;
        int[] blockOf = TriangleSlabs.blockOf(state, BLOCKS);
        int[] count = new int[BLOCKS + 2];
        for (int e = 0; e < blockOf.length; e++) {
            if (touchesFree(e, offset)) {
                count[blockOf[e] + 1]++;
            }
        }
        start = new int[BLOCKS + 2];
        for (int b = 0; b <= BLOCKS; b++) {
            start[b + 1] = start[b] + count[b + 1];
        }
        int n = start[BLOCKS + 1];
        element = new int[n];
        int[] next = start.clone();
        for (int e = 0; e < blockOf.length; e++) {
            if (touchesFree(e, offset)) {
                element[next[blockOf[e]]++] = e;
            }
        }
        dof = new int[6 * n];
        for (int i = 0; i < n; i++) {
            int e = element[i];
            for (int k = 0; k < 3; k++) {
                dof[6 * i + 2 * k] = offset[state.triP[3 * e + k]];
                dof[6 * i + 2 * k + 1] = offset[state.triQ[3 * e + k]];
            }
        }
        rest = new double[4 * n];
        mu2 = new double[n];
        lambda = new double[n];
        damping = new double[n];
        grad = new double[6 * n];
        stress = new double[3 * n];
    }

    private boolean touchesFree(int e, int[] offset) {
        for (int k = 0; k < 3; k++) {
            if (offset[s.triP[3 * e + k]] >= 0 || offset[s.triQ[3 * e + k]] >= 0) {
                return true;
            }
        }
        return false;
    }

    /** Elements with a free node (the others add nothing to the product). */
    public int elements() {
        return element.length;
    }

    /** Elements on the seam, added by the calling thread after the slabs. */
    public int seamElements() {
        return element.length - start[BLOCKS];
    }

    /**
     * Linearises at positions px (m, full layout), keeping the positive part of the stress; the
     * elements are split among the threads of loops (each writes its own entries only).
     */
    public void linearise(double[] px, NodeLoops loops) {
        if (version != s.parameterVersion()) {
            for (int i = 0; i < element.length; i++) {
                int e = element[i];
                System.arraycopy(s.triRest, 4 * e, rest, 4 * i, 4);
                mu2[i] = 2 * s.triMu[e];
                lambda[i] = s.triLambda[e];
                damping[i] = s.triDamping[e];
            }
            version = s.parameterVersion();
        }
        pIn = px;
        try {
            loops.run(element.length, lineariseRange);
        } finally {
            pIn = null;
        }
    }

    private void lineariseRange(int from, int to) {
        final double[] px = pIn;
        for (int i = from; i < to; i++) {
            int e = element[i];
            TriangleKernels.deformationGradient(s.triP3, s.triQ3, s.triRest, e, px, grad, 6 * i);
            TriangleTangent.stress(grad, 6 * i, s.triMu[e], s.triLambda[e], true, stress, 3 * i);
        }
    }

    /**
     * out += sum over the elements of {@code (scale + dampingScale beta_e) K_e p} on the compact
     * vectors: the stiffness (scale = beta^2) and damping (dampingScale = beta) terms of an implicit
     * step's matrix. {@code loops} shares the slabs among its threads.
     */
    public void multiplyAdd(double[] p, double[] out, double scale, double dampingScale, NodeLoops loops) {
        pIn = p;
        pOut = out;
        productScale = scale;
        productDampingScale = dampingScale;
        try {
            if (element.length >= MIN_PARALLEL_ELEMENTS) {
                loops.runTasks(BLOCKS, slabs);
            } else {
                slabs(0, BLOCKS); // the same slabs in the same order: the same bits
            }
        } finally {
            pIn = null;
            pOut = null;
        }
        product(start[BLOCKS], element.length, p, out, scale, dampingScale);
    }

    private void slabs(int from, int to) {
        product(start[from], start[to], pIn, pOut, productScale, productDampingScale);
    }

    /** p[k], or 0 for k < 0 (a node that is not free). */
    private static double at(double[] p, int k) {
        return k >= 0 ? p[k] : 0;
    }

    /** out[k] += v unless k < 0 (a node that is not free). */
    private static void add(double[] out, int k, double v) {
        if (k >= 0) {
            out[k] += v;
        }
    }

    /** Offset of component c of the node at offset k, -1 for a node that is not free (k = -1). */
    private static int at(int k, int c) {
        return k < 0 ? -1 : k + c;
    }

    /**
     * Component c of the sum of the two nodes of a corner, whose offsets are {@code d[j]} and
     * {@code d[j + 1]} (a node that is not free counts 0).
     */
    private static double corner(double[] p, int[] d, int j, int c) {
        return at(p, at(d[j], c)) + at(p, at(d[j + 1], c));
    }

    /** The fused gather, element product and scatter of the entries [from, to). */
    private void product(int from, int to, double[] p, double[] out, double scale, double dampingScale) {
        final int[] d = dof;
        final double[] r = rest;
        final double[] f = grad;
        final double[] st = stress;
        for (int i = from; i < to; i++) {
            final int o = 6 * i; // corner k's nodes at d[o + 2k], d[o + 2k + 1]
            final double r00 = r[4 * i];
            final double r01 = r[4 * i + 1];
            final double r10 = r[4 * i + 2];
            final double r11 = r[4 * i + 3];
            // Edge displacements a = y_1 - y_0, b = y_2 - y_0 (corners as means of their two nodes).
            final double x0 = corner(p, d, o, 0);
            final double y0 = corner(p, d, o, 1);
            final double z0 = corner(p, d, o, 2);
            final double ax = 0.5 * (corner(p, d, o + 2, 0) - x0);
            final double ay = 0.5 * (corner(p, d, o + 2, 1) - y0);
            final double az = 0.5 * (corner(p, d, o + 2, 2) - z0);
            final double bx = 0.5 * (corner(p, d, o + 4, 0) - x0);
            final double by = 0.5 * (corner(p, d, o + 4, 1) - y0);
            final double bz = 0.5 * (corner(p, d, o + 4, 2) - z0);
            // dF = [a b] R: columns du, dw; F's columns u, w.
            final double dux = ax * r00 + bx * r10;
            final double duy = ay * r00 + by * r10;
            final double duz = az * r00 + bz * r10;
            final double dwx = ax * r01 + bx * r11;
            final double dwy = ay * r01 + by * r11;
            final double dwz = az * r01 + bz * r11;
            final double ux = f[o];
            final double uy = f[o + 1];
            final double uz = f[o + 2];
            final double wx = f[o + 3];
            final double wy = f[o + 4];
            final double wz = f[o + 5];
            final double ue = ux * dux + uy * duy + uz * duz;
            final double we = wx * dwx + wy * dwy + wz * dwz;
            final double uw = ux * dwx + uy * dwy + uz * dwz;
            final double wu = wx * dux + wy * duy + wz * duz;
            final double m2 = mu2[i];
            final double dtr = lambda[i] * (ue + we);
            final double ds00 = m2 * ue + dtr;
            final double ds11 = m2 * we + dtr;
            final double ds01 = m2 * 0.5 * (uw + wu);
            final double s00 = st[3 * i];
            final double s01 = st[3 * i + 1];
            final double s11 = st[3 * i + 2];
            final double half = 0.5 * (scale + dampingScale * damping[i]);
            // dP = dF S + F dS, one component at a time, and its edge forces dP R^T.
            final double c0x = TriangleTangent.stressProduct(dux, dwx, ux, wx, s00, s01, ds00, ds01);
            final double c1x = TriangleTangent.stressProduct(dux, dwx, ux, wx, s01, s11, ds01, ds11);
            final double gax = c0x * r00 + c1x * r01;
            final double gbx = c0x * r10 + c1x * r11;
            final double c0y = TriangleTangent.stressProduct(duy, dwy, uy, wy, s00, s01, ds00, ds01);
            final double c1y = TriangleTangent.stressProduct(duy, dwy, uy, wy, s01, s11, ds01, ds11);
            final double gay = c0y * r00 + c1y * r01;
            final double gby = c0y * r10 + c1y * r11;
            final double c0z = TriangleTangent.stressProduct(duz, dwz, uz, wz, s00, s01, ds00, ds01);
            final double c1z = TriangleTangent.stressProduct(duz, dwz, uz, wz, s01, s11, ds01, ds11);
            final double gaz = c0z * r00 + c1z * r01;
            final double gbz = c0z * r10 + c1z * r11;
            scatter(out, d[o], d[o + 1], half * (-gax - gbx), half * (-gay - gby), half * (-gaz - gbz));
            scatter(out, d[o + 2], d[o + 3], half * gax, half * gay, half * gaz);
            scatter(out, d[o + 4], d[o + 5], half * gbx, half * gby, half * gbz);
        }
    }

    /** Adds (gx, gy, gz) to both nodes of a corner (offsets p, q; -1 for a node that is not free). */
    private static void scatter(double[] out, int p, int q, double gx, double gy, double gz) {
        if (p >= 0) {
            out[p] += gx;
            out[p + 1] += gy;
            out[p + 2] += gz;
        }
        if (q >= 0) {
            out[q] += gx;
            out[q + 1] += gy;
            out[q + 2] += gz;
        }
    }
}
