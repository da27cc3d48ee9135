package org.tensim.calibration;

import java.util.List;
import org.tensim.sweep.RunSetup;

/**
 * A calibration, as read by {@link CalibrationReader}:
 *
 * <pre>
 * {
 *   "scene": "diaphragm", "mesh": { "rings": 8 },
 *   "muscleLoad": "pressure",     // absent: "fibres", the default (muscleActionPa an active fibre stress)
 *   "solver": { "integrator": "implicit-euler-cg1e-3", "dtS": 0.01, "seconds": 1.4 },
 *   "fixed": { "tissueDampingRatio": 0.9 },
 *   "fit": { "muscleActionPa": { "min": 1000, "max": 5000, "start": 2000 }, ... },
 *   "optimizer": { "population": 8, "generations": 40, "sigma": 0.3, "seed": 1 },
 *   "targets": [
 *     { "type": "summary", "field": "dome_excursion_mm", "value": 18, "tolerance": 1, "weight": 1 },
 *     { "type": "landmarks", "file": "landmarks.csv", "units": "mm", "toleranceMm": 1 },
 *     { "type": "surface", "file": "inspiration.obj", "units": "mm", "timeS": 1.33, "toleranceMm": 1 }
 *   ]
 * }
 * </pre>
 *
 * @param setup       scene, mesh, muscle load, solver and fixed values, as a sweep's ({@link
 *                    org.tensim.sweep.SweepSpec}: no muscleLoad means fibres; the targets' measures added)
 * @param free        the parameters fitted, with their bounds and start
 * @param optimizer   CMA-ES settings
 * @param targets     what is fitted
 */
public record CalibrationSpec(RunSetup setup, List<Free> free, Optimizer optimizer, List<Target> targets) {
    public CalibrationSpec {
        free = List.copyOf(free);
        targets = List.copyOf(targets);
    }

    /**
     * A fitted parameter. The optimiser works on u = (value - min) / (max - min) in [0, 1].
     *
     * @param name  parameter key (the GUI's)
     * @param min   lower bound, in the parameter's unit
     * @param max   upper bound (> min)
     * @param start first guess, within the bounds
     * @param lowest  the smallest value the parameter takes at all (its own range), at most min
     * @param highest the largest value the parameter takes at all, at least max
     */
    public record Free(String name, double min, double max, double start, double lowest, double highest) {
        /** A fitted parameter whose own range is unbounded (or not known). */
        public Free(String name, double min, double max, double start) {
            this(name, min, max, start, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
        }

        public double value(double u) {
            return min + u * (max - min);
        }

        public double fraction(double value) {
            return (value - min) / (max - min);
        }
    }

    /**
     * CMA-ES settings (Hansen's covariance matrix adaptation evolution strategy, Hipparchus's
     * {@code CMAESOptimizer}).
     *
     * @param population  candidates per generation (lambda; Hansen's default is 4 + 3 ln d)
     * @param generations most generations
     * @param sigma       initial step, as a fraction of each parameter's range
     * @param seed        seed of the strategy's random numbers (same seed, same run)
     * @param stopFitness stop once a candidate scores below this (0: never)
     * @param tolerance   stop once the best point moves less than this fraction of the ranges between two
     *                    improvements
     */
    public record Optimizer(int population, int generations, double sigma, long seed, double stopFitness,
            double tolerance) {
    }

    /** Names of the fitted parameters, in order. */
    public List<String> names() {
        return free.stream().map(Free::name).toList();
    }
}
