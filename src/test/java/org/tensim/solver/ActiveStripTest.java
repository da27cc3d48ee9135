package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.ForceLength;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * A membrane strip of St Venant-Kirchhoff triangles contracted by its own fibres, with an active
 * stress twice what the material can resist in compression ({@code E / (3 sqrt 3)}, at a stretch of
 * {@code 1 / sqrt 3}). With a constant active stress nothing would stop the shortening: the strip
 * would collapse through zero length. With the force-length relation ({@link ForceLength}) the
 * strip settles where the passive stress balances the active one,
 * {@code E lambda (1 - lambda^2) / 2 = sigma_a f_L(lambda)} (nu = 0: uniaxial, no lateral strain),
 * a stable equilibrium above the material's critical stretch.
 */
class ActiveStripTest {
    private static final double E = 40e3;
    private static final double SIGMA = 15e3;
    private static final double LENGTH = 0.03;
    private static final double WIDTH = 0.01;
    private static final double THICKNESS = 2.5e-3;

    /** The passive first Piola stress minus the active stress, Pa: positive where the strip extends again. */
    private static double netStress(double lambda) {
        return E * lambda * (1 - lambda * lambda) / 2 - SIGMA * ForceLength.value(lambda);
    }

    @Test
    void theStripSettlesAtTheBalanceOfPassiveAndActiveStress() {
        assertTrue(SIGMA > 1.9 * E / (3 * Math.sqrt(3)), "the active stress exceeds what the material resists");
        // The equilibrium stretch, by bisection between the critical stretch and the rest length.
        double lo = 1 / Math.sqrt(3);
        double hi = 1;
        assertTrue(netStress(lo) > 0 && netStress(hi) < 0);
        for (int i = 0; i < 100; i++) {
            double mid = 0.5 * (lo + hi);
            if (netStress(mid) > 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        double expected = 0.5 * (lo + hi);
        Topology t = new Topology();
        double m = 1e-3;
        t.addNode(0, 0, 0, m).fix();
        t.addNode(LENGTH, 0, 0, m);
        t.addNode(LENGTH, WIDTH, 0, m);
        t.addNode(0, WIDTH, 0, m).fix();
        int[][] tris = {{0, 1, 2}, {0, 2, 3}};
        for (int[] c : tris) {
            t.addTriangle(c[0], c[1], c[2], THICKNESS, E, 0);
            t.addFibre(c, c, new Vec3(1, 0, 0), THICKNESS, time -> SIGMA);
        }
        t.setViscousDamping(0.3);
        // The muscle does work on the strip from rest: the elastic energy grows from zero, by design.
        Simulation sim = Simulation.of(t);
        sim.apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
        sim.runUntil(3, 1e-4);
        SystemState s = sim.state();
        for (int node : new int[] {1, 2}) {
            assertEquals(expected * LENGTH, s.x[3 * node], 1e-4 * LENGTH, "node " + node + " x");
            assertEquals(node == 1 ? 0 : WIDTH, s.x[3 * node + 1], 1e-6 * WIDTH, "node " + node + " y");
            assertEquals(0, s.v[3 * node], 1e-6, "node " + node + " at rest");
        }
        assertTrue(expected > 1 / Math.sqrt(3) && expected < 0.7, "equilibrium stretch " + expected);
    }
}
