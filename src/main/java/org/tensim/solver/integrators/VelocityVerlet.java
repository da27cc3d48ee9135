package org.tensim.solver.integrators;

import java.util.Arrays;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;

/**
 * Velocity Verlet (kick, drift, kick):
 *
 * <pre>
 *   a0 = f(t, x, v) / m                         (reused from the previous step when valid)
 *   v_half = v + h/2 a0,     x &lt;- x + h v_half
 *   a1 = f(t + h, x, v + h a0) / m
 *   v &lt;- v_half + h/2 a1
 * </pre>
 *
 * Global error O(h^2). On an undamped spring it is the leapfrog scheme: bounded
 * iff w h &lt; 2, energy oscillating without drift.
 *
 * <p>Velocity-dependent forces (damping) are evaluated at the end of the step
 * with the predicted velocity {@code v + h a0}, whose error is O(h^2), which keeps
 * the method second order with damping at no extra force evaluation (evaluating
 * them at {@code v_half} instead would drop it to first order).
 *
 * <p>Cost: one force evaluation per step when the force of the previous step's
 * end can be reused exactly: no force depends on the velocity (no damping) and
 * nothing touched the state since (same time, positions, velocities and
 * parameters). Two otherwise: with damping (the end-of-step force was evaluated
 * with the predicted velocity; reusing it keeps the order but was measured to
 * shrink the stable step to w h = 0.83 at zeta = 0.5, against 2.0 with a fresh
 * force), and on every step of a scene with rigid links, whose projection moves
 * nodes after the step.
 */
public final class VelocityVerlet implements Integrator {
    private double[] f;
    private double[] vp;
    private double[] xEnd;
    private double[] vEnd;
    private double tEnd = Double.NaN;
    private long versionEnd = -1;
    private SystemState owner;
    private final double[] scratch = new double[6];

    @Override
    public String name() {
        return "verlet";
    }

    @Override
    public int order() {
        return 2;
    }

    /** 1 when the end-of-step force is reused (undamped, untouched state); 2 otherwise. */
    @Override
    public int forceEvaluationsPerStep() {
        return 1;
    }

    @Override
    public void step(ForceModel model, double t, double h) {
        SystemState s = model.state();
        int n3 = 3 * s.nodeCount;
        if (f == null || f.length != n3 || owner != s) {
            f = new double[n3];
            vp = new double[n3];
            xEnd = new double[n3];
            vEnd = new double[n3];
            owner = s;
            tEnd = Double.NaN;
        }
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double hh = 0.5 * h;

        boolean reuse = !s.velocityDependentForces() && t == tEnd && versionEnd == s.parameterVersion() && Arrays.equals(x, xEnd)
                && Arrays.equals(v, vEnd);
        if (!reuse) {
            model.computeForces(t, x, v, f);
        }
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                final double a = w * f[k];
                vp[k] = v[k] + h * a;
                v[k] += hh * a;
                x[k] += h * v[k];
            }
        }
        s.applyMotions(t + h, x, vp, scratch);

        model.computeForces(t + h, x, vp, f);
        for (int i = 0; i < s.nodeCount; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                v[k] += hh * w * f[k];
            }
        }
        s.applyMotions(t + h, x, v, scratch);

        System.arraycopy(x, 0, xEnd, 0, n3);
        System.arraycopy(v, 0, vEnd, 0, n3);
        tEnd = t + h;
        versionEnd = s.parameterVersion();
    }
}
