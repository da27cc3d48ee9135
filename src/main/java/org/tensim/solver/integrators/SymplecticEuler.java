package org.tensim.solver.integrators;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * Symplectic (semi-implicit) Euler: the velocity first, then the position with
 * the new velocity:
 *
 * <pre>
 *   v &lt;- v + h f(t, x, v) / m
 *   x &lt;- x + h v
 * </pre>
 *
 * Global error O(h); one force evaluation per step. On an undamped spring the
 * step matrix has determinant 1 and trace 2 - (w h)^2: bounded (energy oscillates,
 * no drift) iff w h &lt; 2, i.e. h &lt; 2 sqrt(m/k). In a network the highest
 * frequency rules: h &lt; 2 / w_max.
 */
public final class SymplecticEuler implements Integrator {
    private double[] f;
    private final double[] scratch = new double[6];

    @Override
    public String name() {
        return "symplectic-euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 1;
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
                v[k] += h * w * f[k];
                x[k] += h * v[k]; // the new velocity: this is what makes it symplectic
            }
        }
        s.applyMotions(t + h, x, v, scratch);
    }
}
