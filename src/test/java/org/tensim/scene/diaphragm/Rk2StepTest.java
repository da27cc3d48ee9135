package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;

/** The stable RK2 step against the amplification factor and against a real damped spring. */
class Rk2StepTest {
    @Test
    void withoutDampingNoStepIsStable() {
        // |1 + z + z^2/2|^2 = 1 + (w h)^4 / 4 on the imaginary axis (PHYSICS.md)
        assertEquals(Math.sqrt(1 + Math.pow(0.5, 4) / 4), Rk2Step.amplification(0, 0.5), 1e-15);
        // Only steps so small that the growth per step is below round-off pass: w h < 0.01.
        assertTrue(Rk2Step.stable(1000, 0, 0) * 1000 < 0.01);
    }

    @Test
    void overdampedRealAxisLimitIsTwo() {
        // For a purely real eigenvalue lambda, RK2 is stable for h |lambda| <= 2.
        assertEquals(1, Rk2Step.amplification(-2, 0), 1e-15);
        assertTrue(Rk2Step.amplification(-2.01, 0) > 1);
    }

    @Test
    void aDampedSpringStepsStablyAtTheChosenStepAndBlowsUpWellAboveIt() {
        double m = 1e-3;
        double k = 100;
        double w = Math.sqrt(k / m);
        double zeta = 0.3;
        double beta = 2 * zeta / w;
        double h = Rk2Step.stable(w, beta, 0);
        assertTrue(h > 1.0 / w && h < 3.0 / w, "about 1.5 / w for zeta = 0.3, got w h = " + h * w);
        assertTrue(amplitudeAfter(m, k, beta * k, 0.95 * h) < 1e-3, "decays at 0.95 h");
        assertTrue(amplitudeAfter(m, k, beta * k, 1.3 * h) > 1, "grows at 1.3 h");
    }

    private static double amplitudeAfter(double m, double k, double c, double h) {
        Topology t = new Topology();
        var anchor = t.addNode(0, 0, 0, m).fix();
        var mass = t.addNode(1, 0, 0, m);
        t.addSpring(anchor.id(), mass.id(), k, 0.9, c);
        Simulation s = Simulation.of(t);
        for (int i = 0; i < 400; i++) {
            try {
                s.step(h);
            } catch (SimulationDivergedException e) {
                return Double.POSITIVE_INFINITY; // the runaway check stopped a growing oscillation
            }
            if (Math.abs(s.state().x[3] - 0.9) > 1e6) {
                break;
            }
        }
        return Math.abs(s.state().x[3] - 0.9) / 0.1;
    }
}
