package org.tensim.solver.integrators;

import org.tensim.model.Check;
import org.tensim.solver.ConjugateGradient;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SolverSettings;
import org.tensim.solver.SystemState;
import org.tensim.solver.TriangleTangent;
import org.tensim.solver.links.LinkTangent;
import org.tensim.solver.stability.LinearStability;

/**
 * Backward (implicit) Euler, linearised once per step (Baraff and Witkin 1998):
 * with S = -df/dx (stiffness) and C = -df/dv (damping) at the start of the step,
 * the velocity change dv solves
 *
 * <pre>
 *   (M + h C + h^2 S) dv = h (f(t + h, x, v) - h S v)
 *   v &lt;- v + dv,   x &lt;- x + h v
 * </pre>
 *
 * The system is solved matrix-free by conjugate gradient with a Jacobi
 * (diagonal) preconditioner on the free nodes only (fixed and driven nodes have
 * dv = 0: their rows and columns are filtered out).
 *
 * <p>Per spring of stiffness k, rest length L, length l and direction u, the
 * stiffness block is {@code k (u u^T + max(0, 1 - L/l) (I - u u^T))}: the
 * transverse term of a compressed spring (l &lt; L) is negative and is clamped to
 * zero, which keeps the matrix symmetric positive definite so that CG applies.
 * Membrane triangles add their tangent stiffness with the compressive stress dropped
 * ({@link TriangleTangent}), positive semi-definite likewise, and transverse shear elements
 * {@code k grad g grad g^T} ({@link org.tensim.solver.ShearElements}), volume elements their Gauss-Newton
 * {@code K V b b^T} ({@link org.tensim.solver.VolumeElements}), and each node in contact with a rigid
 * body {@code k n n^T} at t + h ({@link org.tensim.solver.ContactForces}: the pairs in contact at the start of
 * the step; one that comes into contact within the step is caught at the next).
 * Axial damping c adds {@code c u u^T} to C, viscous damping c_v adds c_v I. An
 * approximate Jacobian leaves the order at 1 (a linearly implicit Euler step is
 * first order with any Jacobian); only the stability depends on it.
 *
 * <p>The rigid links are kept within the step ({@link LinkTangent}, as in BDF2): linearised at the
 * start-of-step positions predicted to the end of the step, {@code x + h v} (driven nodes at t + h),
 * each link asks {@code (dv_b - dv_a) . n = (L - |d|) / h} of the velocity change; the first guess is
 * shifted onto these constraints (mass-weighted) and CG runs in their tangent space with the
 * M-orthogonal projector P (on {@code P^T A P}, preconditioner {@code P D^-1 P^T}, residual
 * {@code P^T r}: the force along a link is the link's, not the CG's), stopped at the tolerance
 * times |b| as without links ({@code |P^T b|} vanishes at a constrained rest). Without
 * them a step far beyond the stiff elements' periods let the shell relax across the material
 * model's rigid columns before stage 2 put them back, and the run came to rest off the constrained
 * equilibrium (docs/diaphragm.md). Why x + h v, once: a link that turns over the step then asks
 * for its length where it will be. Measured (10-ring diaphragm, CG to 1e-3, against RK2 at end of
 * inspiration, shear elements undamped): at 10 ms 2.3 % linearised at x, 0.11 % at x + h v, 0.09 % linearised again after
 * a first solve for 26 % more CG products (5 ms: 0.055, 0.034, 0.038 %; without the links 16 % and
 * 38 %); the remainder is left to stage 2.
 *
 * <p>Global error O(h); one force evaluation per step plus the CG iterations, each
 * one matrix-vector product about as costly as a spring force pass ({@link
 * #matrixVectorProducts()}). Stability: R(z) = 1 / (1 - z), |R| &lt; 1 on the
 * whole imaginary axis: unconditionally stable on springs, and it loses energy
 * (numerical damping that grows with w h).
 */
public final class ImplicitEuler implements Integrator {
    /** Default CG stopping tolerance: residual norm at most 1e-12 of the right-hand side's ({@link SolverSettings}). */
    public static final double DEFAULT_TOLERANCE = SolverSettings.DEFAULTS.cgTolerance();
    /** Default cap on CG iterations per step: 500 ({@link SolverSettings}). */
    public static final int DEFAULT_MAX_ITERATIONS = SolverSettings.DEFAULTS.cgMaxIterations();

    private static final LinearStability STABILITY = LinearStability.declared(Double.POSITIVE_INFINITY,
            (h, zeta, x, v) -> {
                double v1 = (v - h * x) / (1 + h * (2 * zeta) + h * h);
                return new double[] {x + h * v1, v1};
            });

    /** (1 + h c + h^2) v1 = v - h x, x1 = x + h v1 on x'' = -x - c x': |R| &lt; 1 at every step. */
    @Override
    public LinearStability stability() {
        return STABILITY;
    }

    private double tolerance = DEFAULT_TOLERANCE;
    private int maxIterations = DEFAULT_MAX_ITERATIONS;

    private double[] f;
    private double[] xs;
    private double[] vs;
    private double[] dv;
    private double[] r;
    private double[] ap;
    private ConjugateGradient cg;
    private double[] invDiag; // per degree of freedom: 1 / A_kk on free nodes, 0 elsewhere
    private double[] free; // per degree of freedom: 1 on free nodes, 0 on fixed and driven ones
    private double[] massTerm; // per degree of freedom: (m + h c_v) on free nodes, 0 elsewhere
    private double[] xp; // positions the links are linearised at: x + h v (free), at t + h (driven)
    private SpringBlocks springs;
    private LinkTangent links; // null without rigid links
    private SystemState linksState;
    private final double[] scratch = new double[6];
    private TriangleTangent triangles; // null without membrane triangles
    private SystemState s;
    private double h;

    private int lastIterations;
    private double lastRelativeResidual;
    private long products;
    private long unconvergedSolves;

    @Override
    public String name() {
        return "implicit-euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public boolean explicit() {
        return false;
    }

    /** The CG tolerance and iteration cap of the settings. */
    @Override
    public void configure(SolverSettings settings) {
        setTolerance(settings.cgTolerance()).setMaxIterations(settings.cgMaxIterations());
    }

    /** Relative residual at which CG stops (dimensionless, > 0). */
    public ImplicitEuler setTolerance(double relative) {
        tolerance = Check.positive("implicit Euler CG tolerance", "(relative residual)", relative);
        return this;
    }

    /** Relative residual at which CG stops. */
    public double tolerance() {
        return tolerance;
    }

    /** Cap on CG iterations per step (>= 1). */
    public ImplicitEuler setMaxIterations(int n) {
        maxIterations = Check.atLeast("implicit Euler CG iteration cap", n, 1);
        return this;
    }

    /** Cap on CG iterations per step. */
    public int maxIterations() {
        return maxIterations;
    }

    /** CG iterations of the last step. */
    public int lastIterations() {
        return lastIterations;
    }

    /** Relative residual |r| / |b| at the end of the last step's solve (with rigid links |P^T r| / |b|). */
    public double lastRelativeResidual() {
        return lastRelativeResidual;
    }

    /** Matrix-vector products made so far (each costs about one spring force pass). */
    public long matrixVectorProducts() {
        return products;
    }

    /** Steps whose CG stopped at the iteration cap above the tolerance (the step still used its iterate). */
    public long unconvergedSolves() {
        return unconvergedSolves;
    }

    @Override
    public void step(ForceModel model, double t, double step) {
        SystemState st = model.state();
        allocate(st);
        this.s = st;
        this.h = step;
        final int n3 = 3 * st.nodeCount;
        final double[] x = st.x;
        final double[] v = st.v;

        // Driven nodes at their end-of-step positions: their pull is taken implicitly too.
        System.arraycopy(x, 0, xs, 0, n3);
        System.arraycopy(v, 0, vs, 0, n3);
        st.applyMotions(t + step, xs, vs, scratch);
        model.computeForces(t + step, xs, vs, f);
        linearise(t + step, xs);

        // b = h (f - h S v), on free nodes only; r = b - A dv with dv from the last step as the first guess.
        applyStiffness(vs, ap);
        final double[] fr = free;
        for (int k = 0; k < n3; k++) {
            // Selected, not multiplied by the 0/1 mask: a fixed node's force may be anything.
            r[k] = fr[k] == 0 ? 0 : step * (f[k] - step * ap[k]);
            if (fr[k] == 0) {
                dv[k] = 0;
            }
        }
        if (links != null) {
            for (int k = 0; k < n3; k++) {
                xp[k] = fr[k] == 0 ? xs[k] : xs[k] + step * vs[k];
            }
            links.linearise(xp, step);
            links.constrainIncrement(dv);
        }
        solve(dot(r, r));

        for (int k = 0; k < n3; k++) {
            if (fr[k] != 0) {
                v[k] += dv[k];
                x[k] += step * v[k];
            }
        }
        st.applyMotions(t + step, x, v, scratch);
    }

    /**
     * Preconditioned CG on A dv = b ({@link ConjugateGradient}, stopped on |r| / |b|), with r holding b on entry
     * and the last step's dv as the first guess; with links, projected CG on {@code P^T A P} from a first guess
     * that meets the linearised links. dv stays 0 on fixed and driven nodes (the preconditioner is 0 there).
     */
    private void solve(double bNorm2) {
        final int n3 = r.length;
        multiply(dv, ap);
        for (int k = 0; k < n3; k++) {
            r[k] -= ap[k];
        }
        if (links != null) {
            links.projectDual(r);
        }
        if (!cg.solve(system, dv, r, bNorm2, tolerance, maxIterations, ConjugateGradient.Stop.RESIDUAL)) {
            unconvergedSolves++;
        }
        lastIterations = cg.iterations();
        lastRelativeResidual = cg.relativeResidual();
    }

    /** A = M + h C + h^2 S on free nodes for the CG, in the links' tangent space, with its Jacobi preconditioner. */
    private final ConjugateGradient.Problem system = new ConjugateGradient.Problem() {
        @Override
        public void multiply(double[] pv, double[] out) {
            ImplicitEuler.this.multiply(pv, out);
            if (links != null) {
                links.projectDual(out);
            }
        }

        /** z = D^-1 r (Jacobi), kept in the links' tangent space (P D^-1 P^T: r is already P^T r). */
        @Override
        public void precondition(double[] rv, double[] zv) {
            final double[] id = invDiag;
            for (int k = 0; k < rv.length; k++) {
                zv[k] = rv[k] * id[k];
            }
            if (links != null) {
                links.project(zv);
            }
        }
    };

    /**
     * The springs' blocks ({@link SpringBlocks}), the triangles', shear elements' and contacts' tangents at t (positive
     * semi-definite parts), the lumped mass terms per degree of freedom, and the inverse of A's
     * diagonal (Jacobi).
     */
    private void linearise(double t, double[] px) {
        final double[] m = s.mass;
        final double[] im = s.invMass;
        final double hv = h * s.viscousDamping();
        final double h2 = h * h;
        final double[] dg = invDiag;
        for (int i = 0; i < s.nodeCount; i++) {
            final double fr = im[i] == 0 ? 0 : 1;
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                free[k] = fr;
                massTerm[k] = fr * (m[i] + hv);
                dg[k] = m[i] + hv;
            }
        }
        springs.linearise(s, px, h, dg);
        if (triangles != null) {
            triangles.linearise(px, true);
            triangles.addDiagonal(dg, h2, h);
        }
        s.shears.linearise(px, false);
        s.shears.addDiagonal(dg, h2, h);
        s.volumes.linearise(px);
        s.volumes.addDiagonal(dg, h2, h);
        s.contacts.linearise(t, px);
        s.contacts.addDiagonal(dg, h2);
        for (int k = 0; k < dg.length; k++) {
            dg[k] = free[k] / dg[k];
        }
    }

    /** out = S p (stiffness only: springs, triangles, shear elements, contacts), for every node. */
    private void applyStiffness(double[] pv, double[] out) {
        java.util.Arrays.fill(out, 0);
        springs.addStiffness(s, pv, out);
        if (triangles != null) {
            triangles.multiplyAdd(pv, out, null);
        }
        s.shears.multiplyAdd(pv, out, null, 1);
        s.volumes.multiplyAdd(pv, out, 1, 0);
        s.contacts.multiplyAdd(pv, out, null, 1);
    }

    /** out = (M + h C + h^2 S) p on free nodes, 0 on the others. */
    private void multiply(double[] pv, double[] out) {
        products++;
        final double[] mt = massTerm;
        final double[] fr = free;
        final int n3 = out.length;
        for (int k = 0; k < n3; k++) {
            out[k] = mt[k] * pv[k];
        }
        springs.addStep(s, pv, out);
        if (triangles != null) {
            triangles.multiplyAdd(pv, out, null, h * h, h);
        }
        s.shears.multiplyAdd(pv, out, null, h * h, h);
        s.volumes.multiplyAdd(pv, out, h * h, h);
        s.contacts.multiplyAdd(pv, out, null, h * h);
        for (int k = 0; k < n3; k++) {
            out[k] *= fr[k];
        }
    }

    private static double dot(double[] a, double[] b) {
        double sum = 0;
        for (int k = 0; k < a.length; k++) {
            sum += a[k] * b[k];
        }
        return sum;
    }

    private void allocate(SystemState st) {
        int n3 = 3 * st.nodeCount;
        int ns = st.springCount();
        if (f == null || f.length != n3 || springs.springs() != ns) {
            f = new double[n3];
            xs = new double[n3];
            vs = new double[n3];
            dv = new double[n3];
            r = new double[n3];
            ap = new double[n3];
            cg = new ConjugateGradient(n3);
            invDiag = new double[n3];
            free = new double[n3];
            massTerm = new double[n3];
            xp = new double[n3];
            springs = new SpringBlocks(ns);
        }
        if (st != linksState) {
            linksState = st;
            links = st.linkCount() == 0 ? null : LinkTangent.fullLayout(st);
            if (links != null && links.isEmpty()) {
                links = null;
            }
        }
        if (st.triangleCount() == 0) {
            triangles = null;
        } else if (triangles == null || triangles.state() != st) {
            triangles = new TriangleTangent(st);
        }
    }
}
