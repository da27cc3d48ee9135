package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * The large-step BDF2 solver with rigid links (stages 2 and 3 of the paper's loop after it): at
 * large steps it must come to rest on the constrained equilibrium, where the forces along the
 * links' tangents balance. A stage 1 that ignores the links relaxes the springs freely before the
 * projection puts the links back, and comes to rest elsewhere.
 */
class PrefactoredBdf2LinksTest {
    static final double G = 9.81;
    static final double M = 0.05; // kg
    static final double L = 0.1; // m, the link
    static final double K = 40; // N/m, the side spring
    static final double CX = 0.12; // m, the side spring's anchor (CX, 0, CZ)
    static final double CZ = -0.02;

    /**
     * A pendulum: a bob on a rigid link of length L from a fixed pivot at the origin, under
     * gravity, pulled sideways by a spring to a fixed anchor; the bob starts hanging straight down,
     * with the spring stretched by a quarter of its rest length.
     */
    static Topology pendulum() {
        Topology t = new Topology();
        Node pivot = t.addNode(0, 0, 0, M).fix();
        Node bob = t.addNode(0, 0, -L, M);
        Node anchor = t.addNode(CX, 0, CZ, M).fix();
        t.addRigidLink(pivot, bob);
        t.addSpring(bob.id(), anchor.id(), K, 0.8 * Math.hypot(CX, CZ + L), 0.2 * Math.sqrt(K * M));
        t.setGravity(new Vec3(0, 0, -G));
        t.setViscousDamping(0.5 * Math.sqrt(K * M));
        return t;
    }

    /** dE/dtheta of the bob at angle theta from the downward vertical (towards +x), J/rad. */
    static double energySlope(double theta) {
        double bx = L * Math.sin(theta);
        double bz = -L * Math.cos(theta);
        double dx = bx - CX;
        double dz = bz - CZ;
        double len = Math.hypot(dx, dz);
        double rest = 0.8 * Math.hypot(CX, CZ + L);
        double tension = K * (len - rest); // N, along (dx, dz) / len
        double dbx = L * Math.cos(theta);
        double dbz = L * Math.sin(theta);
        return M * G * dbz + tension * (dx * dbx + dz * dbz) / len;
    }

    /** The constrained equilibrium angle, by bisection of dE/dtheta on (0, pi/4) (about 16 degrees), rad. */
    static double equilibriumAngle() {
        double lo = 0;
        double hi = Math.PI / 4;
        assertTrue(energySlope(lo) < 0 && energySlope(hi) > 0, "an equilibrium between 0 and 45 degrees");
        for (int i = 0; i < 200; i++) {
            double mid = 0.5 * (lo + hi);
            if (energySlope(mid) < 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    }

    @Test
    void comesToRestOnTheConstrainedEquilibriumAtLargeSteps() {
        double theta = equilibriumAngle();
        for (double h : new double[] {0.002, 0.02, 0.05}) {
            Simulation sim = new Simulation(SystemState.compile(pendulum()), new PrefactoredBdf2());
            sim.runUntil(40, h);
            SystemState s = sim.state();
            double angle = Math.atan2(s.x[3], -s.x[5]);
            assertEquals(theta, angle, 1e-7, "equilibrium angle at h = " + h + " s (exact " + theta + " rad)");
            assertEquals(L, Math.hypot(s.x[3], s.x[5]), 1e-9 * L, "link length at h = " + h + " s");
            assertEquals(0, s.x[4], 1e-12, "the bob stays in its plane");
        }
    }
}
