package org.tensim.solver.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.SpringScene;
import org.tensim.solver.ForceTerm;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/** The whole force model's highest frequency by central differences, against exact values and the springs' own. */
class ForcePowerIterationTest {
    private static ForcePowerIteration.Estimate measure(Simulation sim) {
        SystemState s = sim.state();
        double[] zero = new double[s.x.length];
        return ForcePowerIteration.estimate((px, f) -> sim.forces().computeForces(0, px, zero, f), s.x, s.invMass,
                1e-7, 2000, 1e-12, 7);
    }

    /** One mass on an anchored spring: w; a term tying it to a point with k2 raises the axial mode to sqrt(w^2 + k2 / m). */
    @Test
    void oneSpringThenATermAddedToIt() {
        double omega = 7;
        Simulation sim = Simulation.of(SpringScene.build(omega, 0, 0));
        ForcePowerIteration.Estimate e = measure(sim);
        assertTrue(e.converged());
        assertEquals(omega, e.omegaMax(), 1e-6 * omega, "the spring alone");
        double k2 = 150; // N/m on the 1 kg node, every axis: f = -k2 (x - x_rest)
        double[] rest = sim.state().x.clone();
        sim.forces().addTerm(new ForceTerm() {
            @Override
            public void addForces(double t, double[] x, double[] v, double[] f) {
                for (int c = 0; c < 3; c++) {
                    f[3 + c] -= k2 * (x[3 + c] - rest[3 + c]);
                }
            }
        });
        e = measure(sim);
        assertEquals(Math.sqrt(omega * omega + k2), e.omegaMax(), 1e-6 * omega, "the term is seen: " + e);
    }

    /** On a lattice cube the springs' own power iteration and the forces' differences find the same w_max. */
    @Test
    void agreesWithTheSpringNetworksEstimateOnALattice() {
        SystemState s = SystemState.compile(LatticeScene.build(5, 0.1, 1, 1000, 0, false));
        double springs = s.criticalTimeStep().omegaMaxPower();
        ForcePowerIteration.Estimate e = measure(new Simulation(s));
        assertEquals(springs, e.omegaMax(), 1e-3 * springs, "forces " + e + " against springs " + springs);
        assertTrue(e.omegaMax() <= s.criticalTimeStep().omegaMaxGershgorin() * (1 + 1e-9), "under the bound");
    }

    @Test
    void refusesBadArguments() {
        ForcePowerIteration.Forces none = (x, f) -> { };
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ForcePowerIteration.estimate(none, new double[5], new double[2], 1e-7, 10, 1e-6, 1));
        assertTrue(e.getMessage().contains("3 per node"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> ForcePowerIteration.estimate(none, new double[6], new double[2], 0, 10, 1e-6, 1));
        assertTrue(e.getMessage().contains("displacement must be > 0 m"), e.getMessage());
    }
}
