package org.tensim.solver.integrators;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * Forward (explicit) Euler on the first-order system (x' = v, v' = f / m):
 *
 * <pre>
 *   a = f(t, x, v) / m
 *   x &lt;- x + h v,      v &lt;- v + h a
 * </pre>
 *
 * Global error O(h); one force evaluation per step. Amplification factor
 * R(z) = 1 + z: on an undamped spring (z = i w h) |R| = sqrt(1 + (w h)^2) &gt; 1, so
 * the amplitude grows at every step size (x exp(pi w h) per period for small w h).
 * Only damping (Re z &lt; 0) brings it inside the unit disc. A baseline, not a method
 * to simulate with.
 */
public final class ExplicitEuler implements Integrator {
    private double[] f;
    private final double[] scratch = new double[6];

    @Override
    public String name() {
        return "euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 1;
    }

    /** 0: undamped, forward Euler grows at every step size. */
    @Override
    public double undampedStabilityLimit() {
        return 0;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState s = model.state();
        if (f == null || f.length != 3 * s.nodeCount) {
            f = new double[3 * s.nodeCount];
        }
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        model.computeForces(t, x, v, f);
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                x[k] += h * v[k]; // uses the old velocity: that is what makes it explicit
                v[k] += h * w * f[k];
            }
        }
        s.applyMotions(t + h, x, v, scratch);
    }
}
