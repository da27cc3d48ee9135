package org.tensim.solver;

/**
 * The paper's integrator: the second-order Runge-Kutta midpoint method applied
 * to the first-order system (x' = v, v' = f(t, x, v) / m).
 *
 * <pre>
 *   a1 = f(t, x, v) / m
 *   x_m = x + h/2 v,      v_m = v + h/2 a1
 *   a2 = f(t + h/2, x_m, v_m) / m
 *   x  <- x + h v_m,      v  <- v + h a2
 * </pre>
 *
 * Global error O(h^2); two force evaluations per step. Stability on an undamped
 * spring: the amplification factor is R(z) = 1 + z + z^2/2 with z = i w h, so
 * |R|^2 = 1 + (w h)^4 / 4 &gt; 1: without damping the amplitude grows slowly at
 * every step size (x1.006 per period at w h = 0.2). Use damping or a small w h.
 */
public final class MidpointRK2 implements Integrator {
    private double[] f;
    private double[] xm;
    private double[] vm;
    private final double[] scratch = new double[6];

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

    /** 0: undamped, RK2 grows at every step size (|R(i w h)| &gt; 1). */
    @Override
    public double undampedStabilityLimit() {
        return 0;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState s = model.state();
        int n3 = 3 * s.nodeCount;
        if (f == null || f.length != n3) {
            f = new double[n3];
            xm = new double[n3];
            vm = new double[n3];
        }
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double hh = 0.5 * h;

        model.computeForces(t, x, v, f);
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            // Fixed and driven nodes (w = 0) are not integrated: testing w also keeps an
            // infinite force on a fixed node from turning its velocity into 0 * inf = NaN.
            final boolean free = w != 0;
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                xm[k] = free ? x[k] + hh * v[k] : x[k];
                vm[k] = free ? v[k] + hh * w * f[k] : v[k];
            }
        }
        s.applyMotions(t + hh, xm, vm, scratch);

        model.computeForces(t + hh, xm, vm, f);
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            if (w == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                x[k] += h * vm[k];
                v[k] += h * w * f[k];
            }
        }
        s.applyMotions(t + h, x, v, scratch);
    }
}
