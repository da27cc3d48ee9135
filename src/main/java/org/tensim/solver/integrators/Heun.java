package org.tensim.solver.integrators;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * Heun's second-order Runge-Kutta method (explicit trapezoidal rule): an Euler
 * predictor to the end of the step, then the average of the two slopes.
 *
 * <pre>
 *   a1 = f(t, x, v) / m
 *   x_p = x + h v,            v_p = v + h a1
 *   a2 = f(t + h, x_p, v_p) / m
 *   x &lt;- x + h/2 (v + v_p),   v &lt;- v + h/2 (a1 + a2)
 * </pre>
 *
 * Global error O(h^2); two force evaluations per step. On linear problems its
 * amplification factor is that of every two-stage RK2, R(z) = 1 + z + z^2/2, so
 * like the paper's midpoint rule it grows slowly on an undamped spring at every
 * step size (|R(i w h)|^2 = 1 + (w h)^4 / 4) and needs damping or a small w h.
 */
public final class Heun implements Integrator {
    private double[] f1;
    private double[] f2;
    private double[] xp;
    private double[] vp;
    private final double[] scratch = new double[6];

    @Override
    public String name() {
        return "heun";
    }

    @Override
    public int order() {
        return 2;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 2;
    }

    /** 0: undamped, every two-stage RK2 grows at every step size. */
    @Override
    public double undampedStabilityLimit() {
        return 0;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState s = model.state();
        int n3 = 3 * s.nodeCount;
        if (f1 == null || f1.length != n3) {
            f1 = new double[n3];
            f2 = new double[n3];
            xp = new double[n3];
            vp = new double[n3];
        }
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double hh = 0.5 * h;

        model.computeForces(t, x, v, f1);
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                xp[k] = x[k] + h * v[k];
                vp[k] = v[k] + h * w * f1[k];
            }
        }
        s.applyMotions(t + h, xp, vp, scratch);

        model.computeForces(t + h, xp, vp, f2);
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                x[k] += hh * (v[k] + vp[k]);
                v[k] += hh * w * (f1[k] + f2[k]);
            }
        }
        s.applyMotions(t + h, x, v, scratch);
    }
}
