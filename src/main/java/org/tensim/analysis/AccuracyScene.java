package org.tensim.analysis;

import java.util.function.Supplier;
import org.tensim.model.Check;
import org.tensim.model.Topology;

/**
 * A scene of the accuracy study: how to build it, how long to run it, the ladder
 * of time steps, and an exact solution when one is known.
 *
 * @param name         registry name, e.g. {@code spring}
 * @param description  one line for reports
 * @param topology     builds a fresh topology (started at rest unless its builder says otherwise)
 * @param endTimeS     simulated time at which errors are measured, s
 * @param largestDtS   the first (largest) step of the ladder, s
 * @param rungs        steps of the ladder, each half the previous one (>= 2)
 * @param exact        exact positions at the end time, or null
 */
public record AccuracyScene(String name, String description, Supplier<Topology> topology, double endTimeS,
        double largestDtS, int rungs, ExactSolution exact) {
    /** Exact node positions of a scene at a time. */
    @FunctionalInterface
    public interface ExactSolution {
        /** Writes the positions (m, 3 per node) at time t (s) into out. */
        void positions(double t, double[] out);
    }

    public AccuracyScene {
        Check.positive(name + " end time", "s", endTimeS);
        Check.positive(name + " largest time step", "s", largestDtS);
        Check.atLeast(name + " ladder rungs", rungs, 2);
    }

    /** The time steps of the ladder, largest first, s. */
    public double[] ladder() {
        double[] dt = new double[rungs];
        for (int i = 0; i < rungs; i++) {
            dt[i] = largestDtS / (1L << i);
        }
        return dt;
    }

    /** The same scene with another ladder. */
    public AccuracyScene withLadder(double largestDt, int n) {
        return new AccuracyScene(name, description, topology, endTimeS, largestDt, n, exact);
    }
}
