package org.tensim.experiment.diaphragm;

import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.stability.ForcePowerIteration;

/**
 * The whole model's highest angular frequency at its current configuration, measured by
 * {@link ForcePowerIteration} on every force the simulation computes, the terms a scene adds (the organs' couplings)
 * included. The scene's recommended explicit step comes from a Gershgorin bound on its own network, which does not
 * count those terms; this figure, beside it in the summary, says whether they raise the frequency the step is set by.
 */
final class ModelFrequency {
    /** The largest node move of a difference, m: small against millimetre elements, large against rounding. */
    static final double DISPLACEMENT_M = 1e-7;
    static final int MAX_ITERATIONS = 300;
    static final double TOLERANCE = 1e-6;

    private ModelFrequency() {
    }

    /**
     * Measures with the velocities held at zero (damping adds nothing) at time {@code t}, s, and returns
     * {@code {"omega_rad_s", "iterations", "converged", "seconds"}} for the summary.
     */
    static Map<String, Object> measure(Simulation sim, double t) {
        long t0 = System.nanoTime();
        SystemState s = sim.state();
        double[] zero = new double[s.x.length];
        double[] x = s.x.clone();
        ForcePowerIteration.Estimate e = ForcePowerIteration.estimate(
                (px, f) -> sim.forces().computeForces(t, px, zero, f), x, s.invMass, DISPLACEMENT_M, MAX_ITERATIONS,
                TOLERANCE, 12345);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("omega_rad_s", Math.round(e.omegaMax() * 10) / 10.0);
        m.put("iterations", e.iterations());
        m.put("converged", e.converged());
        m.put("seconds", Math.round((System.nanoTime() - t0) * 1e-6) / 1e3);
        return m;
    }
}
