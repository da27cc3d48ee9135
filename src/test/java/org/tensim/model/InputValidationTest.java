package org.tensim.model;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.tensim.solver.Simulation;

/** Bad input is rejected where it enters, with a message that names the value and what was expected. */
class InputValidationTest {
    static void rejects(Class<? extends Throwable> type, Executable e, String... mustMention) {
        Throwable t = assertThrows(type, e);
        for (String s : mustMention) {
            assertTrue(t.getMessage().contains(s), "message '" + t.getMessage() + "' should mention '" + s + "'");
        }
    }

    static Topology two() {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(1, 0, 0, 1);
        return t;
    }

    @Test
    void massMustBePositive() {
        rejects(IllegalArgumentException.class, () -> new Topology().addNode(0, 0, 0, 0), "mass", "> 0", "0.0");
        rejects(IllegalArgumentException.class, () -> new Topology().addNode(0, 0, 0, -2), "mass", "-2.0");
    }

    @Test
    void stiffnessMustNotBeNegative() {
        rejects(IllegalArgumentException.class, () -> two().addSpring(0, 1, -5, 1, 0), "stiffness", ">= 0", "-5.0");
    }

    @Test
    void dampingMustNotBeNegative() {
        rejects(IllegalArgumentException.class, () -> two().addSpring(0, 1, 5, 1, -1), "damping", "-1.0");
    }

    @Test
    void nanAndInfiniteValuesAreRejected() {
        rejects(IllegalArgumentException.class, () -> new Topology().addNode(Double.NaN, 0, 0, 1), "node 0", "NaN");
        rejects(IllegalArgumentException.class, () -> new Topology().addNode(0, 0, 0, Double.POSITIVE_INFINITY),
                "mass", "Infinity");
        rejects(IllegalArgumentException.class, () -> two().addSpring(0, 1, Double.NaN, 1, 0), "stiffness", "NaN");
        rejects(IllegalArgumentException.class, () -> two().addRigidLink(0, 1, Double.POSITIVE_INFINITY), "length",
                "Infinity");
        rejects(IllegalArgumentException.class, () -> new Vec3(0, Double.NaN, 0), "NaN");
    }

    @Test
    void timeStepMustBePositiveAndFinite() {
        Simulation sim = Simulation.of(two());
        rejects(IllegalArgumentException.class, () -> sim.step(0), "dt", "> 0", "0.0");
        rejects(IllegalArgumentException.class, () -> sim.step(-1e-3), "dt", "-0.001");
        rejects(IllegalArgumentException.class, () -> sim.step(Double.NaN), "dt", "NaN");
    }

    @Test
    void springOrLinkToItselfIsRejected() {
        rejects(IllegalArgumentException.class, () -> two().addSpring(1, 1, 5, 1, 0), "itself", "node 1");
        rejects(IllegalArgumentException.class, () -> two().addRigidLink(0, 0, 1), "itself", "node 0");
        Topology t = two();
        rejects(IllegalArgumentException.class, () -> t.addSpring(t.node(0), t.node(0), 1, 0), "itself");
    }

    @Test
    void indexOutOfRangeIsRejected() {
        rejects(IndexOutOfBoundsException.class, () -> two().addSpring(0, 2, 5, 1, 0), "2", "0 <= index < 2");
        rejects(IndexOutOfBoundsException.class, () -> two().addRigidLink(-1, 1, 1), "-1");
        rejects(IndexOutOfBoundsException.class, () -> two().node(7), "7");
    }

    @Test
    void zeroLengthRigidLinkIsRejected() {
        Topology t = new Topology();
        Node a = t.addNode(1, 2, 3, 1);
        Node b = t.addNode(1, 2, 3, 1);
        rejects(IllegalArgumentException.class, () -> t.addRigidLink(a, b), "zero length");
        rejects(IllegalArgumentException.class, () -> t.addRigidLink(0, 1, 0), "length", "> 0", "0.0");
    }

    @Test
    void nodesOfAnotherTopologyAreRejected() {
        Topology t = two();
        Node foreign = two().node(1);
        Node other = new Topology().addNode(5, 5, 5, 1);
        // Its id is out of range here.
        rejects(IllegalArgumentException.class, () -> t.addSpring(t.node(0), other, 1, 0), "does not belong");
        // Its id (1) is in range and names another node of this topology: still not this topology's node.
        rejects(IllegalArgumentException.class, () -> t.addSpring(t.node(0), foreign, 1, 0), "node 1",
                "does not belong");
        rejects(IllegalArgumentException.class, () -> t.addRigidLink(foreign, t.node(0)), "does not belong");
    }

    @Test
    void forceLawParametersAreValidated() {
        rejects(IllegalArgumentException.class, () -> ForceLaw.sinusoid(-1, 1, 0, new Vec3(0, 1, 0)), "amplitude");
        rejects(IllegalArgumentException.class, () -> ForceLaw.sinusoid(1, -1, 0, new Vec3(0, 1, 0)), "frequency");
        rejects(IllegalArgumentException.class, () -> ForceLaw.sinusoid(1, 1, 0, Vec3.ZERO), "zero vector");
    }
}
