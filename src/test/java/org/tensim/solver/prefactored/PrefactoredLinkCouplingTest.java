package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.links.RigidPendulum;

/**
 * The rigid links tied in the preconditioner ({@link PrefactoredBdf2#setLinkCoupling}): a preconditioner only, so
 * the converged step is the same and the constrained equilibrium is exact at large steps, while the unconverged
 * step, which the preconditioner shapes, changes.
 */
class PrefactoredLinkCouplingTest {
    private static Simulation coarseDiaphragm(PrefactoredBdf2 bdf2) throws Exception {
        Simulation sim = DiaphragmSetup.generated(8, null, DiaphragmParameters.defaults(), new BreathingCycle(4, 2),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa())).scene().newSimulation();
        sim.setIntegrator(bdf2);
        return sim;
    }

    /** Relative RMS difference of two runs' positions, against the first run's displacement. */
    private static double difference(Simulation a, Simulation b) {
        double diff = 0;
        double disp = 0;
        for (int k = 0; k < a.state().x.length; k++) {
            double d = a.state().x[k] - b.state().x[k];
            double u = a.state().x[k] - a.state().x0[k];
            diff += d * d;
            disp += u * u;
        }
        assertTrue(disp > 0, "the diaphragm moved");
        return Math.sqrt(diff / disp);
    }

    /**
     * A preconditioner only: converged (6 Newton x 60 CG a step), the steps of a coarse diaphragm over half a second
     * of inspiration are the same with and without the links tied, to the solve's tolerance; with one CG iteration a
     * step, which leaves the step to the preconditioner, they differ.
     */
    @Test
    void theConvergedStepIsTheSameWithTheLinksTied() throws Exception {
        Simulation a = coarseDiaphragm(new PrefactoredBdf2().setNewtonIterations(6).setKrylovIterations(60));
        Simulation b = coarseDiaphragm(new PrefactoredBdf2().setNewtonIterations(6).setKrylovIterations(60)
                .setLinkCoupling(1));
        assertTrue(a.state().linkA.length > 0, "the scene has rigid links");
        a.runUntil(0.5, 0.025);
        b.runUntil(0.5, 0.025);
        double converged = difference(a, b);
        System.out.println("link coupling: converged " + converged);
        assertTrue(converged < 1e-6, "converged: relative RMS difference " + converged);
        Simulation c = coarseDiaphragm(new PrefactoredBdf2().setKrylovIterations(1));
        Simulation d = coarseDiaphragm(new PrefactoredBdf2().setKrylovIterations(1).setLinkCoupling(1));
        c.runUntil(0.5, 0.025);
        d.runUntil(0.5, 0.025);
        double oneIteration = difference(c, d);
        System.out.println("link coupling: one CG iteration " + oneIteration);
        assertTrue(oneIteration > 1e-3, "one CG iteration: " + oneIteration + " against " + converged);
    }

    /** The rigid pendulum comes to rest on its constrained equilibrium at large steps with the link tied. */
    @Test
    void comesToRestOnTheConstrainedEquilibriumAtLargeSteps() {
        double theta = RigidPendulum.equilibriumAngle();
        for (double h : new double[] {0.002, 0.05}) {
            Simulation sim = new Simulation(SystemState.compile(RigidPendulum.topology()),
                    new PrefactoredBdf2().setLinkCoupling(1));
            sim.runUntil(40, h);
            assertEquals(theta, RigidPendulum.angle(sim.state().x), 1e-7, "equilibrium angle at h = " + h + " s");
            assertEquals(RigidPendulum.L, Math.hypot(sim.state().x[3], sim.state().x[5]), 1e-9 * RigidPendulum.L);
        }
    }

    /** A change of the coupling after the first step takes effect at the next: a new factor, made once. */
    @Test
    void aChangeAfterTheFirstStepMakesANewFactor() throws Exception {
        PrefactoredBdf2 changed = new PrefactoredBdf2().setKrylovIterations(1);
        Simulation a = coarseDiaphragm(changed);
        Simulation b = coarseDiaphragm(new PrefactoredBdf2().setKrylovIterations(1));
        a.step(0.025);
        b.step(0.025);
        assertEquals(0, difference(a, b), "the same first step");
        changed.setLinkCoupling(1);
        a.runUntil(0.5, 0.025);
        b.runUntil(0.5, 0.025);
        assertTrue(difference(a, b) > 1e-6, "the steps after the change differ: " + difference(a, b));
        assertEquals(1, changed.synchronousFactorisations(), "the new matrix is factored once, at its first step");
    }

    @Test
    void refusesANegativeOrNonFiniteCoupling() {
        for (double c : new double[] {-1, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> new PrefactoredBdf2().setLinkCoupling(c));
            assertTrue(e.getMessage().contains("link coupling must be a finite number >= 0, got " + c),
                    e.getMessage());
        }
    }
}
