package org.tensim.solver.integrators;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.links.RigidPendulum;

/**
 * Implicit Euler with rigid links (stages 2 and 3 of the paper's loop after it): at steps far
 * beyond the side spring's period it comes to rest on the constrained equilibrium of
 * {@link RigidPendulum}, as BDF2 does; its first-order error only delays the approach.
 */
class ImplicitEulerLinksTest {
    @Test
    void comesToRestOnTheConstrainedEquilibriumAtLargeSteps() {
        double theta = RigidPendulum.equilibriumAngle();
        double l = RigidPendulum.L;
        for (double h : new double[] {0.002, 0.005, 0.02, 0.05}) {
            ImplicitEuler ie = new ImplicitEuler().setTolerance(1e-10);
            Simulation sim = new Simulation(SystemState.compile(RigidPendulum.topology()), ie);
            sim.runUntil(40, h);
            SystemState s = sim.state();
            assertEquals(theta, RigidPendulum.angle(s.x), 1e-7, "equilibrium angle at h = " + h + " s (exact " + theta + " rad)");
            assertEquals(l, Math.hypot(s.x[3], s.x[5]), 1e-9 * l, "link length at h = " + h + " s");
            assertEquals(0, s.x[4], 1e-12, "the bob stays in its plane");
            assertEquals(0, ie.unconvergedSolves(), "CG converged at every step, h = " + h + " s");
        }
    }

    @Test
    void swingsOnTheLinkWithoutStretchingItWithinTheStep() {
        // One large step from rest: the bob must move along the circle's tangent, so the link's
        // length after stage 1 alone is off by a second-order remainder only.
        SystemState s = SystemState.compile(RigidPendulum.topology());
        ImplicitEuler ie = new ImplicitEuler().setTolerance(1e-12);
        double h = 0.02;
        ie.step(new org.tensim.solver.ForceModel(s), 0, h);
        double len = Math.hypot(s.x[3], s.x[5]);
        double moved = Math.hypot(s.x[3], s.x[5] + RigidPendulum.L);
        assertTrue(moved > 1e-4, "the bob moves: " + moved + " m");
        assertTrue(Math.abs(len - RigidPendulum.L) < 0.5 * moved * moved / RigidPendulum.L + 1e-12,
                "stage 1 keeps the link to second order: length " + len + " m after a move of " + moved + " m");
    }
}
