package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;

/** A rigid-link projection that cannot converge is reported with its residual, never silently accepted. */
class ProjectionFailureTest {
    /** A triangle whose links ask for lengths 1, 1 and 3: no positions satisfy the triangle inequality. */
    private static Simulation contradictory() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1);
        Node b = t.addNode(1, 0, 0, 1);
        Node c = t.addNode(0.5, 0.8, 0, 1);
        t.addRigidLink(a.id(), b.id(), 1);
        t.addRigidLink(b.id(), c.id(), 1);
        t.addRigidLink(c.id(), a.id(), 3);
        Simulation sim = new Simulation(SystemState.compile(t));
        sim.apply(sim.settings().withProjection(sim.settings().projectionTolerance(), 50));
        return sim;
    }

    @Test
    void warnsWithResidualAndCounts() {
        Simulation sim = contradictory();
        List<String> warnings = new ArrayList<>();
        sim.setWarningSink(warnings::add);
        sim.step(1e-3);
        assertEquals(1, sim.unconvergedProjections());
        double residual = sim.projection().maxRelativeError();
        assertTrue(residual > 0.1, "links 1, 1, 3 cannot all hold: residual " + residual);
        assertEquals(1, warnings.size());
        assertTrue(warnings.get(0).contains(Double.toString(residual)), warnings.get(0));
        assertTrue(warnings.get(0).contains("50 sweeps"), warnings.get(0));
    }

    @Test
    void errorSeverityStopsTheRunNamingLinkAndResidual() {
        Simulation sim = contradictory();
        sim.apply(sim.settings().withProjectionFailureSeverity(Severity.ERROR));
        ProjectionFailedException e = assertThrows(ProjectionFailedException.class, () -> sim.step(1e-3));
        assertTrue(e.residual() > 0.1);
        assertEquals(sim.projection().worstLink(), e.link());
        assertTrue(e.getMessage().contains("link " + e.link()) && e.getMessage().contains("relative length error"),
                e.getMessage());
        assertEquals(1, e.step());
    }

    @Test
    void consistentLinksConvergeSilently() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1);
        Node b = t.addNode(1, 0, 0, 1);
        Node c = t.addNode(0.5, 0.8, 0, 1);
        t.addRigidLink(a, b);
        t.addRigidLink(b, c);
        t.addRigidLink(c, a);
        t.setGravity(new org.tensim.model.Vec3(0, -9.81, 0));
        Simulation sim = new Simulation(SystemState.compile(t));
        sim.apply(sim.settings().withProjectionFailureSeverity(Severity.ERROR));
        sim.runUntil(0.5, 1e-3);
        assertEquals(0, sim.unconvergedProjections());
        assertTrue(sim.projection().maxRelativeError() <= sim.settings().projectionTolerance());
    }
}
