package org.tensim.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.RigidLink;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

class SceneBuildersTest {
    @Test
    void tensegrityElementHasTwelveNodesSixStrutsAndFourCablesPerNode() {
        Topology t = new Topology();
        TensegrityElement.build(t, Vec3.ZERO, 1, 0.5, 1, 10, 0, true);
        assertEquals(12, t.nodeCount());
        assertEquals(6, t.rigidLinks().size());
        assertEquals(24, t.springs().size());
        Map<Integer, Integer> cables = new HashMap<>();
        for (Spring s : t.springs()) {
            cables.merge(s.a(), 1, Integer::sum);
            cables.merge(s.b(), 1, Integer::sum);
        }
        for (int i = 0; i < 12; i++) {
            assertEquals(4, cables.get(i), "cables at node " + i);
        }
        for (RigidLink l : t.rigidLinks()) {
            assertEquals(2.0, l.length(), 1e-12, "struts are 2h long");
        }
        // Without the struts the same element has the same nodes and cables.
        Topology m = new Topology();
        TensegrityElement.build(m, Vec3.ZERO, 1, 0.5, 1, 10, 0, false);
        assertEquals(0, m.rigidLinks().size());
        assertEquals(t.springs(), m.springs());
    }

    @Test
    void cubesAreIdenticalButForTheRigidLinks() {
        CubeParameters p = CubeParameters.paper();
        CubeScene mss = CubeScene.massSpring(p);
        CubeScene ts = CubeScene.tensegrity(p);
        assertEquals(20, mss.topology.nodeCount());
        assertEquals(mss.topology.nodeCount(), ts.topology.nodeCount());
        assertEquals(mss.topology.springs(), ts.topology.springs());
        assertEquals(0, mss.topology.rigidLinks().size());
        assertEquals(6, ts.topology.rigidLinks().size());
        for (int i = 0; i < mss.topology.nodeCount(); i++) {
            Node a = mss.topology.node(i);
            Node b = ts.topology.node(i);
            assertEquals(a.position(), b.position());
            assertEquals(a.isFixed(), b.isFixed());
        }
        assertEquals(2, ts.loaded.size());
        long fixed = ts.topology.nodes().stream().filter(Node::isFixed).count();
        assertEquals(6, fixed, "four bottom corners and the feet of the two vertical struts");
        for (Node n : ts.topology.nodes()) {
            double[] c = {n.position().x(), n.position().y(), n.position().z()};
            for (double v : c) {
                assertTrue(v >= -1e-12 && v <= 10 + 1e-12, "inside the 10 m cube: " + n);
            }
        }
        assertEquals(10, ts.probe.position().y(), 1e-12, "P is on the top face");
    }

    @Test
    void latticeHasTheAdvertisedCounts() {
        Topology t = LatticeScene.build(5, 0.1, 1, 100, 0, false);
        assertEquals(125, t.nodeCount());
        assertEquals(LatticeScene.springCount(5), t.springs().size());
        assertEquals(253_890, LatticeScene.springCount(31));
        assertEquals(25, t.nodes().stream().filter(Node::isFixed).count());
        Topology l = LatticeScene.build(4, 0.1, 1, 100, 0, true);
        assertEquals(27, l.rigidLinks().size());
    }
}
