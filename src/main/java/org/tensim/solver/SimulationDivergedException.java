package org.tensim.solver;

/**
 * Thrown when a step leaves a non-finite position or velocity. The simulation
 * stops at the step that diverged; whatever listeners wrote so far is theirs to
 * keep (recorders flush on each step).
 */
public final class SimulationDivergedException extends RuntimeException {
    private final long step;
    private final double timeSeconds;
    private final int node;

    public SimulationDivergedException(long step, double timeSeconds, int node, String detail) {
        super("simulation diverged at step " + step + " (t = " + timeSeconds + " s): node " + node + " " + detail);
        this.step = step;
        this.timeSeconds = timeSeconds;
        this.node = node;
    }

    /** The 1-based number of the step that diverged. */
    public long step() {
        return step;
    }

    /** Simulated time at the end of the diverged step, s. */
    public double timeSeconds() {
        return timeSeconds;
    }

    /** The first node found with a non-finite value. */
    public int node() {
        return node;
    }
}
