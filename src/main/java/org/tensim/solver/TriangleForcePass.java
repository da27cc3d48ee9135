package org.tensim.solver;

/**
 * A replacement for {@link ForceModel}'s serial loop over the membrane triangles (for example a
 * multi-threaded pass). It adds the triangles' forces (N) of the state it was built for to
 * {@code f}, public layout (node id i at [3i, 3i+1, 3i+2]). Allocation-free.
 */
public interface TriangleForcePass {
    /**
     * Adds the triangles' forces at positions px (m) to f (N); with velocities pv (m/s) their
     * Kelvin-Voigt damping too, without it (pv null) the elastic part only.
     */
    void addTriangleForces(double[] px, double[] pv, double[] f);

    /**
     * Whether the pass also adds the transverse shear elements' forces ({@link ShearElements}); when
     * not, {@link ForceModel} adds them serially.
     */
    default boolean addsShearForces() {
        return false;
    }
}
