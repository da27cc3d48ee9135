package org.tensim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** What a {@link Topology} reports about the scene authored in it. */
class TopologyTest {
    @Test
    void totalMassSumsEveryNodeFixedOrFree() {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1.5).fix();
        t.addNode(1, 0, 0, 2.0);
        t.addNode(0, 1, 0, 0.25);
        assertEquals(3.75, t.totalMass(), 1e-15);
        assertEquals(0, new Topology().totalMass());
    }

    @Test
    void aTrianglesRestAreaIsHalfItsEdgesCrossProduct() {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(0.3, 0, 0, 1);
        t.addNode(0, 0.4, 0, 1);
        TriangleElement e = t.addTriangle(0, 1, 2, 1e-3, 30e3, 0.3);
        assertEquals(0.06, e.areaM2(), 1e-15, "legs 0.3 m and 0.4 m");
    }
}
