package org.tensim.calibration;

import java.util.List;
import org.tensim.sweep.Measure;
import org.tensim.sweep.PointResult;

/**
 * One thing a calibration fits: it may add a {@link Measure} to every run, and turns a
 * run's summary fields into dimensionless residuals r (a measured error over its
 * tolerance). The calibration minimises the sum over targets of weight x sum of r^2.
 */
public interface Target {
    /** A short description for reports, e.g. {@code dome_excursion_mm = 18 +/- 1}. */
    String describe();

    /** Weight of this target's squared residuals (> 0). */
    double weight();

    /** The measure this target adds to each run, or null when it reads the scene's own summary fields. */
    Measure measure();

    /** Names of the residuals, in order (for the residuals report). */
    List<String> residualNames();

    /**
     * Residuals of a finished run, dimensionless; NaN entries when the run did not produce what
     * the target needs (it diverged before, or the field is missing): the calibration then gives
     * the candidate its penalty.
     */
    double[] residuals(PointResult r);

    /** Summary fields this target reads (written to the evaluations file). */
    List<String> fields();
}
