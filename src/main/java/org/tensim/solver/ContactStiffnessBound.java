package org.tensim.solver;

import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * The contacts' stiffness for a critical-step estimate ({@link ContactForces#worstCaseStiffness()}): every pair
 * taken as in contact, with any normal, i.e. {@code k I} on its node, which bounds {@code k n n^T} (|n| = 1) from
 * above; counted in the Gershgorin sums as a spring of stiffness k (N/m) to a fixed point. Reads the pairs' arrays
 * (shared, never written).
 */
final class ContactStiffnessBound implements ExtraStiffness {
    private final int[] node3; // per pair: 3 x node id
    private final double[] stiffness; // per pair: k, N/m

    ContactStiffnessBound(int[] node3, double[] stiffness) {
        this.node3 = node3;
        this.stiffness = stiffness;
    }

    @Override
    public void multiplyAdd(double[] z, double[] y) {
        for (int e = 0; e < node3.length; e++) {
            for (int d = 0; d < 3; d++) {
                y[node3[e] + d] += stiffness[e] * z[node3[e] + d];
            }
        }
    }

    @Override
    public void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
        for (int e = 0; e < node3.length; e++) {
            final int i = node3[e] / 3;
            if (free[i]) {
                row[i] += form == CriticalTimeStep.Form.ROWS ? stiffness[e] : stiffness[e] / mass[i];
            }
        }
    }
}
