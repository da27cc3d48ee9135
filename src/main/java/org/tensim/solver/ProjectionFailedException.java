package org.tensim.solver;

/**
 * Thrown (with {@link Severity#ERROR}) when the rigid-link projection stops at its
 * iteration cap with a relative length error above its tolerance, e.g. because the
 * links contradict each other. The message names the step, the worst link and the
 * residual.
 */
public final class ProjectionFailedException extends RuntimeException {
    private final long step;
    private final int link;
    private final double residual;

    public ProjectionFailedException(long step, int link, double residual, String message) {
        super(message);
        this.step = step;
        this.link = link;
        this.residual = residual;
    }

    /** The 1-based step whose projection failed. */
    public long step() {
        return step;
    }

    /** Index of the link with the largest relative length error. */
    public int link() {
        return link;
    }

    /** Largest relative length error |l - L| / L left after the last sweep. */
    public double residual() {
        return residual;
    }
}
