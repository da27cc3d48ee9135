package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.SpringScene;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.parallel.Parallelism;

/** The one home of the solver's settings: validated where they enter, and reaching every part they set. */
class SolverSettingsTest {
    @Test
    void defaultsAreThoseOfTheParts() {
        SolverSettings d = SolverSettings.DEFAULTS;
        assertEquals(Severity.WARN, d.stepLimitSeverity());
        assertEquals(Severity.WARN, d.projectionFailureSeverity());
        assertEquals(100, d.energyGrowthLimit());
        assertEquals(100, d.energyCheckInterval());
        assertEquals(RigidLinkProjection.DEFAULT_TOLERANCE, d.projectionTolerance());
        assertEquals(1e-9, d.projectionTolerance());
        assertEquals(200, d.projectionMaxIterations());
        assertEquals(ImplicitEuler.DEFAULT_TOLERANCE, d.cgTolerance());
        assertEquals(1e-12, d.cgTolerance());
        assertEquals(500, d.cgMaxIterations());
        assertEquals(1, d.threads());
        Simulation sim = new Simulation(SystemState.compile(SpringScene.build(10, 0, 0.01)));
        assertEquals(d, sim.settings());
    }

    @Test
    void badValuesAreNamedWhereTheyEnter() {
        SolverSettings d = SolverSettings.DEFAULTS;
        String[][] cases = {
            {message(() -> d.withEnergyCheck(0.5, 100)), "energy growth limit", "0.5"},
            {message(() -> d.withEnergyCheck(100, 0)), "energy check interval", "0"},
            {message(() -> d.withProjection(-1e-9, 10)), "rigid link tolerance", "-1.0E-9"},
            {message(() -> d.withProjection(1e-9, 0)), "rigid link iteration cap", "0"},
            {message(() -> d.withCg(Double.NaN, 10)), "CG tolerance", "NaN"},
            {message(() -> d.withCg(1e-6, -3)), "CG iteration cap", "-3"},
            {message(() -> d.withThreads(0)), "thread count", "0"},
        };
        for (String[] c : cases) {
            assertTrue(c[0].contains(c[1]) && c[0].contains(c[2]), c[0]);
        }
        assertThrows(NullPointerException.class, () -> d.withStepLimitSeverity(null));
    }

    private static String message(Runnable r) {
        return assertThrows(IllegalArgumentException.class, r::run).getMessage();
    }

    @Test
    void applyReachesTheProjectionTheCheckAndTheIntegrator() {
        ImplicitEuler ie = new ImplicitEuler();
        SolverSettings s = SolverSettings.DEFAULTS.withStepLimitSeverity(Severity.ERROR)
                .withProjectionFailureSeverity(Severity.IGNORE).withEnergyCheck(50, 7).withProjection(1e-6, 12)
                .withCg(1e-4, 33).withThreads(2);
        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(3, 0.1, 1, 1000, 0.5, true)), ie, s);
        assertEquals(s, sim.settings());
        assertEquals(1e-4, ie.tolerance());
        assertEquals(33, ie.maxIterations());
        try (Parallelism p = Parallelism.install(sim)) {
            assertEquals(2, p.threads());
            assertSame(p.nodeLoops(), sim.forces().nodeLoops());
        }
        // A change of one setting keeps the others; an integrator's own CG stays unless the CG settings change.
        ie.setTolerance(1e-7);
        sim.apply(sim.settings().withEnergyCheck(1e3, 7));
        assertEquals(1e3, sim.settings().energyGrowthLimit());
        assertEquals(12, sim.settings().projectionMaxIterations());
        assertEquals(1e-7, ie.tolerance());
        sim.apply(sim.settings().withCg(1e-5, 33));
        assertEquals(1e-5, ie.tolerance());
    }

    /** The projection's tolerance and cap are the settings', read at each step. */
    @Test
    void theProjectionStopsAtTheSettingsCapEachStep() {
        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(3, 0.1, 1, 1000, 0.5, true)));
        sim.apply(sim.settings().withProjection(1e-30, 3).withProjectionFailureSeverity(Severity.IGNORE));
        sim.step(1e-3);
        assertEquals(3, sim.projection().iterations(), "an unreachable tolerance: the cap of 3 sweeps");
        sim.apply(sim.settings().withProjection(1e-30, 5));
        sim.step(1e-3);
        assertEquals(5, sim.projection().iterations());
    }
}
