package org.tensim.solver.prefactored;

import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.tensim.solver.SystemState;

/**
 * The constant matrix of the large-step solvers, factored once and reused at every step
 * (Liu, O'Brien, Kavan and Ladislav 2013): on the free nodes only (fixed and driven nodes are
 * eliminated: their springs add to the free end's diagonal), the scalar node matrix
 *
 * <pre>
 *   A(beta) = diag(m_i + beta c_v) + sum over springs (beta^2 k_s + beta c_s) (e_a - e_b)(e_a - e_b)^T
 * </pre>
 *
 * shared by the three coordinates, with m_i the node mass (kg), c_v the viscous damping (N s/m),
 * k_s and c_s a spring's stiffness (N/m) and axial damping (N s/m), and beta the implicit
 * scheme's weight of the new step (s; h for implicit Euler, 2h/3 for BDF2). Each spring is
 * taken isotropically (k I instead of k u u^T), so A does not depend on the positions: it is
 * the exact Hessian of Liu et al.'s local/global energy, and a preconditioner of the true
 * Jacobian M + beta C + beta^2 K of the springs. A membrane triangle adds, likewise isotropically,
 * {@code (beta^2 + beta beta_e) (2 mu + lambda) A t grad N_k . grad N_l} between its corners k, l (its scalar
 * Laplacian at the stiffer of its moduli; a midpoint corner shares it equally between its two nodes).
 * A transverse shear element ({@link org.tensim.solver.ShearElements}) adds, for each edge k (upper corners
 * p, q, their partners p', q'), its stiffest mode: the faces sliding along the edge, {@code g_k} changing by
 * {@code 2 e_k . (mean of p', q' - mean of p, q)}, taken isotropically as a spring of stiffness
 * {@code (beta^2 + beta beta_e) K_kk 4 |e_k|^2} between the two pairs' means. On coarse meshes this mode is
 * several times stiffer than the membrane ({@code kappa G (h / t)^2} against E): without it the
 * preconditioner leaves it to the few Krylov iterations of a step, which do not resolve it.
 * A contact with a rigid body ({@link org.tensim.solver.ContactForces}) adds {@code beta^2 k / 3} to its node's
 * diagonal: the isotropic matrix with the trace of its tangent {@code beta^2 k n n^T} (the factor is shared by the
 * three coordinates, so it cannot carry a direction). Which nodes touch changes from step to step; every pair
 * is taken as touching, the same for all. Left out, a stiff contact ({@code k / m} far above {@code 1 / beta^2})
 * was left to the few Krylov iterations of a step, which do not resolve it; the exact
 * {@code beta^2 k n n^T} is in the Newton-Krylov products ({@link SpringJacobian}), so CG converges to the true
 * step either way.
 *
 * <p><b>Probed</b> (the default where no contact acts and the rigid links are disjoint): the isotropic matrix
 * above misses the membrane's anisotropy, the springs' and triangles' true stiffness along and across them,
 * and the rigid links, and four CG iterations with it leave a Newton step about half resolved. Instead,
 * the entries of the operator CG runs on, {@code A = P^T J P} (the Jacobian in the links' tangent space), are
 * read from products ({@link JacobianProbe}: about 80 on the default diaphragm), and factored as
 * <pre>
 *   A ~ S^(1/2) (A_s (x) I_3) S^(1/2),   (A_s)_ij = tr(A_ij) / 3,   S_i = A_ii / (A_s)_ii
 * </pre>
 * the scalar matrix of A's blocks' mean diagonals, shared by the three coordinates, and per node the 3 x 3
 * scaling that gives back A's diagonal block exactly (its eigenvalues kept above 1e-3 of the largest: along a
 * link, A_ii is nearly singular). Both come from the same linearisation, so the matrix follows the state and
 * every term of the Jacobian (fibres, shear, support) without an assembly of its own. Measured on the default
 * diaphragm at 0.9 s (a Newton system dumped and solved offline): four CG iterations leave 0.37 of the step's
 * error in the energy norm against 0.56 with the isotropic matrix, as eight did with it (docs/performance.md).
 * The graph probed is that of the isotropic matrix widened by the links (P couples a node's neighbours to its
 * link partner's).
 *
 * <p>The first call of {@link #factorFor} factors synchronously (the step waits once; probed, the step also
 * makes all the probing products). After a
 * change of the state's parameters ({@link SystemState#parameterVersion()}) or of beta, the
 * new matrix is factored on a background thread while the steps keep the old factor; the new
 * one is taken at the first step after it is ready. No step after the first waits: probed, the products
 * that read the new matrix are spread over the steps ({@link #PROBE_BUDGET}) before the background
 * factorisation starts.
 */
final class PrefactoredMatrix {
    /**
     * Probing work a step does towards a new probed matrix after a change, in products times free nodes (the first
     * step makes all the products): 3 products a step on the default diaphragm's 11,362 free nodes, all of them
     * at once on a small scene.
     */
    static final int PROBE_BUDGET = 40_000;
    /** Eigenvalues of a node's scaling below this fraction of its largest are raised to it. */
    static final double SCALING_FLOOR = 1e-3;
    /** The default background thread, shared by all instances (a refactorisation is rare). */
    private static final ExecutorService BACKGROUND = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "tensim-refactor");
        t.setDaemon(true);
        return t;
    });

    /** A factor and the parameters it was made for. */
    static final class Factor {
        final SparseCholesky cholesky;
        final long parameterVersion;
        final double beta;
        /** Probed: per free node S_i^(-1/2), row-major (9 doubles); null for the isotropic matrix. */
        final double[] scaling;

        Factor(SparseCholesky cholesky, long parameterVersion, double beta, double[] scaling) {
            this.cholesky = cholesky;
            this.parameterVersion = parameterVersion;
            this.beta = beta;
            this.scaling = scaling;
        }

        /**
         * z = C^-1 z with C the factored matrix (three columns, compact layout): the solve, between the
         * scalings when probed.
         */
        void solve3(double[] z, double[] work, org.tensim.solver.NodeLoops loops) {
            if (scaling != null) {
                scale(z);
            }
            cholesky.solve3(z, work, loops);
            if (scaling != null) {
                scale(z);
            }
        }

        private void scale(double[] z) {
            final double[] m = scaling;
            for (int j = 0, o = 0; o < z.length; j += 9, o += 3) {
                final double a = z[o];
                final double b = z[o + 1];
                final double c = z[o + 2];
                z[o] = m[j] * a + m[j + 1] * b + m[j + 2] * c;
                z[o + 1] = m[j + 3] * a + m[j + 4] * b + m[j + 5] * c;
                z[o + 2] = m[j + 6] * a + m[j + 7] * b + m[j + 8] * c;
            }
        }

        /** Whether this factor was made for these parameters and weight. */
        boolean isFor(long version, double b) {
            return parameterVersion == version && beta == b;
        }
    }

    private final SystemState s;
    /** Free-node index of each node, -1 for fixed and driven nodes. */
    final int[] freeIndex;
    /** Node id of each free node. */
    final int[] freeNodes;
    private final SparseCholesky.Pattern pattern;
    private final AtomicReference<Factor> ready = new AtomicReference<>();
    private final AtomicBoolean inFlight = new AtomicBoolean();
    private volatile RuntimeException backgroundFailure;
    private Executor executor = BACKGROUND;
    private Factor current;
    private long synchronousFactorisations;
    private long backgroundFactorisations;
    /** Null for the isotropic matrix. */
    private final JacobianProbe probe;
    /** The parameters and beta the reading under way is for; whether one is under way. */
    private boolean probing;
    private long probeVersion;
    private double probeBeta;
    private volatile long probedFallbacks;

    /** The isotropic matrix. */
    PrefactoredMatrix(SystemState s) {
        this(s, false);
    }

    /**
     * @param probed whether the matrix is read from the Jacobian ({@link JacobianProbe}) rather than assembled
     *               isotropically; refused where contact acts or rigid links share nodes (the probed graph would
     *               not hold all of A's entries)
     */
    PrefactoredMatrix(SystemState s, boolean probed) {
        this.s = s;
        freeIndex = new int[s.nodeCount];
        int nf = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            freeIndex[i] = s.invMass[i] != 0 ? nf++ : -1;
        }
        freeNodes = new int[nf];
        for (int i = 0; i < s.nodeCount; i++) {
            if (freeIndex[i] >= 0) {
                freeNodes[freeIndex[i]] = i;
            }
        }
        Triplets t = assemble(1, s.springK.clone(), s.springC.clone(), s.viscousDamping());
        if (probed) {
            if (!probeable(s)) {
                throw new IllegalArgumentException("a probed preconditioner needs a scene without contact and with "
                        + "rigid links that share no node");
            }
            probe = graph(t);
            int nnz = probe.column.length;
            int[] r = new int[nnz];
            for (int i = 0; i < nf; i++) {
                for (int p = probe.rowStart[i]; p < probe.rowStart[i + 1]; p++) {
                    r[p] = i;
                }
            }
            pattern = SparseCholesky.analyse(nf, r, probe.column, new double[nnz], nnz);
        } else {
            probe = null;
            pattern = SparseCholesky.analyse(nf, t.rows, t.cols, t.vals, t.count);
        }
    }

    /** Whether the probed matrix applies: no contact, and no node in two rigid links. */
    static boolean probeable(SystemState s) {
        if (s.contacts.count() > 0) {
            return false;
        }
        boolean[] linked = new boolean[s.nodeCount];
        for (int l = 0; l < s.linkA.length; l++) {
            if (linked[s.linkA[l]] || linked[s.linkB[l]]) {
                return false;
            }
            linked[s.linkA[l]] = true;
            linked[s.linkB[l]] = true;
        }
        return true;
    }

    /**
     * The graph of A = P^T J P on the free nodes: the isotropic matrix's entries (every element's nodes), each
     * (i, j) also joining i's and j's link partners (P moves a node with its partner).
     */
    private JacobianProbe graph(Triplets t) {
        int nf = freeNodes.length;
        int[] partner = new int[nf];
        java.util.Arrays.fill(partner, -1);
        for (int l = 0; l < s.linkA.length; l++) {
            int a = freeIndex[s.linkA[l]];
            int b = freeIndex[s.linkB[l]];
            if (a >= 0 && b >= 0) {
                partner[a] = b;
                partner[b] = a;
            }
        }
        java.util.List<java.util.TreeSet<Integer>> rows = new java.util.ArrayList<>(nf);
        for (int i = 0; i < nf; i++) {
            java.util.TreeSet<Integer> row = new java.util.TreeSet<>();
            row.add(i);
            rows.add(row);
        }
        for (int e = 0; e < t.count; e++) {
            int i = t.rows[e];
            int j = t.cols[e];
            for (int a : new int[] {i, partner[i]}) {
                for (int b : new int[] {j, partner[j]}) {
                    if (a >= 0 && b >= 0) {
                        rows.get(a).add(b);
                        rows.get(b).add(a);
                    }
                }
            }
        }
        int[] start = new int[nf + 1];
        for (int i = 0; i < nf; i++) {
            start[i + 1] = start[i] + rows.get(i).size();
        }
        int[] col = new int[start[nf]];
        for (int i = 0, p = 0; i < nf; i++) {
            for (int j : rows.get(i)) {
                col[p++] = j;
            }
        }
        return new JacobianProbe(nf, start, col);
    }

    /** The probe (null for the isotropic matrix); for tests. */
    JacobianProbe probe() {
        return probe;
    }

    /** Whether this matrix is probed from the Jacobian. */
    boolean probed() {
        return probe != null;
    }

    /** Products a full probing reading takes (0 for the isotropic matrix). */
    int probeProducts() {
        return probe == null ? 0 : probe.products();
    }

    /** Probed factorisations that failed (not positive definite) and were replaced by the isotropic matrix. */
    long probedFallbacks() {
        return probedFallbacks;
    }

    /** Where background refactorisations run (default: one shared daemon thread). */
    void setExecutor(Executor e) {
        executor = java.util.Objects.requireNonNull(e, "refactorisation executor");
    }

    /** Free nodes (the order of the factored system). */
    int freeCount() {
        return freeNodes.length;
    }

    /** Nonzeros of the factor. */
    int factorNonZeros() {
        return pattern.factorNonZeros();
    }

    /** Factorisations a step waited for (1 after the first step). */
    long synchronousFactorisations() {
        return synchronousFactorisations;
    }

    /** Factorisations made on the background thread and taken into use. */
    long backgroundFactorisations() {
        return backgroundFactorisations;
    }

    /** Whether a background refactorisation is under way. */
    boolean refactorInFlight() {
        return inFlight.get();
    }

    /**
     * The factor to use for a step with weight {@code beta} (s): the newest one ready. Starts a
     * background refactorisation when it was made for other parameters or another beta; probed, it first
     * reads the new matrix from {@code a} over this and the next steps ({@link #PROBE_BUDGET}).
     *
     * @param a the operator whose entries a probed matrix reads: A = P^T J P at the step's linearisation
     *          (unused by the isotropic matrix)
     * @return the factor to use
     * @throws NotPositiveDefiniteException when the (background) factorisation failed
     */
    Factor factorFor(double beta, JacobianProbe.Operator a) {
        RuntimeException failure = backgroundFailure;
        if (failure != null) {
            backgroundFailure = null;
            throw failure;
        }
        Factor done = ready.getAndSet(null);
        if (done != null) {
            current = done;
            backgroundFactorisations++;
        }
        long version = s.parameterVersion();
        if (current == null) {
            double[] k = s.springK.clone();
            double[] c = s.springC.clone();
            double cv = s.viscousDamping();
            if (probe != null) {
                probe.restart();
                probe.run(a, Integer.MAX_VALUE);
                current = buildProbed(version, beta, probe.traces(), probe.diagonalBlocks(), k, c, cv);
            } else {
                current = build(version, beta, k, c, cv);
            }
            synchronousFactorisations++;
        } else if (!current.isFor(version, beta) && !inFlight.get()) {
            if (probe != null) {
                if (!probing || probeVersion != version || probeBeta != beta) {
                    probe.restart();
                    probing = true;
                    probeVersion = version;
                    probeBeta = beta;
                }
                probe.run(a, Math.max(1, PROBE_BUDGET / Math.max(1, freeNodes.length)));
                if (probe.complete()) {
                    probing = false;
                    double[] tr = probe.traces().clone();
                    double[] blocks = probe.diagonalBlocks().clone();
                    startBackground(version, beta, (k, c, cv) -> buildProbed(version, beta, tr, blocks, k, c, cv));
                }
            } else {
                startBackground(version, beta, (k, c, cv) -> build(version, beta, k, c, cv));
            }
        }
        return current;
    }

    /** Whether {@link #factorFor} would make probing products in this step (the matrix is probed and not current). */
    boolean wantsProducts(double beta) {
        if (probe == null) {
            return false;
        }
        Factor f = ready.get() != null ? ready.get() : current;
        return f == null || (!f.isFor(s.parameterVersion(), beta) && !inFlight.get());
    }

    /** The isotropic matrix's factor for a step of weight beta; no probing. */
    Factor factorFor(double beta) {
        if (probe != null) {
            throw new IllegalStateException("a probed matrix needs the operator to read");
        }
        return factorFor(beta, null);
    }

    private interface Builder {
        Factor build(double[] k, double[] c, double cv);
    }

    private void startBackground(long version, double beta, Builder b) {
        if (!inFlight.compareAndSet(false, true)) {
            return;
        }
        // The parameters are copied here, on the stepping thread, so the factor sees one consistent set.
        double[] k = s.springK.clone();
        double[] c = s.springC.clone();
        double cv = s.viscousDamping();
        executor.execute(() -> {
            try {
                ready.set(b.build(k, c, cv));
            } catch (RuntimeException e) {
                backgroundFailure = e;
            } finally {
                inFlight.set(false);
            }
        });
    }

    /**
     * The probed matrix's factor and scalings (see the class comment); the isotropic matrix's factor when the
     * probed one is not positive definite.
     */
    private Factor buildProbed(long version, double beta, double[] trace, double[] blocks, double[] k, double[] c,
            double cv) {
        int nf = freeNodes.length;
        int nnz = probe.column.length;
        int[] r = new int[nnz];
        for (int i = 0; i < nf; i++) {
            for (int p = probe.rowStart[i]; p < probe.rowStart[i + 1]; p++) {
                r[p] = i;
            }
        }
        double[] scaling = new double[9 * nf];
        for (int i = 0; i < nf; i++) {
            double d = trace[probe.entry(i, i)];
            if (!(d > 0)) {
                probedFallbacks++;
                return build(version, beta, k, c, cv);
            }
            nodeScaling(blocks, i, d, scaling);
        }
        try {
            SparseCholesky ch = SparseCholesky.factor(pattern, r, probe.column, trace, nnz,
                    "tr(P^T J P) / 3 (beta = " + beta + " s) on the free nodes");
            return new Factor(ch, version, beta, scaling);
        } catch (NotPositiveDefiniteException e) {
            probedFallbacks++;
            return build(version, beta, k, c, cv);
        }
    }

    /** S_i^(-1/2) with S_i = (A_ii + A_ii^T) / (2 d), its eigenvalues floored at {@link #SCALING_FLOOR} of the largest. */
    private static void nodeScaling(double[] blocks, int i, double d, double[] out) {
        double[][] m = new double[3][3];
        for (int r = 0; r < 3; r++) {
            for (int q = 0; q < 3; q++) {
                m[r][q] = (blocks[9 * i + 3 * r + q] + blocks[9 * i + 3 * q + r]) / (2 * d);
            }
        }
        org.hipparchus.linear.EigenDecompositionSymmetric eig = new org.hipparchus.linear.EigenDecompositionSymmetric(
                new org.hipparchus.linear.Array2DRowRealMatrix(m, false));
        double[] lambda = eig.getEigenvalues();
        double top = Math.max(lambda[0], Math.max(lambda[1], lambda[2]));
        if (!(top > 0)) {
            top = 1;
        }
        for (int r = 0; r < 3; r++) {
            for (int q = 0; q < 3; q++) {
                double sum = 0;
                for (int e = 0; e < 3; e++) {
                    org.hipparchus.linear.RealVector v = eig.getEigenvector(e);
                    sum += v.getEntry(r) * v.getEntry(q) / Math.sqrt(Math.max(lambda[e], SCALING_FLOOR * top));
                }
                out[9 * i + 3 * r + q] = sum;
            }
        }
    }

    private Factor build(long version, double beta, double[] k, double[] c, double cv) {
        Triplets t = assemble(beta, k, c, cv);
        SparseCholesky ch = SparseCholesky.factor(pattern, t.rows, t.cols, t.vals, t.count,
                "M + beta C + beta^2 K (beta = " + beta + " s) on the free nodes");
        return new Factor(ch, version, beta, null);
    }

    /** The entries of A(beta), both triangles, duplicates to be summed. */
    private Triplets assemble(double beta, double[] k, double[] c, double cv) {
        int nf = freeNodes.length;
        int ns = s.springCount();
        Triplets t = new Triplets(nf + 4 * ns + 36 * s.triangleCount() + 48 * s.shears.count() + s.contacts.count());
        for (int j = 0; j < nf; j++) {
            t.add(j, j, s.mass[freeNodes[j]] + beta * cv);
        }
        for (int i = 0; i < ns; i++) {
            double w = beta * beta * k[i] + beta * c[i];
            int a = freeIndex[s.springA[i]];
            int b = freeIndex[s.springB[i]];
            if (a >= 0) {
                t.add(a, a, w);
            }
            if (b >= 0) {
                t.add(b, b, w);
            }
            if (a >= 0 && b >= 0) {
                t.add(a, b, -w);
                t.add(b, a, -w);
            }
        }
        double[] grad = new double[6];
        for (int e = 0; e < s.triangleCount(); e++) {
            // Gradients of the corners' shape functions in the rest frame: rows of D_m^-1, and minus their sum.
            grad[2] = s.triRest[4 * e];
            grad[3] = s.triRest[4 * e + 1];
            grad[4] = s.triRest[4 * e + 2];
            grad[5] = s.triRest[4 * e + 3];
            grad[0] = -grad[2] - grad[4];
            grad[1] = -grad[3] - grad[5];
            double w = (beta * beta + beta * s.triDamping[e]) * (2 * s.triMu[e] + s.triLambda[e]);
            for (int h = 0; h < 6; h++) {
                int a = freeIndex[h < 3 ? s.triP[3 * e + h] : s.triQ[3 * e + h - 3]];
                for (int g = 0; g < 6 && a >= 0; g++) {
                    int b = freeIndex[g < 3 ? s.triP[3 * e + g] : s.triQ[3 * e + g - 3]];
                    int ck = h % 3;
                    int cl = g % 3;
                    if (b >= 0) {
                        t.add(a, b, 0.25 * w * (grad[2 * ck] * grad[2 * cl] + grad[2 * ck + 1] * grad[2 * cl + 1]));
                    }
                }
            }
        }
        addShears(t, beta);
        for (int e = 0; e < s.contacts.count(); e++) {
            int a = freeIndex[s.contacts.node(e)];
            if (a >= 0) {
                t.add(a, a, beta * beta * s.contacts.stiffness(e) / 3);
            }
        }
        return t;
    }

    /** The shear elements' sliding modes (see the class comment). */
    private void addShears(Triplets t, double beta) {
        final double[] x0 = s.x0;
        final int[] slot = new int[4];
        for (int e = 0; e < s.shears.count(); e++) {
            double w = beta * beta + beta * s.shears.dampingS(e);
            for (int c = 0; c < 3; c++) {
                int p = s.shears.node(e, c);
                int q = s.shears.node(e, (c + 1) % 3);
                double ex = x0[3 * q] - x0[3 * p];
                double ey = x0[3 * q + 1] - x0[3 * p + 1];
                double ez = x0[3 * q + 2] - x0[3 * p + 2];
                // Spring between the means: u = (-1/2, -1/2, 1/2, 1/2) on p, q, p', q', stiffness k, k u u^T.
                double k = w * s.shears.stiffness(e, c, c) * 4 * (ex * ex + ey * ey + ez * ez);
                slot[0] = freeIndex[p];
                slot[1] = freeIndex[q];
                slot[2] = freeIndex[s.shears.node(e, 3 + c)];
                slot[3] = freeIndex[s.shears.node(e, 3 + (c + 1) % 3)];
                for (int a = 0; a < 4; a++) {
                    for (int b = 0; b < 4 && slot[a] >= 0; b++) {
                        if (slot[b] >= 0) {
                            t.add(slot[a], slot[b], 0.25 * k * ((a < 2) == (b < 2) ? 1 : -1));
                        }
                    }
                }
            }
        }
    }

    /** Matrix entries in triplet form. */
    private static final class Triplets {
        final int[] rows;
        final int[] cols;
        final double[] vals;
        int count;

        Triplets(int capacity) {
            rows = new int[capacity];
            cols = new int[capacity];
            vals = new double[capacity];
        }

        void add(int r, int c, double v) {
            rows[count] = r;
            cols[count] = c;
            vals[count++] = v;
        }
    }
}
