package org.tensim.solver.integrators;

import java.util.Arrays;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.SystemState;
import org.tensim.solver.stability.LinearStability;

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
    /** The step on x'' = -x - 2 zeta x' (damping at the predicted velocity); undamped: leapfrog, w h &lt; 2. */
    private static final LinearStability STABILITY = LinearStability.declared(2, (h, zeta, x, v) -> {
        double c = 2 * zeta;
        double a0 = -x - c * v;
        double vh = v + h / 2 * a0;
        double x1 = x + h * vh;
        double a1 = -x1 - c * (v + h * a0);
        return new double[] {x1, vh + h / 2 * a1};
    });

    @Override
    public LinearStability stability() {
        return STABILITY;
    }

    private final NodeLoops.Body kickDrift = this::kickDriftRange;
    private final NodeLoops.Body kick = this::kickRange;
    private double[] f;
    private double[] vp;
    private double[] xEnd;
    private double[] vEnd;
    private double tEnd = Double.NaN;
    private long versionEnd = -1;
    private SystemState owner;
    private double h;
    private final double[] scratch = new double[6];

    @Override
    public String name() {
        return "verlet";
    }

    @Override
    public int order() {
        return 2;
    }

    @Override
    public void step(ForceModel model, double t, double dt) {
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
        h = dt;

        boolean reuse = !s.velocityDependentForces() && t == tEnd && versionEnd == s.parameterVersion()
                && Arrays.equals(x, xEnd) && Arrays.equals(v, vEnd);
        if (!reuse) {
            model.computeForces(t, x, v, f);
        }
        model.nodeLoops().run(s.nodeCount, kickDrift);
        s.applyMotions(t + dt, x, vp, scratch);

        model.computeForces(t + dt, x, vp, f);
        model.nodeLoops().run(s.nodeCount, kick);
        s.applyMotions(t + dt, x, v, scratch);

        System.arraycopy(x, 0, xEnd, 0, n3);
        System.arraycopy(v, 0, vEnd, 0, n3);
        tEnd = t + dt;
        versionEnd = s.parameterVersion();
    }

    /**
     * v_p = v + h a0 (the predicted end velocity), v += h/2 a0, x += h v, for the free
     * nodes of [lo, hi); fixed and driven ones keep x and v (and v_p = v).
     */
    private void kickDriftRange(int lo, int hi) {
        final double[] x = owner.x;
        final double[] v = owner.v;
        final double[] im = owner.invMass;
        final double[] fo = f;
        final double[] vpo = vp;
        final double dt = h;
        final double hh = 0.5 * dt;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                for (int k = 3 * i; k < 3 * i + 3; k++) {
                    vpo[k] = v[k];
                }
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                final double a = w * fo[k];
                vpo[k] = v[k] + dt * a;
                v[k] += hh * a;
                x[k] += dt * v[k];
            }
        }
    }

    /** v += h/2 a1 for the free nodes of [lo, hi). */
    private void kickRange(int lo, int hi) {
        final double[] v = owner.v;
        final double[] im = owner.invMass;
        final double[] fo = f;
        final double hh = 0.5 * h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                v[k] += hh * w * fo[k];
            }
        }
    }
}
