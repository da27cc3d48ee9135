package org.tensim.analysis.lungs;

/**
 * The time course of a breath: each phase's share of the end-inhale displacement. With displacements
 * {@code d_i(p)} of the points from end-exhale to phase p and {@code D_i} to end-inhale, the share of phase p is the
 * least-squares factor that best maps the end-inhale field onto the phase's,
 * <pre>
 *   a_p = sum_i d_i(p) . D_i / sum_i |D_i|^2,
 * </pre>
 * 0 at end-exhale and 1 at end-inhale; exactly the factor when the field keeps its shape ({@code d_i(p) = a D_i}).
 * Over all points and all three axes, it is not thrown by the 2.5 mm slices' rounding of small displacements as
 * point-by-point ratios would be.
 */
public final class PhaseShares {
    private PhaseShares() {
    }

    /**
     * The share of each phase: {@code positions[p]} the points at phase p (m, {@code 3 i + a}), {@code exhale} and
     * {@code inhale} the indices of end-exhale and end-inhale among them.
     *
     * @throws IllegalArgumentException when the end-inhale field is zero or the phases' sizes differ
     */
    public static double[] of(double[][] positions, int exhale, int inhale) {
        double[] x0 = positions[exhale];
        double[] x1 = positions[inhale];
        double den = 0;
        for (int k = 0; k < x0.length; k++) {
            double dd = x1[k] - x0[k];
            den += dd * dd;
        }
        if (!(den > 0)) {
            throw new IllegalArgumentException("the points do not move from end-exhale to end-inhale: no share of it"
                    + " can be taken");
        }
        double[] share = new double[positions.length];
        for (int p = 0; p < positions.length; p++) {
            if (positions[p].length != x0.length) {
                throw new IllegalArgumentException("phase " + p + " has " + positions[p].length / 3 + " points, end-"
                        + "exhale " + x0.length / 3);
            }
            double num = 0;
            for (int k = 0; k < x0.length; k++) {
                num += (positions[p][k] - x0[k]) * (x1[k] - x0[k]);
            }
            share[p] = num / den;
        }
        return share;
    }
}
