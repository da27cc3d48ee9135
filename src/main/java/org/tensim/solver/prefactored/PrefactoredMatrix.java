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
 * step either way. A scene's own term (a contact on a mapped surface, {@link org.tensim.solver.MappedContact}) adds
 * {@code beta^2} times its {@link org.tensim.solver.ForceTerm#addIsotropicStiffness} in the same way.
 *
 * <p>With a link coupling c &gt; 0 ({@link PrefactoredBdf2#setLinkCoupling}) each rigid link (a, b) adds
 * {@code w (e_a - e_b)(e_a - e_b)^T}, {@code w = c max(A_aa, A_bb)} from the diagonal assembled before the links:
 * CG works in the links' tangent space, with the preconditioner {@code P C^-1 P^T}
 * ({@link org.tensim.solver.links.LinkTangent}). A factor that does not know the links answers a residual partly
 * with motion along them, which the projection then removes, and the rest of its answer is that of a shell whose
 * faces may approach each other; tying the links' ends brings {@code C^-1} towards the inverse within the tangent
 * space (exactly so for a penalty along each link's direction growing without bound, which a scalar factor cannot
 * carry: it ties the ends in all three directions). On a diaphragm held at its origins and sliding on bone
 * (docs/thorax.md, "Real time in the thorax") it takes the step at 25 ms from 64 % of the converged step to 14 %
 * for the same iterations; on the double dome held by its band it costs accuracy (docs/performance.md), so it is 0
 * by default.
 *
 * <p>The first call of {@link #factorFor} factors synchronously (the step waits once). After a
 * change of the state's parameters ({@link SystemState#parameterVersion()}) or of beta, the
 * new matrix is factored on a background thread while the steps keep the old factor; the new
 * one is taken at the first step after it is ready. No step after the first waits.
 */
final class PrefactoredMatrix {
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

        Factor(SparseCholesky cholesky, long parameterVersion, double beta) {
            this.cholesky = cholesky;
            this.parameterVersion = parameterVersion;
            this.beta = beta;
        }

        /** Whether this factor was made for these parameters and weight. */
        boolean isFor(long version, double b) {
            return parameterVersion == version && beta == b;
        }
    }

    private final SystemState s;
    /** The links' coupling c (dimensionless), see the class comment. */
    private final double linkCoupling;
    /** Per node: the added terms' isotropic stiffness, N/m (0 without terms). */
    private final double[] termStiffness;
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

    PrefactoredMatrix(SystemState s) {
        this(s, 0);
    }

    /** The matrix of a state, the rigid links' ends tied by {@code linkCoupling} (0 for none; see the class comment). */
    PrefactoredMatrix(SystemState s, double linkCoupling) {
        this(s, linkCoupling, null);
    }

    /** As {@link #PrefactoredMatrix(SystemState, double)}, with the isotropic stiffness of model's terms (null: none). */
    PrefactoredMatrix(SystemState s, double linkCoupling, org.tensim.solver.ForceModel model) {
        this.s = s;
        this.linkCoupling = linkCoupling;
        termStiffness = new double[s.nodeCount];
        for (int i = 0; model != null && i < model.termCount(); i++) {
            model.term(i).addIsotropicStiffness(termStiffness);
        }
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
        pattern = SparseCholesky.analyse(nf, t.rows, t.cols, t.vals, t.count);
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
     * background refactorisation when it was made for other parameters or another beta.
     *
     * @throws NotPositiveDefiniteException when the (background) factorisation failed
     */
    Factor factorFor(double beta) {
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
            current = build(version, beta, s.springK.clone(), s.springC.clone(), s.viscousDamping());
            synchronousFactorisations++;
        } else if (!current.isFor(version, beta) && inFlight.compareAndSet(false, true)) {
            // The parameters are copied here, on the stepping thread, so the factor sees one consistent set.
            double[] k = s.springK.clone();
            double[] c = s.springC.clone();
            double cv = s.viscousDamping();
            executor.execute(() -> {
                try {
                    ready.set(build(version, beta, k, c, cv));
                } catch (RuntimeException e) {
                    backgroundFailure = e;
                } finally {
                    inFlight.set(false);
                }
            });
        }
        return current;
    }

    private Factor build(long version, double beta, double[] k, double[] c, double cv) {
        Triplets t = assemble(beta, k, c, cv);
        SparseCholesky ch = SparseCholesky.factor(pattern, t.rows, t.cols, t.vals, t.count,
                "M + beta C + beta^2 K (beta = " + beta + " s) on the free nodes");
        return new Factor(ch, version, beta);
    }

    /** The entries of A(beta), both triangles, duplicates to be summed. */
    private Triplets assemble(double beta, double[] k, double[] c, double cv) {
        int nf = freeNodes.length;
        int ns = s.springCount();
        Triplets t = new Triplets(2 * nf + 4 * ns + 36 * s.triangleCount() + 48 * s.shears.count() + s.contacts.count()
                + s.volumes.restPairCount()
                + (linkCoupling > 0 ? 4 * s.linkA.length : 0));
        for (int j = 0; j < nf; j++) {
            t.add(j, j, s.mass[freeNodes[j]] + beta * cv);
        }
        for (int i = 0; i < ns; i++) {
            t.addPair(freeIndex[s.springA[i]], freeIndex[s.springB[i]], beta * beta * k[i] + beta * c[i]);
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
        // Volume elements: a scalar a node pair, the trace of their rest blocks (the matrix preconditions only).
        s.volumes.restPairs((m, n, stiffness, damping) -> {
            int a = freeIndex[m];
            int b = freeIndex[n];
            if (a >= 0 && b >= 0) {
                t.add(a, b, beta * beta * stiffness + beta * damping);
            }
        });
        for (int e = 0; e < s.contacts.count(); e++) {
            int a = freeIndex[s.contacts.node(e)];
            if (a >= 0) {
                t.add(a, a, beta * beta * s.contacts.stiffness(e) / 3);
            }
        }
        for (int j = 0; j < nf; j++) {
            if (termStiffness[freeNodes[j]] != 0) {
                t.add(j, j, beta * beta * termStiffness[freeNodes[j]]);
            }
        }
        if (linkCoupling > 0) {
            addLinks(t);
        }
        return t;
    }

    /** The rigid links' ends tied, each by {@link #linkCoupling} times the larger diagonal entry of its two ends. */
    private void addLinks(Triplets t) {
        double[] diag = new double[freeNodes.length];
        for (int q = 0; q < t.count; q++) {
            if (t.rows[q] == t.cols[q]) {
                diag[t.rows[q]] += t.vals[q];
            }
        }
        for (int e = 0; e < s.linkA.length; e++) {
            int a = freeIndex[s.linkA[e]];
            int b = freeIndex[s.linkB[e]];
            t.addPair(a, b, linkCoupling * Math.max(a >= 0 ? diag[a] : 0, b >= 0 ? diag[b] : 0));
        }
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

        /** {@code w (e_a - e_b)(e_a - e_b)^T}, an end of index -1 (fixed or driven) left out. */
        void addPair(int a, int b, double w) {
            if (a >= 0) {
                add(a, a, w);
            }
            if (b >= 0) {
                add(b, b, w);
            }
            if (a >= 0 && b >= 0) {
                add(a, b, -w);
                add(b, a, -w);
            }
        }
    }
}
