package org.tensim.solver;

/**
 * A replacement for {@link ForceModel}'s built-in spring loops (for example a
 * multi-threaded pass over a cache-friendly ordering). It adds the spring forces
 * (N), axial damping included, of the state it was built for to {@code f}, which
 * already holds gravity, viscous damping and the external forces. Arrays use the
 * public layout: node id i at [3i, 3i+1, 3i+2]. Allocation-free.
 */
public interface SpringForcePass {
    /** Adds the spring forces at positions px (m) and velocities pv (m/s) to f (N). */
    void addSpringForces(double[] px, double[] pv, double[] f);
}
