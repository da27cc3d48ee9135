package org.tensim.solver.prefactored;

import java.util.concurrent.Executor;
import org.tensim.model.Check;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * Large steps by TR-BDF2 (Bank et al. 1985; Hosea and Shampine 1996): a trapezoidal stage to
 * t + gamma h, then a BDF2 stage through t_n, t + gamma h and t + h, with gamma = 2 - sqrt 2. Each stage is
 * solved as {@link PrefactoredBdf2}'s step is (Newton, CG preconditioned by the prefactored sparse Cholesky
 * factor of {@link PrefactoredMatrix}, the rigid links kept within the stage), and with gamma = 2 - sqrt 2
 * both stages have the same weight beta = gamma h / 2, so one factor serves both. L-stable (the BDF2 stage
 * damps what the trapezoid leaves ringing), order 2, with a local error constant about a fifth of BDF2's
 * (|(-3 gamma^2 + 4 gamma - 2) / (12 (2 - gamma))| = 0.040 against BDF2's 2/9 per h^3 x''').
 * One-step: it needs no history, so the first step and a change of step are steps like the others.
 *
 * <p>Each stage solves, for the stage's new velocity v (h in s, M the masses, f the force model):
 *
 * <pre>
 *   M (v - v^) - beta f(t1, x^ + beta v, v) = 0,   x = x^ + beta v,   beta = gamma h / 2
 *   trapezoid, t1 = t + gamma h:  x^ = x_n + beta v_n,      v^ = v_n + beta M^-1 f(t, x_n, v_n)
 *   BDF2,      t1 = t + h:        x^ = a x_g + (1 - a) x_n,  v^ = a v_g + (1 - a) v_n,
 *                                 a = 1 / (gamma (2 - gamma)),  (x_g, v_g) the trapezoid's result
 * </pre>
 *
 * The trapezoid needs the forces at the start of the step: one force pass more than two BDF2 steps, per
 * step. Newton starts from v_n in the trapezoid and from v_g in the BDF2 stage. Cost per step: twice
 * {@link PrefactoredBdf2}'s, plus that force pass. Allocation-free after the first step.
 */
public final class PrefactoredTrBdf2 implements Integrator {
    /** Name in {@link org.tensim.solver.integrators.Integrators}. */
    public static final String NAME = "tr-bdf2";
    /** gamma = 2 - sqrt 2: the fraction of the step the trapezoid covers. */
    public static final double GAMMA = 2 - Math.sqrt(2);
    /** Weight of the trapezoid's end in the BDF2 stage, 1 / (gamma (2 - gamma)). */
    static final double A = 1 / (GAMMA * (2 - GAMMA));

    private int newtonIterations = PrefactoredBdf2.DEFAULT_NEWTON_ITERATIONS;
    private int krylovIterations = PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS;

    private Executor executor;
    private SystemState s;
    private PrefactoredMatrix matrix;
    private NewtonKrylov newton;
    private final double[] scratch = new double[6];
    private double[] f0; // forces at the start of the step, full size
    private long steps;

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public int order() {
        return 2;
    }

    /** At most: the start's force pass, and per stage one residual pass per Newton iteration plus one per CG iteration. */
    @Override
    public int forceEvaluationsPerStep() {
        return 1 + 2 * newtonIterations * (1 + krylovIterations);
    }

    @Override
    public boolean explicit() {
        return false;
    }

    @Override
    public double undampedStabilityLimit() {
        return Double.POSITIVE_INFINITY;
    }

    /** Newton iterations per stage (>= 1). */
    public PrefactoredTrBdf2 setNewtonIterations(int n) {
        newtonIterations = Check.atLeast("TR-BDF2 Newton iterations per stage", n, 1);
        return this;
    }

    /** Newton iterations per stage. */
    public int newtonIterations() {
        return newtonIterations;
    }

    /** Cap on CG iterations per Newton iteration (>= 1). */
    public PrefactoredTrBdf2 setKrylovIterations(int n) {
        krylovIterations = Check.atLeast("TR-BDF2 CG iterations per Newton iteration", n, 1);
        return this;
    }

    /** Cap on CG iterations per Newton iteration. */
    public int krylovIterations() {
        return krylovIterations;
    }

    /** Where the background refactorisations run (default: one shared daemon thread); for tests. */
    public PrefactoredTrBdf2 setRefactorExecutor(Executor e) {
        executor = java.util.Objects.requireNonNull(e, "refactorisation executor");
        if (matrix != null) {
            matrix.setExecutor(e);
        }
        return this;
    }

    /** Factorisations a step had to wait for: 1 after the first step, and never more. */
    public long synchronousFactorisations() {
        return matrix == null ? 0 : matrix.synchronousFactorisations();
    }

    /** Force passes made for the Jacobian products so far (the residual passes come on top). */
    public long jacobianProducts() {
        return newton == null ? 0 : newton.products;
    }

    /** Mean wall time per step of a part of the two stages' solves (ms), as {@link PrefactoredBdf2#partMillisPerStep}. */
    public double partMillisPerStep(Bdf2Part part) {
        return newton == null || steps == 0 ? 0 : newton.partNanos[part.ordinal()] / 1e6 / steps;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState st = model.state();
        setup(st);
        if (matrix.freeCount() == 0) {
            st.applyMotions(t + h, st.x, st.v, scratch);
            return;
        }
        final double beta = GAMMA * h / 2;
        PrefactoredMatrix.Factor factor = matrix.factorFor(beta);
        final int[] nodes = matrix.freeNodes;
        final double[] x = st.x;
        final double[] v = st.v;
        final double[] m = st.mass;
        final double[] xh = newton.xHat;
        final double[] vh = newton.vHat;
        final double[] v0 = newton.guess;
        steps++;

        model.computeForces(t, x, v, f0);
        for (int j = 0; j < nodes.length; j++) {
            final int i = nodes[j];
            for (int c = 0; c < 3; c++) {
                final int k = 3 * i + c;
                final int q = 3 * j + c;
                xh[q] = x[k] + beta * v[k];
                vh[q] = v[k] + beta * f0[k] / m[i];
                v0[q] = v[k];
            }
        }
        newton.solve(model, factor.cholesky, t + GAMMA * h, beta, newtonIterations, krylovIterations,
                PrefactoredBdf2.KRYLOV_TOLERANCE);

        final double[] xn = newton.xIt;
        final double[] vn = newton.vIt;
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                final int k = 3 * nodes[j] + c;
                final int q = 3 * j + c;
                xh[q] = A * xn[k] + (1 - A) * x[k];
                vh[q] = A * vn[k] + (1 - A) * v[k];
                v0[q] = vn[k];
            }
        }
        newton.solve(model, factor.cholesky, t + h, beta, newtonIterations, krylovIterations,
                PrefactoredBdf2.KRYLOV_TOLERANCE);

        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                final int k = 3 * nodes[j] + c;
                x[k] = xn[k];
                v[k] = vn[k];
            }
        }
        // The driven nodes at t + h, as the second stage's solve set them (PrefactoredBdf2 does the same).
        final int[] driven = st.drivenNode;
        for (int d = 0; d < driven.length; d++) {
            final int o = 3 * driven[d];
            for (int c = 0; c < 3; c++) {
                x[o + c] = xn[o + c];
                v[o + c] = vn[o + c];
            }
        }
    }

    private void setup(SystemState st) {
        if (st == s) {
            return;
        }
        s = st;
        matrix = new PrefactoredMatrix(st);
        if (executor != null) {
            matrix.setExecutor(executor);
        }
        newton = new NewtonKrylov(st, matrix.freeIndex, matrix.freeNodes);
        f0 = new double[3 * st.nodeCount];
        steps = 0;
    }
}
