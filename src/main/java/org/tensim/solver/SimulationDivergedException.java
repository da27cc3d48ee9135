package org.tensim.solver;

/**
 * Thrown when a step leaves a non-finite position or velocity, or when the
 * energy grows past the simulation's limit. The simulation stops at the step
 * that diverged; whatever listeners wrote so far is theirs to keep (recorders
 * flush on each step). The message names the step, the time, the worst node and,
 * when known, the critical time step estimate.
 */
public final class SimulationDivergedException extends RuntimeException {
    private final long step;
    private final double timeSeconds;
    private final int node;
    private final double criticalStepSeconds;

    public SimulationDivergedException(long step, double timeSeconds, int node, String detail) {
        this(step, timeSeconds, node, detail, Double.NaN);
    }

    /**
     * @param criticalStepSeconds the critical time step estimate for the integrator in use, s (NaN if unknown)
     */
    public SimulationDivergedException(long step, double timeSeconds, int node, String detail,
            double criticalStepSeconds) {
        super("simulation diverged at step " + step + " (t = " + timeSeconds + " s): node " + node + " " + detail);
        this.step = step;
        this.timeSeconds = timeSeconds;
        this.node = node;
        this.criticalStepSeconds = criticalStepSeconds;
    }

    /** The critical time step estimate quoted in the message, s (NaN if none). */
    public double criticalStepSeconds() {
        return criticalStepSeconds;
    }

    /** The 1-based number of the step that diverged. */
    public long step() {
        return step;
    }

    /** Simulated time at the end of the diverged step, s. */
    public double timeSeconds() {
        return timeSeconds;
    }

    /** The first node found with a non-finite value, or the fastest node when the energy grew. */
    public int node() {
        return node;
    }
}
