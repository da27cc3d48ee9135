package org.tensim.solver;

import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * The transverse shear elements' stiffness {@code sum_kl K_kl grad g_k grad g_l^T} ({@link ShearElements},
 * without the geometric term) linearised at given positions, as an {@link ExtraStiffness} for the
 * critical step and as a matrix-free operator for a statics solve. It has its own tangent, so it
 * does not disturb a solver's.
 */
public final class ShearStiffness implements ExtraStiffness {
    private final ShearElements e;

    /** The stiffness of {@code elements} linearised at positions px (m, full layout). */
    public ShearStiffness(ShearElements elements, double[] px) {
        this.e = elements.tangentAt(px);
    }

    /** y += scale K z; offsets as in {@link ShearElements#multiplyAdd(double[], double[], int[], double)}. */
    public void multiplyAdd(double[] z, double[] y, int[] offset, double scale) {
        e.multiplyAdd(z, y, offset, scale);
    }

    /** diag += scale times K's diagonal (full layout). */
    public void addDiagonal(double[] diag, double scale) {
        e.addDiagonal(diag, scale);
    }

    @Override
    public void multiplyAdd(double[] z, double[] y) {
        e.multiplyAdd(z, y, null, 1);
    }

    /**
     * Gershgorin rows: the Frobenius norm of every 3 x 3 node block, added as
     * {@link CriticalTimeStep#gershgorin} adds a spring's stiffness (as {@link TriangleTangent} does).
     */
    @Override
    public void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
        for (int el = 0; el < e.count(); el++) {
            for (int a = 0; a < 6; a++) {
                final int na = e.node(el, a);
                if (!free[na]) {
                    continue;
                }
                for (int b = 0; b < 6; b++) {
                    final int nb = e.node(el, b);
                    double sq = 0;
                    for (int d = 0; d < 3; d++) {
                        for (int f = 0; f < 3; f++) {
                            final double v = e.blockEntry(el, a, d, b, f);
                            sq += v * v;
                        }
                    }
                    final double norm = Math.sqrt(sq);
                    if (form == CriticalTimeStep.Form.ROWS) {
                        row[na] += 0.5 * norm;
                    } else if (nb == na) {
                        row[na] += norm / mass[na];
                    } else if (free[nb]) {
                        row[na] += norm / Math.sqrt(mass[na] * mass[nb]);
                    }
                }
            }
        }
    }
}
