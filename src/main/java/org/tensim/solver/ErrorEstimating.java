package org.tensim.solver;

/**
 * An {@link Integrator} that knows how accurate its last step was, so that an
 * interface (the GUI's status bar) or a report can show it next to the speed.
 *
 * <p>The estimate is dimensionless and relative: the size of the error left in
 * the last step's solution over the size of what the step changed, e.g. the
 * relative residual ||r|| / ||b|| left by the iterative solve of an implicit step,
 * or a local truncation error estimate ||x_h - x_ref|| / ||x_h - x_0|| from a
 * step pair. 0.01 reads as "about 1 % off". It is what the method can tell about
 * itself at run time, not a measured error against a reference (the real-time
 * study of the diaphragm measures that).
 */
public interface ErrorEstimating {
    /**
     * Relative error estimate of the last step (dimensionless, >= 0), or
     * {@link Double#NaN} before the first step.
     */
    double errorEstimate();
}
