package org.tensim.calibration;

import java.util.List;
import org.tensim.sweep.Measure;
import org.tensim.sweep.PointResult;

/**
 * A summary figure with a tolerance, e.g. a dome excursion of 18 +/- 1 mm: the residual is
 * (value - target) / tolerance.
 *
 * @param field     summary field, e.g. {@code dome_excursion_mm}
 * @param value     target value, in the field's unit
 * @param tolerance tolerance, same unit (> 0): the error that counts as one
 * @param weight    weight of the squared residual (> 0)
 */
public record SummaryTarget(String field, double value, double tolerance, double weight) implements Target {
    @Override
    public String describe() {
        return field + " = " + value + " +/- " + tolerance;
    }

    @Override
    public Measure measure() {
        return null;
    }

    @Override
    public List<String> residualNames() {
        return List.of(field);
    }

    @Override
    public double[] residuals(PointResult r) {
        return new double[] {(r.field(field) - value) / tolerance};
    }

    @Override
    public List<String> fields() {
        return List.of(field);
    }
}
