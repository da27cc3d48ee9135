package org.tensim.solver;

/**
 * A force a scene adds to the built-in ones of {@link ForceModel}: a coupling with another body (a surface the
 * nodes slide on, carried by other nodes), a contact on a surface mapped from the nodes, any load that depends on
 * positions. The force model calls it at every force pass, after its own forces, so every integrator sees it.
 *
 * <p>Contract: {@link #addForces} adds (never overwrites) newtons to {@code f}, 3 per node, and does not allocate
 * (it runs at every force pass). A conservative term gives its potential in {@link #energy}, and its forces are
 * minus that energy's gradient; the implicit integrators linearise the built-in forces only, so a term with a
 * large stiffness against the node masses and the step needs its own stability check (its owner's job).
 */
public interface ForceTerm {
    /**
     * Adds the term's forces (N) at time {@code t} (s), positions {@code x} (m) and velocities {@code v} (m/s),
     * 3 doubles per node, to {@code f}.
     */
    void addForces(double t, double[] x, double[] v, double[] f);

    /** The term's potential energy at time {@code t} (s) and positions {@code x} (m), J; 0 for a term that has none. */
    default double energy(double t, double[] x) {
        return 0;
    }
}
