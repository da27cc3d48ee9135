package org.tensim.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.solver.SystemState;

class StabilityLimitTest {
    @Test
    void oneAnchoredSpringGivesTheGershgorinBound() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1).fix();
        Node b = t.addNode(1, 0, 0, 2);
        t.addSpring(a, b, 50, 0);
        double h = StabilityLimit.criticalTimeStep(SystemState.compile(t));
        // w_max^2 <= 2 k / m = 50, so h = 2 / sqrt(50); the exact limit 2 sqrt(m/k) = 0.4 is larger (safe side).
        assertEquals(2 / Math.sqrt(50), h, 1e-12);
        assertTrue(h <= 2 * Math.sqrt(2.0 / 50));
    }

    @Test
    void stifferSpringsLowerTheLimitAndNoSpringsMeanNone() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1);
        Node b = t.addNode(1, 0, 0, 1);
        t.addSpring(a, b, 10, 0);
        SystemState s = SystemState.compile(t);
        double soft = StabilityLimit.criticalTimeStep(s);
        s.setSpringStiffness(0, 40);
        assertEquals(soft / 2, StabilityLimit.criticalTimeStep(s), 1e-12);
        Topology lone = new Topology();
        lone.addNode(0, 0, 0, 1);
        assertEquals(Double.POSITIVE_INFINITY, StabilityLimit.criticalTimeStep(SystemState.compile(lone)));
    }
}
