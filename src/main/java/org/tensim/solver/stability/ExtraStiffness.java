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

    /** The sum of two stiffnesses (either may be {@link #NONE}). */
    static ExtraStiffness sum(ExtraStiffness a, ExtraStiffness b) {
        if (a == NONE) {
            return b;
        }
        if (b == NONE) {
            return a;
        }
        return new ExtraStiffness() {
            @Override
            public void multiplyAdd(double[] z, double[] y) {
                a.multiplyAdd(z, y);
                b.multiplyAdd(z, y);
            }

            @Override
            public void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
                a.addGershgorinRows(mass, free, form, row);
                b.addGershgorinRows(mass, free, form, row);
            }
        };
    }

    /** y += K z (N/m times m), full layout. */
    void multiplyAdd(double[] z, double[] y);

    /**
     * Adds this stiffness to the per-node Gershgorin sums {@code row} in the way
     * {@link CriticalTimeStep#gershgorin} adds a spring of stiffness k, in the given form.
     */
    void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row);
}
