package org.tensim.tuning;

import org.tensim.solver.ErrorEstimating;
import org.tensim.solver.Integrator;

/**
 * The error estimate an integrator gives of its own last step
 * ({@link ErrorEstimating}), for the status bar and the {@code --run-for} summary.
 * Integrators without one read NaN: nothing is shown rather than a guess.
 */
public final class ErrorReadout {
    private ErrorReadout() {
    }

    /** The integrator's relative error estimate of its last step, or NaN when it has none. */
    public static double of(Integrator i) {
        return i instanceof ErrorEstimating e ? e.errorEstimate() : Double.NaN;
    }

    /** The larger of two estimates, NaN (none) counting as absent. */
    public static double worse(double a, double b) {
        if (Double.isNaN(a)) {
            return b;
        }
        return Double.isNaN(b) ? a : Math.max(a, b);
    }
}
