package org.tensim.solver.stability;

/**
 * Stiffness beyond the springs that a critical-step estimate must count (for example membrane
 * triangles), linearised at the rest positions: symmetric, positive semi-definite, on the full
 * layout (3 per node).
 */
public interface ExtraStiffness {
    /** No extra stiffness. */
    ExtraStiffness NONE = new ExtraStiffness() {
        @Override
        public void multiplyAdd(double[] z, double[] y) {
        }

        @Override
        public void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
        }
    };

    /** y += K z (N/m times m), full layout. */
    void multiplyAdd(double[] z, double[] y);

    /**
     * Adds this stiffness to the per-node Gershgorin sums {@code row} in the way
     * {@link CriticalTimeStep#gershgorin} adds a spring of stiffness k, in the given form.
     */
    void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row);
}
