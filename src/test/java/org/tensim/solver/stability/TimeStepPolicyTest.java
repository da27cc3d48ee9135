package org.tensim.solver.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.Integrators;

/**
 * The time-step policy: the stable RK2 step against the amplification factor and
 * against a real damped spring; how it treats methods without a limit; the reasons.
 */
class TimeStepPolicyTest {
    private static final LinearStability RK2 = ButcherTableau.MIDPOINT;

    private static double amplification(double x, double y) {
        return ButcherTableau.MIDPOINT.stabilityPolynomial().modulus(x, y);
    }

    private static double stable(double omegaMax, double beta, double alpha) {
        return TimeStepPolicy.largestStableStep(RK2, new ModalBounds(omegaMax, beta, alpha, "test"));
    }

    @Test
    void withoutDampingNoStepIsStable() {
        // |1 + z + z^2/2|^2 = 1 + (w h)^4 / 4 on the imaginary axis (docs/physics.md)
        assertEquals(Math.sqrt(1 + Math.pow(0.5, 4) / 4), amplification(0, 0.5), 1e-15);
        // Only steps so small that the growth per step is below round-off pass: w h < 0.01.
        assertTrue(stable(1000, 0, 0) * 1000 < 0.01);
    }

    @Test
    void overdampedRealAxisLimitIsTwo() {
        // For a purely real eigenvalue lambda, RK2 is stable for h |lambda| <= 2.
        assertEquals(1, amplification(-2, 0), 1e-15);
        assertTrue(amplification(-2.01, 0) > 1);
    }

    @Test
    void aDampedSpringStepsStablyAtTheChosenStepAndBlowsUpWellAboveIt() {
        double m = 1e-3;
        double k = 100;
        double w = Math.sqrt(k / m);
        double zeta = 0.3;
        double beta = 2 * zeta / w;
        double h = stable(w, beta, 0);
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
            } catch (org.tensim.solver.SimulationDivergedException e) {
                return Double.POSITIVE_INFINITY; // the simulation's own runaway check saw it blow up
            }
            if (Math.abs(s.state().x[3] - 0.9) > 1e6) {
                break;
            }
        }
        return Math.abs(s.state().x[3] - 0.9) / 0.1;
    }

    @Test
    void stepsAndTheirReasons() {
        ModalBounds m = new ModalBounds(1000, 2 * 0.3 / 1000, 0, "test bound");
        TimeStep rk2 = TimeStepPolicy.recommend("rk2", RK2, true, m);
        assertEquals(stable(1000, 2 * 0.3 / 1000, 0) * TimeStepPolicy.SAFETY, rk2.seconds(), 0);
        assertTrue(rk2.reason().contains("test bound") && rk2.reason().contains("x0.8"), rk2.reason());
        // RK4's stability region is larger than RK2's: a larger step, by its own rule.
        TimeStep rk4 = TimeStepPolicy.recommend("rk4", Integrators.create("rk4").stability(), true, m);
        assertTrue(rk4.seconds() > 1.2 * rk2.seconds(), rk4 + " against " + rk2);
        // Implicit Euler has no limit: the paper's RK2 step, said so.
        TimeStep ie = TimeStepPolicy.recommend("implicit-euler", Integrators.create("implicit-euler").stability(), false, m);
        assertEquals(rk2.seconds(), ie.seconds(), 0);
        assertTrue(ie.reason().contains("no stability limit"), ie.reason());
        // A method that describes nothing and is implicit is treated alike.
        assertEquals(rk2.seconds(), TimeStepPolicy.recommend("new-implicit", null, false, m).seconds(), 0);
        // Undamped: symplectic Euler's 2 / w_max, RK2's real-axis 2 / w_max, RK4's 2 sqrt(2) / w_max, each x0.8.
        ModalBounds u = new ModalBounds(1000, 0, 0, "test");
        assertEquals(2 / 1000.0 * 0.8, TimeStepPolicy.recommend("symplectic-euler",
                Integrators.create("symplectic-euler").stability(), true, u).seconds(), 1e-15);
        assertEquals(2 / 1000.0 * 0.8, TimeStepPolicy.recommend("rk2", RK2, true, u).seconds(), 1e-15);
        assertEquals(2 * Math.sqrt(2) / 1000 * 0.8, TimeStepPolicy.recommend("rk4",
                Integrators.create("rk4").stability(), true, u).seconds(), 1e-15);
    }

    @Test
    void aGivenStepIsTakenAndABadOneNamed() {
        ModalBounds m = new ModalBounds(1000, 1e-4, 0, "test");
        TimeStep given = TimeStepPolicy.choose(1e-3, "--dt", "rk2", RK2, true, m);
        assertEquals(1e-3, given.seconds(), 0);
        assertEquals("given (--dt)", given.reason());
        assertEquals(TimeStepPolicy.recommend("rk2", RK2, true, m), TimeStepPolicy.choose(0, "--dt", "rk2", RK2, true, m));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TimeStepPolicy.choose(-1, "--dt", "rk2", RK2, true, m));
        assertTrue(e.getMessage().contains("--dt") && e.getMessage().contains("-1"), e.getMessage());
    }

    /** Every registered method gets a finite, positive recommended step on a damped scene. */
    @Test
    void everyRegisteredMethodGetsAStep() {
        ModalBounds m = new ModalBounds(1000, 2 * 0.3 / 1000, 1, "test");
        for (String name : Integrators.names()) {
            Integrator in = Integrators.create(name);
            TimeStep s = TimeStepPolicy.recommend(name, in.stability(), in.explicit(), m);
            assertTrue(s.seconds() > 0 && Double.isFinite(s.seconds()) && s.reason().startsWith(name), name + ": " + s);
        }
    }

    /** A state without known damping: the undamped limits over the power estimate of w_max, x0.8. */
    @Test
    void aSimulationAsksThePolicyWithItsOwnEstimate() {
        Simulation sim = new Simulation(org.tensim.solver.SystemState.compile(
                org.tensim.scene.LatticeScene.build(4, 0.1, 1, 1000, 0, false)), Integrators.create("symplectic-euler"));
        CriticalTimeStep c = sim.state().criticalTimeStep();
        TimeStep se = sim.recommendedTimeStep();
        assertEquals(0.8 * c.stepSeconds(), se.seconds(), 1e-15 * se.seconds());
        assertTrue(se.reason().contains("power iteration"), se.reason());
        sim.setIntegrator(Integrators.create("rk4"));
        assertEquals(0.8 * c.forLimit(2 * Math.sqrt(2)), sim.recommendedTimeStep().seconds(), 1e-15);
    }
}
