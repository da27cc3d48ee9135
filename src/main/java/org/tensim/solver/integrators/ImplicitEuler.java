package org.tensim.solver.integrators;

import org.tensim.model.Check;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SolverSettings;
import org.tensim.solver.SystemState;
import org.tensim.solver.TriangleTangent;
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
 * ({@link TriangleTangent}), positive semi-definite likewise.
 * Axial damping c adds {@code c u u^T} to C, viscous damping c_v adds c_v I. An
 * approximate Jacobian leaves the order at 1 (a linearly implicit Euler step is
 * first order with any Jacobian); only the stability depends on it.
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
    private double[] z;
    private double[] p;
    private double[] ap;
    private double[] invDiag; // per degree of freedom: 1 / A_kk on free nodes, 0 elsewhere
    private double[] free; // per degree of freedom: 1 on free nodes, 0 on fixed and driven ones
    private double[] massTerm; // per degree of freedom: (m + h c_v) on free nodes, 0 elsewhere
    private double[] dir; // per spring: direction u_x, u_y, u_z
    private double[] blockA; // per spring: alpha, beta of its block of A (see linearise)
    private double[] blockS; // per spring: the same for the stiffness S alone: k (1 - g), k g
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

    /** One force pass per step; the CG matrix-vector products come on top ({@link #matrixVectorProducts()}). */
    @Override
    public int forceEvaluationsPerStep() {
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

    /** Relative residual |r| / |b| at the end of the last step's solve. */
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
        linearise(xs);

        // b = h (f - h S v), on free nodes only; r = b - A dv with dv from the last step as the first guess.
        applyStiffness(vs, ap);
        final double[] fr = free;
        double bNorm2 = 0;
        for (int k = 0; k < n3; k++) {
            // Selected, not multiplied by the 0/1 mask: a fixed node's force may be anything.
            double b = fr[k] == 0 ? 0 : step * (f[k] - step * ap[k]);
            r[k] = b;
            bNorm2 += b * b;
            if (fr[k] == 0) {
                dv[k] = 0;
            }
        }
        solve(bNorm2);

        for (int k = 0; k < n3; k++) {
            if (fr[k] != 0) {
                v[k] += dv[k];
                x[k] += step * v[k];
            }
        }
        st.applyMotions(t + step, x, v, scratch);
    }

    /** Preconditioned CG on A dv = b, with r holding b on entry. */
    private void solve(double bNorm2) {
        final int n3 = r.length;
        final double[] id = invDiag; // 0 on fixed and driven nodes: z, p and dv stay 0 there
        multiply(dv, ap);
        for (int k = 0; k < n3; k++) {
            r[k] -= ap[k];
        }
        double stop2 = tolerance * tolerance * bNorm2;
        double rr = dot(r, r);
        int it = 0;
        if (rr > stop2) {
            double rz = 0;
            for (int k = 0; k < n3; k++) {
                z[k] = r[k] * id[k];
                p[k] = z[k];
                rz += r[k] * z[k];
            }
            while (it < maxIterations) {
                multiply(p, ap);
                double pap = dot(p, ap);
                if (!(pap > 0)) {
                    break; // breakdown: A is positive definite on free nodes, so only p = 0 gets here
                }
                double alpha = rz / pap;
                rr = 0;
                double rzNew = 0;
                for (int k = 0; k < n3; k++) {
                    dv[k] += alpha * p[k];
                    final double rk = r[k] - alpha * ap[k];
                    r[k] = rk;
                    rr += rk * rk;
                    final double zk = rk * id[k];
                    z[k] = zk;
                    rzNew += rk * zk;
                }
                it++;
                if (rr <= stop2) {
                    break;
                }
                double beta = rzNew / rz;
                rz = rzNew;
                for (int k = 0; k < n3; k++) {
                    p[k] = z[k] + beta * p[k];
                }
            }
        }
        lastIterations = it;
        lastRelativeResidual = bNorm2 > 0 ? Math.sqrt(rr / bNorm2) : 0;
        if (rr > stop2) {
            unconvergedSolves++;
        }
    }

    /**
     * Per spring, the direction u and the two coefficients of its block of A,
     * {@code h^2 S_s + h C_s = alpha u u^T + beta I} with {@code alpha = h^2 k (1 - g) + h c}
     * and {@code beta = h^2 k g}, g the clamped transverse factor; the lumped mass
     * terms per degree of freedom; and the inverse of A's diagonal (Jacobi).
     */
    private void linearise(double[] px) {
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] kk = s.springK;
        final double[] cc = s.springC;
        final double[] rl = s.springL;
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
        for (int i = 0; i < sa.length; i++) {
            final int a = 3 * sa[i];
            final int b = 3 * sb[i];
            final double dx = px[b] - px[a];
            final double dy = px[b + 1] - px[a + 1];
            final double dz = px[b + 2] - px[a + 2];
            final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            final double inv = len > 0 ? 1 / len : 0;
            final double g = len > 0 ? Math.max(0, 1 - rl[i] / len) : 0;
            final double ux = dx * inv;
            final double uy = dy * inv;
            final double uz = dz * inv;
            final double alpha = h2 * kk[i] * (1 - g) + h * cc[i];
            final double beta = h2 * kk[i] * g;
            dir[3 * i] = ux;
            dir[3 * i + 1] = uy;
            dir[3 * i + 2] = uz;
            blockA[2 * i] = alpha;
            blockA[2 * i + 1] = beta;
            blockS[2 * i] = kk[i] * (1 - g);
            blockS[2 * i + 1] = kk[i] * g;
            final double ddx = alpha * ux * ux + beta;
            final double ddy = alpha * uy * uy + beta;
            final double ddz = alpha * uz * uz + beta;
            dg[a] += ddx;
            dg[a + 1] += ddy;
            dg[a + 2] += ddz;
            dg[b] += ddx;
            dg[b + 1] += ddy;
            dg[b + 2] += ddz;
        }
        if (triangles != null) {
            triangles.linearise(px, true);
            triangles.addDiagonal(dg, h2, h);
        }
        for (int k = 0; k < dg.length; k++) {
            dg[k] = free[k] / dg[k];
        }
    }

    /** out = S p (stiffness only, k (u u^T (1 - g) + g I) per spring), for every node. */
    private void applyStiffness(double[] pv, double[] out) {
        java.util.Arrays.fill(out, 0);
        addBlocks(blockS, pv, out);
        if (triangles != null) {
            triangles.multiplyAdd(pv, out, null);
        }
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
        addBlocks(blockA, pv, out);
        if (triangles != null) {
            triangles.multiplyAdd(pv, out, null, h * h, h);
        }
        for (int k = 0; k < n3; k++) {
            out[k] *= fr[k];
        }
    }

    /**
     * out += sum over springs of the block {@code alpha u u^T + beta I} (coefficients
     * {@code coef[2i]}, {@code coef[2i + 1]}) times (p_b - p_a), added at b and subtracted at a.
     */
    private void addBlocks(double[] coef, double[] pv, double[] out) {
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] u = dir;
        for (int i = 0; i < sa.length; i++) {
            final int a = 3 * sa[i];
            final int b = 3 * sb[i];
            final double ux = u[3 * i];
            final double uy = u[3 * i + 1];
            final double uz = u[3 * i + 2];
            final double beta = coef[2 * i + 1];
            final double rx = pv[b] - pv[a];
            final double ry = pv[b + 1] - pv[a + 1];
            final double rz = pv[b + 2] - pv[a + 2];
            final double ur = coef[2 * i] * (ux * rx + uy * ry + uz * rz);
            final double ax = ur * ux + beta * rx;
            final double ay = ur * uy + beta * ry;
            final double az = ur * uz + beta * rz;
            out[a] -= ax;
            out[a + 1] -= ay;
            out[a + 2] -= az;
            out[b] += ax;
            out[b + 1] += ay;
            out[b + 2] += az;
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
        if (f == null || f.length != n3 || dir.length != 3 * ns) {
            f = new double[n3];
            xs = new double[n3];
            vs = new double[n3];
            dv = new double[n3];
            r = new double[n3];
            z = new double[n3];
            p = new double[n3];
            ap = new double[n3];
            invDiag = new double[n3];
            free = new double[n3];
            massTerm = new double[n3];
            dir = new double[3 * ns];
            blockA = new double[2 * ns];
            blockS = new double[2 * ns];
        }
        if (st.triangleCount() == 0) {
            triangles = null;
        } else if (triangles == null || triangles.state() != st) {
            triangles = new TriangleTangent(st);
        }
    }
}
