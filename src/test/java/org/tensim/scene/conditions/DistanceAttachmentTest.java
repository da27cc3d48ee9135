package org.tensim.scene.conditions;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.model.Motion;
import org.tensim.model.Topology;

/**
 * The attachment by a distance threshold on eleven nodes 1 mm apart along x between two targets, a point at x = 0
 * that drives its nodes and a point at x = 10 mm that ties them by springs to an anchor: within 3 mm (inclusive)
 * each node goes to its nearest target, a node as near to both to the first, the others stay free.
 */
class DistanceAttachmentTest {
    @Test
    void eachNodeWithinTheThresholdGoesToItsNearestTargetAndTheOthersStayFree() {
        Topology t = new Topology();
        for (int i = 0; i <= 10; i++) {
            t.addNode(1e-3 * i, 0, 0, 1e-3);
        }
        int anchor = t.addNode(0.02, 0, 0, 1e-3).fix().id();
        Motion lift = (time, rest, out, o) -> {
            out[o] = rest.x();
            out[o + 1] = rest.y() + time;
            out[o + 2] = rest.z();
        };
        List<int[]> springs = new ArrayList<>();
        List<Double> stiffness = new ArrayList<>();
        List<DistanceAttachment.Target> targets = List.of(
                new DistanceAttachment.Target("left", q -> Math.abs(q.x()), DistanceAttachment.drive(lift)),
                new DistanceAttachment.Target("right", q -> Math.abs(q.x() - 0.01),
                        DistanceAttachment.tie((a, b, k) -> {
                            springs.add(new int[] {a, b});
                            stiffness.add(k);
                        }, 7, anchor)));
        BitSet candidates = new BitSet();
        candidates.set(0, 11);
        // Nodes 4 to 6 are 4 mm or more from both targets: free.
        DistanceAttachment.Result r = DistanceAttachment.attach(t, candidates, targets, 0.003 + 1e-15);
        assertArrayEquals(new int[] {0, 0, 0, 0, -1, -1, -1, 1, 1, 1, 1, -1}, r.target());
        assertEquals(8, r.attached());
        assertEquals(0, r.nearest());
        for (int i = 0; i <= 10; i++) {
            assertEquals(i <= 3, t.node(i).isDriven(), "node " + i + " driven");
            assertTrue(!t.node(i).isFixed(), "node " + i + " not fixed");
        }
        assertEquals(4, springs.size(), "one spring from each of nodes 7-10 to the anchor");
        for (int k = 0; k < springs.size(); k++) {
            assertArrayEquals(new int[] {7 + k, anchor}, springs.get(k));
            assertEquals(7, stiffness.get(k));
        }
        double[] out = new double[3];
        t.node(2).motion().position(0.5, t.node(2).position(), out, 0);
        assertArrayEquals(new double[] {0.002, 0.5, 0}, out, 1e-15);
    }

    @Test
    void theNearerTargetWinsAndTiesGoToTheFirst() {
        Topology t = new Topology();
        t.addNode(0.005, 0, 0, 1e-3);
        t.addNode(0.004, 0, 0, 1e-3);
        BitSet both = new BitSet();
        both.set(0, 2);
        DistanceAttachment.Result r = DistanceAttachment.attach(t, both, List.of(
                new DistanceAttachment.Target("spine", q -> Math.abs(q.x() - 0.01), DistanceAttachment.fix()),
                new DistanceAttachment.Target("rib", q -> Math.abs(q.x()), DistanceAttachment.fix())), 0.005);
        // Node 0 is exactly at the threshold from both (inclusive): the first target takes it.
        assertArrayEquals(new int[] {0, 1}, r.target(), "node 0 as near to both (the first), node 1 nearer the rib");
        assertTrue(t.node(0).isFixed() && t.node(1).isFixed());
        assertThrows(IllegalArgumentException.class, () -> DistanceAttachment.tie((a, b, k) -> { }, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> DistanceAttachment.attach(t, both, List.of(), Double.NaN));
    }
}
