package org.tensim.solver;

/**
 * The two loops of {@link RigidLinkProjection}, replaceable (for example by sweeps
 * over link colours in parallel). A sweep applies the mass-weighted correction of
 * every link once, Gauss-Seidel; the order of the links within a sweep is the
 * implementation's. Allocation-free.
 */
public interface LinkSweeps {
    /** One Gauss-Seidel sweep over all links of s, on positions x (m), in place. */
    void sweep(SystemState s, double[] x);

    /**
     * Largest relative length error |l - L| / L over all links of s at positions x
     * (NaN when a length is not finite); {@link #worstLink()} then names that link
     * (its authored index, the smallest among equals).
     */
    double measure(SystemState s, double[] x);

    /** Authored index of the link with the largest error at the last measure (-1 if none). */
    int worstLink();
}
