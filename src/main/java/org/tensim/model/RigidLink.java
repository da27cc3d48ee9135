package org.tensim.model;

/**
 * A rigid element of a tensegrity: the distance between its two nodes is kept
 * at {@code length} by the projection stage of the simulation loop (paper,
 * section 2.2, step 2; Provot 1995). It carries compression and tension but has
 * no stiffness parameter: it is a constraint, not a force.
 *
 * @param a      first node id
 * @param b      second node id (different from a)
 * @param length constant length, m (> 0)
 */
public record RigidLink(int a, int b, double length) {
    public RigidLink {
        if (a == b) {
            throw new IllegalArgumentException("a rigid link must join two different nodes, got node " + a
                    + " to itself");
        }
        Check.positive("rigid link " + a + "-" + b + " length", "m", length);
    }
}
