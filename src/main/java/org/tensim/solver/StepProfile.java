package org.tensim.solver;

/**
 * Wall time spent in each {@link Stage}, accumulated over steps, in nanoseconds.
 * Written by the simulation thread only.
 */
public final class StepProfile {
    private final long[] totalNanos = new long[Stage.values().length];
    private long steps;

    void record(Stage stage, long nanos) {
        totalNanos[stage.ordinal()] += nanos;
    }

    void countStep() {
        steps++;
    }

    /** Steps recorded. */
    public long steps() {
        return steps;
    }

    /** Total time in a stage, ns. */
    public long totalNanos(Stage stage) {
        return totalNanos[stage.ordinal()];
    }

    /** Mean time per step in a stage, ms (0 before the first step). */
    public double meanMillis(Stage stage) {
        return steps == 0 ? 0 : totalNanos(stage) / 1e6 / steps;
    }

    /** Clears all counters. */
    public void reset() {
        java.util.Arrays.fill(totalNanos, 0);
        steps = 0;
    }
}
