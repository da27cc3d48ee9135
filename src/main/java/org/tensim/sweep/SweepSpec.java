package org.tensim.sweep;

import java.util.List;
import java.util.Map;

/**
 * A parameter sweep, as read from its JSON file by {@link SpecReader} (which
 * validates everything before a run starts):
 *
 * <pre>
 * {
 *   "scene": "diaphragm",
 *   "mesh": { "rings": 10 },                  // or { "file": "x.obj", "units": "mm", "thicknessMm": 2.5 }
 *   "muscleLoad": "pressure",                 // muscleActionPa in Pa of pressure; absent: "fibres", the default
 *   "parameters": {
 *     "muscleActionPa":     { "min": 1000, "max": 4000, "steps": 4 },
 *     "ribAmplitudeFactor": { "values": [0.5, 1, 1.5] }
 *   },
 *   "sampling": { "method": "grid" },         // or { "method": "lhs", "points": 16, "seed": 1 }
 *   "fixed":    { "tissueDampingRatio": 0.9 },
 *   "solver":   { "integrator": "rk2", "dtS": 0, "seconds": 1.5 },
 *   "outputs":  [ "dome_excursion_mm", "ap_extent_change_mm" ]
 * }
 * </pre>
 *
 * Parameter names are the scene's tunable parameters, as in the GUI and its presets
 * ({@code ./tensim gui}, docs/gui.md), with their units in their names and their valid
 * ranges from there. {@code muscleLoad} (diaphragm only) is the muscle-load model as
 * {@code tensim diaphragm --muscle-load}: {@code fibres} when absent (the default, whose
 * {@code muscleActionPa} is an active fibre stress, 19 kPa by default), {@code pressure} or
 * {@code paper-nodes} (a pressure, 2.6 kPa by default).
 *
 * @param setup      what every point shares: scene, mesh, solver, fixed values, measures
 * @param parameters the swept parameters, in column order
 * @param sampling   how points are placed
 * @param outputs    summary fields written to the CSV and charted, in order
 */
public record SweepSpec(RunSetup setup, List<Range> parameters, Sampling sampling, List<String> outputs) {
    public SweepSpec {
        parameters = List.copyOf(parameters);
        outputs = List.copyOf(outputs);
    }

    /** Names of the swept parameters, in column order. */
    public List<String> parameterNames() {
        return parameters.stream().map(Range::name).toList();
    }

    /**
     * One swept parameter: either an explicit list of values (grid only), or a closed
     * interval [min, max] cut into {@code steps} equally spaced grid values, or sampled
     * by the Latin hypercube.
     *
     * @param name   parameter key, e.g. {@code muscleActionPa}
     * @param min    lower bound, in the parameter's unit
     * @param max    upper bound (>= min; equal only with one step)
     * @param steps  grid values between min and max inclusive (>= 1); ignored by the Latin hypercube
     * @param values explicit grid values, or null
     */
    public record Range(String name, double min, double max, int steps, double[] values) {
        /** The grid values of this range, in order. */
        public double[] gridValues() {
            if (values != null) {
                return values.clone();
            }
            double[] v = new double[steps];
            for (int i = 0; i < steps; i++) {
                v[i] = steps == 1 ? min : min + (max - min) * i / (steps - 1);
            }
            if (steps > 1) {
                v[steps - 1] = max; // exact end point whatever the rounding
            }
            return v;
        }
    }

    /**
     * How points are placed.
     *
     * @param latinHypercube false: full grid (the Cartesian product of every range's values);
     *                       true: a Latin hypercube of {@code points} points
     * @param points         number of Latin-hypercube points
     * @param seed           seed of the Latin hypercube (same seed, same points)
     */
    public record Sampling(boolean latinHypercube, int points, long seed) {
        public static Sampling grid() {
            return new Sampling(false, 0, 0);
        }
    }

    /** The fixed values as a map (for messages and presets). */
    public Map<String, Double> fixed() {
        return setup.fixed();
    }
}
