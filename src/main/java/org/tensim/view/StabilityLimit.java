package org.tensim.view;

import org.tensim.solver.SystemState;

/**
 * An estimate of the largest stable time step of an explicit integrator on a
 * spring network: {@code h_crit = 2 / w_max} with the Gershgorin bound
 * {@code w_max^2 <= max_i 2 sum_j k_ij / m_i} over free nodes (docs: PHYSICS.md).
 * The bound over-estimates w_max, so the estimate errs on the safe side. The
 * paper's RK2 gains a little energy per period at any step without damping; the
 * estimate says where it stops being usable at all.
 */
public final class StabilityLimit {
    private StabilityLimit() {
    }

    /** Critical time step estimate, s; infinite when no spring acts on a free node. */
    public static double criticalTimeStep(SystemState s) {
        double[] sumK = new double[s.nodeCount];
        for (int i = 0; i < s.springCount(); i++) {
            sumK[s.springA[i]] += s.springK[i];
            sumK[s.springB[i]] += s.springK[i];
        }
        double w2 = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            if (s.invMass[i] != 0) {
                w2 = Math.max(w2, 2 * sumK[i] * s.invMass[i]);
            }
        }
        return w2 == 0 ? Double.POSITIVE_INFINITY : 2 / Math.sqrt(w2);
    }
}
