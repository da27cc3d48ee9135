package org.tensim.model;

/**
 * A mass point of a {@link Topology}. Created only through
 * {@link Topology#addNode(double, double, double, double)}; its id is its index in
 * the topology and stays the same in the compiled state.
 *
 * <p>A node is <em>fixed</em> (it never moves: infinite mass for the rigid-link
 * projection, no integration) or <em>driven</em> (its position is a prescribed
 * function of time, {@link Motion}), or free.
 */
public final class Node {
    private final int id;
    private final Vec3 position;
    private final double massKg;
    private boolean fixed;
    private Motion motion;
    private int heldAxes;

    Node(int id, Vec3 position, double massKg) {
        this.id = id;
        this.position = position;
        this.massKg = Check.positive("node " + id + " mass", "kg", massKg);
    }

    /** Index of this node in its topology, 0-based. */
    public int id() {
        return id;
    }

    /** Initial (rest) position, m. */
    public Vec3 position() {
        return position;
    }

    /** Mass, kg (always > 0; a fixed node keeps its mass but does not move). */
    public double mass() {
        return massKg;
    }

    public boolean isFixed() {
        return fixed;
    }

    public boolean isDriven() {
        return motion != null;
    }

    /** The prescribed motion, or null when the node is not driven. */
    public Motion motion() {
        return motion;
    }

    /** Fixes the node at its initial position. Returns this node. */
    public Node fix() {
        if (motion != null) {
            throw new IllegalStateException("node " + id + " is driven by a motion; it cannot also be fixed");
        }
        fixed = true;
        return this;
    }

    /**
     * Holds the node at its initial coordinate on some axes only ({@code axes}: bit 0 x, bit 1 y, bit 2 z), free on
     * the others: the solver zeroes the force on those coordinates at every force pass and puts them back at rest
     * (velocity 0) after every step. Adds to the axes held before. Returns this node.
     */
    public Node hold(int axes) {
        if (axes <= 0 || axes > 7) {
            throw new IllegalArgumentException("node " + id + ": held axes must be a mask of x (1), y (2), z (4), got "
                    + axes);
        }
        if (motion != null) {
            throw new IllegalStateException("node " + id + " is driven by a motion; it cannot also be held on an axis");
        }
        heldAxes |= axes;
        return this;
    }

    /** The axes the node is held on ({@link #hold}: bit 0 x, 1 y, 2 z); 0 when none. A fixed node is held on all. */
    public int heldAxes() {
        return fixed ? 7 : heldAxes;
    }

    /** Prescribes this node's position as a function of time. Returns this node. */
    public Node drive(Motion m) {
        if (m == null) {
            throw new IllegalArgumentException("node " + id + ": motion must not be null");
        }
        if (fixed) {
            throw new IllegalStateException("node " + id + " is fixed; it cannot also be driven");
        }
        if (heldAxes != 0) {
            throw new IllegalStateException("node " + id + " is held on an axis; it cannot also be driven");
        }
        motion = m;
        return this;
    }

    @Override
    public String toString() {
        return "Node[" + id + " at " + position + ", " + massKg + " kg" + (fixed ? ", fixed" : "")
                + (motion != null ? ", driven" : "") + "]";
    }
}
