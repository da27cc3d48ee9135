package org.tensim.solver.integrators;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.SystemState;
import org.tensim.solver.stability.LinearStability;

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
    /** The step on x'' = -x - 2 zeta x', and the undamped limit w h = 2 (trace 2 - (w h)^2). */
    private static final LinearStability STABILITY = LinearStability.declared(2, (h, zeta, x, v) -> {
        double v1 = v + h * (-x - 2 * zeta * v);
        return new double[] {x + h * v1, v1};
    });

    @Override
    public LinearStability stability() {
        return STABILITY;
    }

    private final NodeLoops.Body update = this::updateRange;
    private final double[] scratch = new double[6];
    private double[] f;
    private SystemState s;
    private double h;

    @Override
    public String name() {
        return "symplectic-euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public void step(ForceModel model, double t, double dt) {
        SystemState st = model.state();
        if (f == null || f.length != 3 * st.nodeCount) {
            f = new double[3 * st.nodeCount];
        }
        s = st;
        h = dt;
        model.computeForces(t, st.x, st.v, f);
        model.nodeLoops().run(st.nodeCount, update);
        st.applyMotions(t + dt, st.x, st.v, scratch);
        s = null;
    }

    /** v += h w f, then x += h v (the new velocity), for the free nodes of [lo, hi). */
    private void updateRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] fo = f;
        final double dt = h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                continue; // fixed and driven nodes: also no 0 * inf from an infinite force
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                v[k] += dt * w * fo[k];
                x[k] += dt * v[k]; // the new velocity: this is what makes it symplectic
            }
        }
    }
}
