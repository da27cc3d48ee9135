package org.tensim.solver.integrators;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * The classic fourth-order Runge-Kutta method on (x' = v, v' = f / m):
 *
 * <pre>
 *   stage 1: (x, v)                              -&gt; slopes (v,  a1)
 *   stage 2: (x + h/2 v,  v + h/2 a1) at t + h/2 -&gt; slopes (v2, a2)
 *   stage 3: (x + h/2 v2, v + h/2 a2) at t + h/2 -&gt; slopes (v3, a3)
 *   stage 4: (x + h v3,   v + h a3)   at t + h   -&gt; slopes (v4, a4)
 *   x &lt;- x + h/6 (v + 2 v2 + 2 v3 + v4),  v &lt;- v + h/6 (a1 + 2 a2 + 2 a3 + a4)
 * </pre>
 *
 * Global error O(h^4); four force evaluations per step. R(z) = 1 + z + z^2/2 +
 * z^3/6 + z^4/24: on an undamped spring |R(i w h)| &lt;= 1 iff w h &lt;= 2 sqrt(2)
 * (about 2.83), where it loses a little energy per step ((w h)^6 / 72 to first order).
 */
public final class RK4 implements Integrator {
    /** 2 sqrt(2): the imaginary-axis limit of classic RK4. */
    public static final double UNDAMPED_LIMIT = 2 * Math.sqrt(2);

    private double[] f;
    private double[] xs;
    private double[] vs;
    private double[] sumV;
    private double[] sumA;
    private final double[] scratch = new double[6];

    @Override
    public String name() {
        return "rk4";
    }

    @Override
    public int order() {
        return 4;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 4;
    }

    @Override
    public double undampedStabilityLimit() {
        return UNDAMPED_LIMIT;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState s = model.state();
        int n3 = 3 * s.nodeCount;
        if (f == null || f.length != n3) {
            f = new double[n3];
            xs = new double[n3];
            vs = new double[n3];
            sumV = new double[n3];
            sumA = new double[n3];
        }
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final int n = s.nodeCount;
        final double hh = 0.5 * h;

        model.computeForces(t, x, v, f);
        for (int i = 0; i < n; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                sumV[k] = v[k];
                sumA[k] = w * f[k];
                xs[k] = x[k] + hh * v[k];
                vs[k] = v[k] + hh * w * f[k];
            }
        }
        s.applyMotions(t + hh, xs, vs, scratch);

        model.computeForces(t + hh, xs, vs, f);
        for (int i = 0; i < n; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                sumV[k] += 2 * vs[k];
                sumA[k] += 2 * w * f[k];
                xs[k] = x[k] + hh * vs[k]; // reads stage 2's velocity before it is replaced
                vs[k] = v[k] + hh * w * f[k];
            }
        }
        s.applyMotions(t + hh, xs, vs, scratch);

        model.computeForces(t + hh, xs, vs, f);
        for (int i = 0; i < n; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                sumV[k] += 2 * vs[k];
                sumA[k] += 2 * w * f[k];
                xs[k] = x[k] + h * vs[k];
                vs[k] = v[k] + h * w * f[k];
            }
        }
        s.applyMotions(t + h, xs, vs, scratch);

        model.computeForces(t + h, xs, vs, f);
        final double h6 = h / 6;
        for (int i = 0; i < n; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                x[k] += h6 * (sumV[k] + vs[k]);
                v[k] += h6 * (sumA[k] + w * f[k]);
            }
        }
        s.applyMotions(t + h, x, v, scratch);
    }
}
