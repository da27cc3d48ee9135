package org.tensim.solver.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.analysis.StabilityStudy;
import org.tensim.model.Node;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.SpringScene;
import org.tensim.solver.Integrator;
import org.tensim.solver.Severity;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/** The critical time step estimate against exact values and against the measured limit. */
class CriticalTimeStepTest {
    private static double forIntegrator(CriticalTimeStep c, String name) {
        Integrator in = Integrators.create(name);
        return c.forMethod(in.explicit(), in.undampedStabilityLimit());
    }

    /** The one Gershgorin bound, both forms, on one free node between a fixed end and a free 4 kg mass. */
    @Test
    void gershgorinFormsOnKnownRows() {
        int[] a = {0, 1};
        int[] b = {1, 2};
        double[] k = {100, 300};
        double[] m = {1, 1, 4};
        boolean[] free = {false, true, true};
        // Rows of M^-1 K: node 1: 2 (100 + 300) / 1 = 800; node 2: 2 300 / 4 = 150.
        assertEquals(Math.sqrt(800), CriticalTimeStep.gershgorin(3, a, b, k, 2, m, free, CriticalTimeStep.Form.ROWS),
                1e-12);
        // Symmetric: node 1: 100 + 300 + 300 / 2 = 550; node 2: 300 / 4 + 300 / 2 = 225.
        assertEquals(Math.sqrt(550), CriticalTimeStep.gershgorin(3, a, b, k, 2, m, free,
                CriticalTimeStep.Form.SYMMETRIC), 1e-12);
    }
    @Test
    void singleAnchoredSpringIsExact() {
        double omega = 7;
        CriticalTimeStep c = SystemState.compile(SpringScene.build(omega, 0, 0.01)).criticalTimeStep();
        assertEquals(omega, c.omegaMaxPower(), 1e-9 * omega, "power iteration on one spring");
        assertEquals(omega, c.omegaMaxGershgorin(), 1e-9 * omega, "Gershgorin on one spring (anchor fixed)");
        assertEquals(2 / omega, c.stepSeconds(), 1e-9);
        assertEquals(2 * Math.sqrt(2) / omega, forIntegrator(c, "rk4"), 1e-9);
        assertEquals(Double.POSITIVE_INFINITY, forIntegrator(c, "implicit-euler"));
    }

    @Test
    void freeTwoMassSpringHasOmegaSqrtTwoKOverM() {
        // Two free 1 kg masses on a 100 N/m spring: w = sqrt(k (1/m1 + 1/m2)) = sqrt(200).
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1);
        Node b = t.addNode(1, 0, 0, 1);
        t.addSpring(a, b, 100, 0);
        CriticalTimeStep c = SystemState.compile(t).criticalTimeStep();
        assertEquals(Math.sqrt(200), c.omegaMaxPower(), 1e-6);
        assertTrue(c.omegaMaxGershgorin() >= c.omegaMaxPower() * (1 - 1e-12), "Gershgorin is an upper bound");
    }

    /**
     * Lattice cube of 5 x 5 x 5 nodes (spacing 0.1 m, 1 kg, 1000 N/m, bottom fixed,
     * no gravity), every free node displaced by a seeded random 1e-7 m so that all
     * modes are excited; symplectic Euler's largest stable step found by bisection.
     */
    @Test
    void estimateWithinTenPercentOfMeasuredLimitOnLatticeCube() {
        Topology lattice = LatticeScene.build(5, 0.1, 1, 1000, 0, false);
        Topology perturbed = perturbed(lattice, 1e-7, 42);
        CriticalTimeStep c = SystemState.compile(lattice).criticalTimeStep();
        double omega = c.omegaMaxPower();
        double duration = 200 * 2 * Math.PI / omega; // 200 periods of the highest mode
        // Bracket w h in [1, 4] around the theory's 2: trials at small w h would only cost time.
        double measuredOmegaH = StabilityStudy.criticalOmegaH(perturbed, "symplectic-euler", omega, duration, 1e-7,
                1e-3, 1, 4);
        double measuredStep = measuredOmegaH / omega;
        assertEquals(measuredStep, c.stepSeconds(), 0.10 * measuredStep, "estimate " + c.stepSeconds()
                + " s against the measured limit " + measuredStep + " s");
        assertTrue(c.gershgorinStepSeconds() <= measuredStep * 1.001, "the Gershgorin step "
                + c.gershgorinStepSeconds() + " s must not exceed the measured limit " + measuredStep + " s");
    }

    /** A copy of t with every free node moved by a seeded random vector of length up to amp (m), same springs. */
    static Topology perturbed(Topology t, double amp, long seed) {
        Random rnd = new Random(seed);
        Topology p = new Topology();
        for (Node n : t.nodes()) {
            double dx = 0;
            double dy = 0;
            double dz = 0;
            if (!n.isFixed()) {
                dx = amp * (rnd.nextDouble() - 0.5);
                dy = amp * (rnd.nextDouble() - 0.5);
                dz = amp * (rnd.nextDouble() - 0.5);
            }
            Node q = p.addNode(n.position().x() + dx, n.position().y() + dy, n.position().z() + dz, n.mass());
            if (n.isFixed()) {
                q.fix();
            }
        }
        for (Spring s : t.springs()) {
            p.addSpring(s.a(), s.b(), s.stiffness(), s.restLength(), s.damping());
        }
        return p;
    }

    @Test
    void explicitStepBeyondEstimateWarnsNamingIt() {
        SystemState s = SystemState.compile(SpringScene.build(10, 0, 0.01));
        Simulation sim = new Simulation(s, Integrators.create("symplectic-euler"));
        List<String> warnings = new ArrayList<>();
        sim.setWarningSink(warnings::add);
        sim.step(0.1); // w h = 1: fine
        assertEquals(List.of(), warnings);
        sim.step(0.25); // w h = 2.5 > 2
        assertEquals(1, warnings.size(), "one warning for the new step size");
        assertTrue(warnings.get(0).contains("0.2 s"), "names the estimate 2 / w = 0.2 s: " + warnings.get(0));
        sim.step(0.25);
        assertEquals(1, warnings.size(), "warned once per step size, not every step");
    }

    @Test
    void explicitStepBeyondEstimateCanBeAnError() {
        Simulation sim = new Simulation(SystemState.compile(SpringScene.build(10, 0, 0.01)),
                Integrators.create("rk4"));
        sim.apply(sim.settings().withStepLimitSeverity(Severity.ERROR));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.step(0.3));
        assertTrue(e.getMessage().contains("critical step estimate " + 2 * Math.sqrt(2) / 10),
                e.getMessage());
        assertEquals(0, sim.steps(), "nothing was stepped");
    }

    @Test
    void implicitMethodNeverWarns() {
        Simulation sim = new Simulation(SystemState.compile(SpringScene.build(10, 0, 0.01)),
                Integrators.create("implicit-euler"));
        sim.apply(sim.settings().withStepLimitSeverity(Severity.ERROR));
        sim.step(10); // w h = 100
        assertEquals(0, sim.stepLimitWarnings());
    }
}
