package org.tensim.solver.prefactored;

import java.util.concurrent.Executor;
import org.tensim.model.Check;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * Stage 1 for large steps (10-40 ms): the second-order backward differentiation formula
 * (BDF2) solved by Newton's method, each Newton system by conjugate gradient preconditioned
 * with a sparse Cholesky factor that is computed once and reused at every step
 * ({@link PrefactoredMatrix}: Liu et al. 2013's constant matrix M + beta C + beta^2 L).
 *
 * <p>Scheme, with beta = 2h/3 and the new velocity v as unknown (h in s):
 *
 * <pre>
 *   x = x^ + beta v,   x^ = (4 x_n - x_{n-1}) / 3,   v^ = (4 v_n - v_{n-1}) / 3
 *   g(v) = M (v - v^) - beta f(t + h, x^ + beta v, v) = 0
 * </pre>
 *
 * The first step, and every step after a change of h or a jump in time, is backward Euler
 * (x^ = x_n, v^ = v_n, beta = h): the history is that of the state after stages 2 and 3, so
 * the rigid links and the velocity update enter it as for every integrator. Within the step the
 * rigid links are kept to first order ({@link org.tensim.solver.links.LinkTangent}): a step many
 * times longer than the stiff springs' periods that ignored them would let those springs relax
 * across the links before stage 2 puts them back, and come to rest off the constrained
 * equilibrium. BDF2 is L-stable:
 * it damps the unresolved stiff modes (the through-thickness springs at 10-40 ms) instead of
 * letting them ring, and its error falls as h^2 (backward Euler's as h).
 *
 * <p>Newton: the Jacobian {@code J = M + beta C + beta^2 K} (C = -df/dv, K = -df/dx, with the
 * scene's axial and viscous damping) is applied matrix-free by a directional difference of the
 * force model, one force pass per product (the parallel spring pass when installed); so the
 * residual and the products see the true springs, damping and driven nodes, and only the
 * preconditioner is approximate (isotropic springs). Conjugate gradient chooses its own step
 * length, so a stale factor (after a change of stiffness or of h, while the new one is made
 * in the background) still converges, in more iterations. Fixed and driven nodes are
 * eliminated: driven ones take their prescribed position and velocity at t + h.
 *
 * <p>Cost per step: per Newton iteration one force pass for the residual, and per CG
 * iteration one force pass and one three-column triangular solve with the factor.
 * Allocation-free after the first step (and after a parameter change, whose background
 * factorisation allocates off the stepping thread).
 */
public final class PrefactoredBdf2 implements Integrator, org.tensim.solver.ErrorEstimating {
    /** Name in {@link org.tensim.solver.integrators.Integrators}. */
    public static final String NAME = "bdf2";
    /** Default Newton iterations per step. */
    public static final int DEFAULT_NEWTON_ITERATIONS = 1;
    /**
     * Default cap on CG iterations per Newton iteration: with one Newton iteration at 25 ms the fewest the real-time
     * study found within its 5 % of RK2 at end-inspiration and at the worst moment on the default diaphragm (1 x 5:
     * 2.0 / 4.8 %; 1 x 4, the default before the geodesic tendon, 2.7 / 5.2 % there; docs/diaphragm.md, "Real time").
     */
    public static final int DEFAULT_KRYLOV_ITERATIONS = 5;
    /**
     * Newton iterations per step where stiff one-sided contact acts (a diaphragm in bone surfaces): with the
     * default single iteration the contact's stiffness, linearised once, leaves a residual that accumulates, and
     * a diaphragm at rest in the thorax sinks (docs/thorax.md).
     */
    public static final int CONTACT_NEWTON_ITERATIONS = 3;
    /** Cap on CG iterations per Newton iteration where stiff contact acts (see {@link #CONTACT_NEWTON_ITERATIONS}). */
    public static final int CONTACT_KRYLOV_ITERATIONS = 20;
    /**
     * Link coupling of the real-time step where stiff contact acts ({@link #setLinkCoupling}): the best of 0.3, 1, 10
     * and 100 on the BodyParts3D diaphragm in the shared thorax at 25 ms (docs/thorax.md, "Real time in the thorax").
     */
    public static final double CONTACT_LINK_COUPLING = 1;
    /** Relative residual (dimensionless) at which CG stops. */
    public static final double KRYLOV_TOLERANCE = 1e-3;

    private int newtonIterations = DEFAULT_NEWTON_ITERATIONS;
    private int krylovIterations = DEFAULT_KRYLOV_ITERATIONS;
    private final double krylovTolerance = KRYLOV_TOLERANCE;
    private double linkCoupling;
    private Executor executor;
    private KernelSharing sharing = KernelSharing.MEASURED;

    private SystemState s;
    private PrefactoredMatrix matrix;
    private NewtonKrylov newton;
    private final double[] scratch = new double[6];
    private double[] xOld1; // free nodes, compact: x_{n-1}
    private double[] xOld2; // x_{n-2}
    private double[] vOld1; // v_{n-1}
    private double[] predictor; // quadratic extrapolation of x_{n+1}, for the error estimate
    private int history; // consecutive steps of the same h behind the current state (0, 1, 2)
    private double lastT = Double.NaN;
    private double lastH = Double.NaN;
    private volatile double errorEstimate = Double.NaN;
    private long steps; // steps with free nodes made since setup
    /** The largest sum of squared displacements from x0 over the free nodes since setup, m^2. */
    private double peakDisplacement2;

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public int order() {
        return 2;
    }

    /** At most: one residual pass per Newton iteration plus one pass per CG iteration. */
    @Override
    public int forceEvaluationsPerStep() {
        return newtonIterations * (1 + krylovIterations);
    }

    @Override
    public boolean explicit() {
        return false;
    }

    @Override
    public double undampedStabilityLimit() {
        return Double.POSITIVE_INFINITY;
    }

    /** Newton iterations per step (>= 1). */
    public PrefactoredBdf2 setNewtonIterations(int n) {
        newtonIterations = Check.atLeast("BDF2 Newton iterations per step", n, 1);
        return this;
    }

    /** Newton iterations per step. */
    public int newtonIterations() {
        return newtonIterations;
    }

    /**
     * Ties the rigid links' ends in the preconditioner's matrix, each by {@code c} times the larger diagonal entry of
     * its two ends (dimensionless, &gt;= 0; default 0, the matrix of Liu et al. alone): CG works in the links'
     * tangent space, and a factor that ties their ends approximates the inverse there better where the links carry
     * the shell's thickness and nothing else holds the sheet (a diaphragm on bone surfaces; see
     * {@link PrefactoredMatrix}). It changes the preconditioner only: CG converged to its tolerance gives the same
     * step. A change after the first step takes effect at the next step, with a new factor and a new start of the
     * BDF2 history.
     */
    public PrefactoredBdf2 setLinkCoupling(double c) {
        if (!(c >= 0) || !Double.isFinite(c)) {
            throw new IllegalArgumentException("BDF2 link coupling must be a finite number >= 0, got " + c);
        }
        if (c != linkCoupling) {
            linkCoupling = c;
            s = null; // the pattern changes: a new matrix at the next step
        }
        return this;
    }

    /** The rigid links' coupling in the preconditioner (see {@link #setLinkCoupling}). */
    public double linkCoupling() {
        return linkCoupling;
    }

    /** Cap on CG iterations per Newton iteration. */
    public int krylovIterations() {
        return krylovIterations;
    }

    /** Cap on CG iterations per Newton iteration (>= 1). */
    public PrefactoredBdf2 setKrylovIterations(int n) {
        krylovIterations = Check.atLeast("BDF2 CG iterations per Newton iteration", n, 1);
        return this;
    }

    /**
     * When the preconditioner's solves and the fibres' and shear elements' part of the Jacobian products are
     * shared among the force model's threads, if it has two or more (default {@link KernelSharing#MEASURED}; the
     * same bits in every case). {@link KernelSharing#NEVER} is the form before they were shared, kept for
     * before/after measurements in one run ({@code tensim bench --compare bdf2:serial,bdf2}).
     */
    public PrefactoredBdf2 setKernelSharing(KernelSharing policy) {
        sharing = java.util.Objects.requireNonNull(policy, "kernel sharing");
        if (newton != null) {
            newton.setSharing(policy);
        }
        return this;
    }

    /** When the solves and the products' fibres and shear elements are shared among the force model's threads. */
    public KernelSharing kernelSharing() {
        return sharing;
    }

    /** Where the background refactorisations run (default: one shared daemon thread); for tests. */
    public PrefactoredBdf2 setRefactorExecutor(Executor e) {
        executor = java.util.Objects.requireNonNull(e, "refactorisation executor");
        if (matrix != null) {
            matrix.setExecutor(e);
        }
        return this;
    }

    /**
     * Estimated error of the last step: the local truncation error of the positions, RMS over
     * the free nodes (m), divided by the largest RMS displacement of the free nodes from their
     * initial positions so far (dimensionless; 0.01 = 1 %): relative to the motion's amplitude, so
     * that it does not blow up where a cyclic motion passes its start (end-expiration, where the
     * displacement itself is near 0 and a 60 s run of the diaphragm read 23 %). For BDF2, (2/11)
     * of the difference between the new positions and their quadratic extrapolation from the three
     * before (Milne's device, BDF2's error constant 2/9); for a backward Euler step, half the second difference. It estimates the
     * error made in one step, not the error accumulated over a run (the real-time study measures
     * that against RK2). NaN until two steps of the same size were made. Safe to read from
     * another thread.
     */
    @Override
    public double errorEstimate() {
        return errorEstimate;
    }

    /** Factorisations a step had to wait for: 1 after the first step, and never more. */
    public long synchronousFactorisations() {
        return matrix == null ? 0 : matrix.synchronousFactorisations();
    }

    /** Background refactorisations (after changes of stiffness, damping or step) taken into use. */
    public long backgroundFactorisations() {
        return matrix == null ? 0 : matrix.backgroundFactorisations();
    }

    /** Whether a background refactorisation is under way. */
    public boolean refactorInFlight() {
        return matrix != null && matrix.refactorInFlight();
    }

    /** Nonzeros of the Cholesky factor (0 before the first step). */
    public int factorNonZeros() {
        return matrix == null ? 0 : matrix.factorNonZeros();
    }

    /**
     * Relative residual sqrt(r^T P^-1 r / r0^T P^-1 r0) of the last CG solve of the last step, as
     * last measured (before its final iteration when the iteration cap stopped it).
     */
    public double lastRelativeResidual() {
        return newton == null ? Double.NaN : newton.lastRelativeResidual;
    }

    /**
     * Mean wall time per step of a part of the solve (ms) over the steps made so far
     * (0 before the first step). Timed with {@link System#nanoTime()} around each part.
     */
    public double partMillisPerStep(Bdf2Part part) {
        return newton == null || steps == 0 ? 0 : newton.partNanos[part.ordinal()] / 1e6 / steps;
    }

    /** Force passes made for the Jacobian products so far (the residual passes come on top). */
    public long jacobianProducts() {
        return newton == null ? 0 : newton.products;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState st = model.state();
        setup(st, model);
        if (matrix.freeCount() == 0) {
            st.applyMotions(t + h, st.x, st.v, scratch);
            return;
        }
        boolean continuous = history > 0 && h == lastH && Math.abs(t - (lastT + lastH)) <= 1e-9 * h;
        if (!continuous) {
            history = 0;
        }
        boolean bdf2 = history >= 1;
        double beta = bdf2 ? 2 * h / 3 : h;
        // The factor is that of BDF2's weight even for a start-up backward Euler step, for which it is a
        // preconditioner like any other: one factor per step size, no refactorisation after the first step.
        PrefactoredMatrix.Factor factor = matrix.factorFor(2 * h / 3);

        final int[] nodes = matrix.freeNodes;
        final double[] x = st.x;
        final double[] v = st.v;
        final double[] xh = newton.xHat;
        final double[] vh = newton.vHat;
        final double[] v0 = newton.guess;
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                final int k = 3 * nodes[j] + c;
                final int q = 3 * j + c;
                if (bdf2) {
                    xh[q] = (4 * x[k] - xOld1[q]) / 3;
                    vh[q] = (4 * v[k] - vOld1[q]) / 3;
                    v0[q] = v[k];
                } else {
                    xh[q] = x[k];
                    vh[q] = v[k];
                    v0[q] = v[k];
                }
                predictor[q] = history >= 2 ? 3 * x[k] - 3 * xOld1[q] + xOld2[q] : 2 * x[k] - xOld1[q];
            }
        }
        double[] tmp = xOld2;
        xOld2 = xOld1;
        xOld1 = tmp;
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                xOld1[3 * j + c] = x[3 * nodes[j] + c];
                vOld1[3 * j + c] = v[3 * nodes[j] + c];
            }
        }

        steps++;
        newton.solve(model, factor.cholesky, t + h, beta, newtonIterations, krylovIterations, krylovTolerance);

        final double[] xn = newton.xIt;
        final double[] vn = newton.vIt;
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                final int k = 3 * nodes[j] + c;
                x[k] = xn[k];
                v[k] = vn[k];
            }
        }
        // The driven nodes at t + h: the solve set them (and only read them since), so they are copied
        // rather than evaluated again (the motions of the default diaphragm's 12,000 anchor nodes cost
        // about 1 ms a call, as much as a Jacobian product).
        final int[] driven = st.drivenNode;
        for (int d = 0; d < driven.length; d++) {
            final int o = 3 * driven[d];
            for (int c = 0; c < 3; c++) {
                x[o + c] = xn[o + c];
                v[o + c] = vn[o + c];
            }
        }
        errorEstimate = estimateError(st, bdf2 && history >= 2 ? 2.0 / 11 : 0.5, history >= 1);
        history = Math.min(2, history + 1);
        lastT = t;
        lastH = h;
    }

    /** The relative local error estimate of {@link #errorEstimate()}. */
    private double estimateError(SystemState st, double weight, boolean available) {
        if (!available) {
            return Double.NaN;
        }
        final int[] nodes = matrix.freeNodes;
        double e2 = 0;
        double d2 = 0;
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                final int k = 3 * nodes[j] + c;
                final double e = st.x[k] - predictor[3 * j + c];
                final double d = st.x[k] - st.x0[k];
                e2 += e * e;
                d2 += d * d;
            }
        }
        peakDisplacement2 = Math.max(peakDisplacement2, d2);
        return peakDisplacement2 > 0 ? weight * Math.sqrt(e2 / peakDisplacement2)
                : (e2 > 0 ? Double.POSITIVE_INFINITY : 0);
    }

    private void setup(SystemState st, ForceModel model) {
        if (st == s) {
            return;
        }
        s = st;
        matrix = new PrefactoredMatrix(st, linkCoupling, model);
        if (executor != null) {
            matrix.setExecutor(executor);
        }
        int nf3 = 3 * matrix.freeCount();
        newton = new NewtonKrylov(st, matrix.freeIndex, matrix.freeNodes);
        newton.setSharing(sharing);
        xOld1 = new double[nf3];
        xOld2 = new double[nf3];
        vOld1 = new double[nf3];
        predictor = new double[nf3];
        history = 0;
        peakDisplacement2 = 0;
        steps = 0;
    }
}
