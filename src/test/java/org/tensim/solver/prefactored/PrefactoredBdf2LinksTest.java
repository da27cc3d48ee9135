package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.links.RigidPendulum;

/**
 * The large-step BDF2 solver with rigid links (stages 2 and 3 of the paper's loop after it): at
 * large steps it must come to rest on the constrained equilibrium, where the forces along the
 * links' tangents balance ({@link RigidPendulum}).
 */
class PrefactoredBdf2LinksTest {
    @Test
    void comesToRestOnTheConstrainedEquilibriumAtLargeSteps() {
        double theta = RigidPendulum.equilibriumAngle();
        double l = RigidPendulum.L;
        for (double h : new double[] {0.002, 0.02, 0.05}) {
            Simulation sim = new Simulation(SystemState.compile(RigidPendulum.topology()), new PrefactoredBdf2());
            sim.runUntil(40, h);
            SystemState s = sim.state();
            assertEquals(theta, RigidPendulum.angle(s.x), 1e-7, "equilibrium angle at h = " + h + " s (exact " + theta + " rad)");
            assertEquals(l, Math.hypot(s.x[3], s.x[5]), 1e-9 * l, "link length at h = " + h + " s");
            assertEquals(0, s.x[4], 1e-12, "the bob stays in its plane");
        }
    }
}
