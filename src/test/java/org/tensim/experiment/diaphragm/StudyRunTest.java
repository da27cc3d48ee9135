package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.solver.Simulation;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * A study run's first step is stepped untimed (it carries the prefactored integrator's first factorisation), and
 * is still the trajectory's first step: the run's samples are those of the same scene stepped straight through. A
 * cached reference's speed is timed over enough steps to be a steady state.
 */
class StudyRunTest {
    @Test
    void theUntimedFirstStepIsTheTrajectorysOwn() throws Exception {
        DiaphragmScene scene = DiaphragmSetup.generated(6, null, null, DiaphragmParameters.defaults(),
                BreathingCycle.quiet(), new DiaphragmControls(1, 19000), BoundaryConditions.defaults()).scene();
        double dt = 0.025;
        RealTimeStudy.Config c = new RealTimeStudy.Config("bdf2 at 25 ms / 1 thread", PrefactoredBdf2::new, dt, 1,
                false);
        StudyRun r = StudyRun.simulate(scene, 6, c, 0.2);
        assertEquals(4, r.samples().size(), "a sample every 50 ms");
        assertArrayEquals(new double[] {0.05, 0.1, 0.15, 0.2}, r.sampleTimesS(), 1e-9);
        assertTrue(r.realtimeWall() > 0 && Double.isFinite(r.realtimeWall()), "timed over the steps after the first");

        Simulation sim = scene.newSimulation();
        sim.setIntegrator(new PrefactoredBdf2());
        int nd = scene.diaphragmNodes();
        for (int s = 0; s < 4; s++) {
            sim.runUntil(0.05 * (s + 1), dt);
            double[] d = new double[3 * nd];
            for (int k = 0; k < d.length; k++) {
                d[k] = sim.state().x[k] - sim.state().x0[k];
            }
            assertArrayEquals(d, r.samples().get(s), 0.0, "sample " + s + " is the straight run's, bit for bit");
        }
        assertEquals(8, sim.steps());
        assertTrue(Math.abs(sim.state().x[3 * scene.apexNode() + 2] - sim.state().x0[3 * scene.apexNode() + 2])
                > 1e-5, "the diaphragm moved: the comparison is not of two resting states");
    }

    @Test
    void aCachedReferenceIsTimedOverTwentyStepsAtLeast() {
        assertEquals(20 * 0.005, StudyRun.speedSpanS(0.005), 1e-15, "the thorax's 5 ms reference: 20 steps");
        assertEquals(StudyRun.SPEED_SPAN_S, StudyRun.speedSpanS(8.5e-5), 0.0, "RK2's stable step: 0.02 s, 235 steps");
    }
}
