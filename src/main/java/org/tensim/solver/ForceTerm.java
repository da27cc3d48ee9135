package org.tensim.solver;

/**
 * A force a scene adds to the built-in ones of {@link ForceModel}: a coupling with another body (a surface the
 * nodes slide on, carried by other nodes), a contact on a surface mapped from the nodes, any load that depends on
 * positions. The force model calls it at every force pass, after its own forces, so every integrator sees it.
 *
 * <p>Contract: {@link #addForces} adds (never overwrites) newtons to {@code f}, 3 per node, and does not allocate
 * (it runs at every force pass). A conservative term gives its potential in {@link #energy}, and its forces are
 * minus that energy's gradient. A stiff term (a contact penalty) gives its tangent too: {@link #linearise} and
 * {@link #multiplyAdd}, which {@code bdf2}'s Newton-Krylov products add to the built-in forces' (and
 * {@link #addIsotropicStiffness}, which its prefactored preconditioner adds to its diagonal); a term without them is
 * treated explicitly, and one with a large stiffness against the node masses and the step then needs its own
 * stability check (its owner's job). The other implicit integrators linearise the built-in forces only.
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

    /**
     * Linearises the term's tangent stiffness {@code K = -df/dx} (N/m) at time {@code t} (s) and positions {@code x}
     * (m) for the {@link #multiplyAdd} products that follow, until the next call. Default: no tangent.
     */
    default void linearise(double t, double[] x) {
    }

    /**
     * {@code y += weight K z} with K linearised by {@link #linearise}: {@code offset[i]} is the index of node i's x in
     * z and y, or -1 for a node left out (its z taken as 0, its y not written); a null offset means the full layout
     * (3 i). Allocation-free. Default: nothing (no tangent).
     */
    default void multiplyAdd(double[] z, double[] y, int[] offset, double weight) {
    }

    /**
     * Adds to {@code perNode[i]} (N/m, one per node) an isotropic part of the term's stiffness on node i, the trace
     * of its diagonal block over 3 for any configuration it may take (a contact counted as touching), for a
     * preconditioner that is factored once. Default: nothing.
     */
    default void addIsotropicStiffness(double[] perNode) {
    }

    /**
     * The term's projection stage, run after each step with the rigid links' and the nodes' own contacts'
     * ({@link Simulation}): moves positions {@code x} (m) at time {@code t} (s) to satisfy the term's hard
     * constraints (a mapped surface kept out of the bones), nodes of zero inverse mass left where they are; the
     * velocity update that follows takes away the velocity of the motion removed. Returns the largest correction, m
     * (0: nothing to correct, and the rounds stop). Allocation-free. Default: none.
     */
    default double project(double t, double[] x, double[] invMass) {
        return 0;
    }

    /** The nodes {@link #project} may move (each once, ascending); default none. */
    default int[] projectedNodes() {
        return new int[0];
    }
}
