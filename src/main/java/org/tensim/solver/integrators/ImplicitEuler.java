package org.tensim.solver.integrators;

import org.tensim.model.Check;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

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
    /** Default CG stopping tolerance: residual norm at most 1e-12 of the right-hand side's. */
    public static final double DEFAULT_TOLERANCE = 1e-12;
    /** Default cap on CG iterations per step. */
    public static final int DEFAULT_MAX_ITERATIONS = 500;

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
    private double[] diag;
    private double[] su; // per spring: direction u (3)
    private double[] sg; // per spring: clamped transverse factor max(0, 1 - L/l)
    private final double[] scratch = new double[6];
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

    @Override
    public double undampedStabilityLimit() {
        return Double.POSITIVE_INFINITY;
    }

    /** Relative residual at which CG stops (dimensionless, > 0). */
    public ImplicitEuler setTolerance(double relative) {
        tolerance = Check.positive("implicit Euler CG tolerance", "(relative residual)", relative);
        return this;
    }

    /** Cap on CG iterations per step (>= 1). */
    public ImplicitEuler setMaxIterations(int n) {
        maxIterations = Check.atLeast("implicit Euler CG iteration cap", n, 1);
        return this;
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
        final double[] im = st.invMass;

        // Driven nodes at their end-of-step positions: their pull is taken implicitly too.
        System.arraycopy(x, 0, xs, 0, n3);
        System.arraycopy(v, 0, vs, 0, n3);
        st.applyMotions(t + step, xs, vs, scratch);
        model.computeForces(t + step, xs, vs, f);
        linearise(xs);

        // b = h (f - h S v), on free nodes only; r = b - A dv with dv from the last step as the first guess.
        applyStiffness(vs, ap);
        double bNorm2 = 0;
        for (int k = 0; k < n3; k++) {
            double b = im[k / 3] == 0 ? 0 : step * (f[k] - step * ap[k]);
            r[k] = b;
            bNorm2 += b * b;
            if (im[k / 3] == 0) {
                dv[k] = 0;
            }
        }
        solve(bNorm2);

        for (int i = 0; i < st.nodeCount; i++) {
            if (im[i] == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                v[k] += dv[k];
                x[k] += step * v[k];
            }
        }
        st.applyMotions(t + step, x, v, scratch);
    }

    /** Preconditioned CG on A dv = b, with r holding b on entry. */
    private void solve(double bNorm2) {
        final int n3 = r.length;
        final double[] im = s.invMass;
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
                z[k] = im[k / 3] == 0 ? 0 : r[k] / diag[k];
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
                for (int k = 0; k < n3; k++) {
                    dv[k] += alpha * p[k];
                    r[k] -= alpha * ap[k];
                    rr += r[k] * r[k];
                }
                it++;
                if (rr <= stop2) {
                    break;
                }
                double rzNew = 0;
                for (int k = 0; k < n3; k++) {
                    z[k] = im[k / 3] == 0 ? 0 : r[k] / diag[k];
                    rzNew += r[k] * z[k];
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

    /** Spring directions and clamped transverse factors at positions px, and the diagonal of A. */
    private void linearise(double[] px) {
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] kk = s.springK;
        final double[] cc = s.springC;
        final double[] m = s.mass;
        final double hv = h * s.viscousDamping();
        for (int i = 0; i < s.nodeCount; i++) {
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                diag[k] = m[i] + hv;
            }
        }
        for (int i = 0; i < sa.length; i++) {
            int a = 3 * sa[i];
            int b = 3 * sb[i];
            double dx = px[b] - px[a];
            double dy = px[b + 1] - px[a + 1];
            double dz = px[b + 2] - px[a + 2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double inv = len > 0 ? 1 / len : 0;
            su[3 * i] = dx * inv;
            su[3 * i + 1] = dy * inv;
            su[3 * i + 2] = dz * inv;
            sg[i] = len > 0 ? Math.max(0, 1 - s.springL[i] / len) : 0;
            for (int c = 0; c < 3; c++) {
                double uc = su[3 * i + c];
                double d = h * h * kk[i] * (uc * uc + sg[i] * (1 - uc * uc)) + h * cc[i] * uc * uc;
                diag[a + c] += d;
                diag[b + c] += d;
            }
        }
    }

    /** out = S p (stiffness only), for every node. */
    private void applyStiffness(double[] pv, double[] out) {
        java.util.Arrays.fill(out, 0);
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] kk = s.springK;
        for (int i = 0; i < sa.length; i++) {
            int a = 3 * sa[i];
            int b = 3 * sb[i];
            double rx = pv[b] - pv[a];
            double ry = pv[b + 1] - pv[a + 1];
            double rz = pv[b + 2] - pv[a + 2];
            double ux = su[3 * i];
            double uy = su[3 * i + 1];
            double uz = su[3 * i + 2];
            double ur = ux * rx + uy * ry + uz * rz;
            double g = sg[i];
            // K_s r = k (u (u.r) + g (r - u (u.r)))
            double ax = (1 - g) * ur * ux + g * rx;
            double ay = (1 - g) * ur * uy + g * ry;
            double az = (1 - g) * ur * uz + g * rz;
            double k = kk[i];
            out[a] -= k * ax;
            out[a + 1] -= k * ay;
            out[a + 2] -= k * az;
            out[b] += k * ax;
            out[b + 1] += k * ay;
            out[b + 2] += k * az;
        }
    }

    /** out = (M + h C + h^2 S) p on free nodes, 0 on the others. */
    private void multiply(double[] pv, double[] out) {
        products++;
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] kk = s.springK;
        final double[] cc = s.springC;
        final double[] m = s.mass;
        final double[] im = s.invMass;
        final double hv = h * s.viscousDamping();
        final double h2 = h * h;
        for (int i = 0; i < s.nodeCount; i++) {
            double d = im[i] == 0 ? 0 : m[i] + hv;
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                out[k] = d * pv[k];
            }
        }
        for (int i = 0; i < sa.length; i++) {
            int a = 3 * sa[i];
            int b = 3 * sb[i];
            double rx = pv[b] - pv[a];
            double ry = pv[b + 1] - pv[a + 1];
            double rz = pv[b + 2] - pv[a + 2];
            double ux = su[3 * i];
            double uy = su[3 * i + 1];
            double uz = su[3 * i + 2];
            double ur = ux * rx + uy * ry + uz * rz;
            double g = sg[i];
            double kh = h2 * kk[i];
            double axial = kh * (1 - g) * ur + h * cc[i] * ur;
            double trans = kh * g;
            double ax = axial * ux + trans * rx;
            double ay = axial * uy + trans * ry;
            double az = axial * uz + trans * rz;
            out[a] -= ax;
            out[a + 1] -= ay;
            out[a + 2] -= az;
            out[b] += ax;
            out[b + 1] += ay;
            out[b + 2] += az;
        }
        for (int i = 0; i < s.nodeCount; i++) {
            if (im[i] == 0) {
                out[3 * i] = 0;
                out[3 * i + 1] = 0;
                out[3 * i + 2] = 0;
            }
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
        if (f == null || f.length != n3 || su.length != 3 * ns) {
            f = new double[n3];
            xs = new double[n3];
            vs = new double[n3];
            dv = new double[n3];
            r = new double[n3];
            z = new double[n3];
            p = new double[n3];
            ap = new double[n3];
            diag = new double[n3];
            su = new double[3 * ns];
            sg = new double[ns];
        }
    }
}
