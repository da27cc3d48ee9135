package org.tensim.solver;

import org.tensim.solver.stability.ButcherTableau;
import org.tensim.solver.stability.LinearStability;

/**
 * The paper's integrator: the second-order Runge-Kutta midpoint method applied
 * to the first-order system (x' = v, v' = f(t, x, v) / m).
 *
 * <pre>
 *   a1 = f(t, x, v) / m                                  0   |
 *   x_m = x + h/2 v,      v_m = v + h/2 a1               1/2 | 1/2
 *   a2 = f(t + h/2, x_m, v_m) / m                        ----+----------
 *   x  &lt;- x + h v_m,      v  &lt;- v + h a2                    | 0     1
 * </pre>
 *
 * Global error O(h^2); two force evaluations per step. Stability on an undamped
 * spring: the amplification factor is R(z) = 1 + z + z^2/2 with z = i w h, so
 * |R|^2 = 1 + (w h)^4 / 4 &gt; 1: without damping the amplitude grows slowly at
 * every step size (x1.006 per period at w h = 0.2). Use damping or a small w h.
 *
 * <p>Written out by hand as the readable reference of the paper's method; it is
 * the generic {@code integrators.ExplicitRungeKutta} on {@link #TABLEAU} to the last
 * bit (tested). Kept because the generic loop measured 0.8 % to 4.6 % slower in CPU
 * time per step (4 of 5 alternating rounds, lattice n = 31); JMH
 * ({@code IntegratorStepBenchmark}) could not separate the two on the loaded machine
 * of that day (docs/performance.md). Its two node loops run through
 * {@link ForceModel#nodeLoops()}.
 */
public final class MidpointRK2 implements Integrator {
    /** The midpoint tableau ({@link ButcherTableau#MIDPOINT}). */
    public static final ButcherTableau TABLEAU = ButcherTableau.MIDPOINT;

    private final NodeLoops.Body half = this::halfRange;
    private final NodeLoops.Body full = this::fullRange;
    private final double[] scratch = new double[6];
    private double[] f;
    private double[] xm;
    private double[] vm;
    private SystemState s;
    private double h;

    @Override
    public String name() {
        return "rk2";
    }

    @Override
    public int order() {
        return 2;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 2;
    }

    /** The midpoint tableau (R(z) = 1 + z + z^2/2: undamped limit 0). */
    @Override
    public LinearStability stability() {
        return TABLEAU;
    }

    @Override
    public void step(ForceModel model, double t, double dt) {
        SystemState st = model.state();
        int n3 = 3 * st.nodeCount;
        if (f == null || f.length != n3) {
            f = new double[n3];
            xm = new double[n3];
            vm = new double[n3];
        }
        s = st;
        h = dt;
        final double hh = 0.5 * dt;

        model.computeForces(t, st.x, st.v, f);
        model.nodeLoops().run(st.nodeCount, half);
        st.applyMotions(t + hh, xm, vm, scratch);

        model.computeForces(t + hh, xm, vm, f);
        model.nodeLoops().run(st.nodeCount, full);
        st.applyMotions(t + dt, st.x, st.v, scratch);
        s = null;
    }

    /** x_m = x + h/2 v, v_m = v + h/2 a1 for the nodes [lo, hi). */
    private void halfRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] fo = f;
        final double[] xmo = xm;
        final double[] vmo = vm;
        final double hh = 0.5 * h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            // Fixed and driven nodes (w = 0) are not integrated: testing w also keeps an
            // infinite force on a fixed node from turning its velocity into 0 * inf = NaN.
            final boolean free = w != 0;
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                xmo[k] = free ? x[k] + hh * v[k] : x[k];
                vmo[k] = free ? v[k] + hh * w * fo[k] : v[k];
            }
        }
    }

    /** x += h v_m, v += h a2 for the free nodes of [lo, hi). */
    private void fullRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] fo = f;
        final double[] vmo = vm;
        final double dt = h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                x[k] += dt * vmo[k];
                v[k] += dt * w * fo[k];
            }
        }
    }
}
