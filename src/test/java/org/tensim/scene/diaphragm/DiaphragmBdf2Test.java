package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.shell.TissueModel;
import org.tensim.solver.Simulation;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The large-step BDF2 solver on a coarse diaphragm with the default (material) tissue model: all of
 * the scene (fixed and driven nodes, the attachment band, the muscle pressure, axial and viscous
 * damping, abdominal support, a rigid column under every upper node), run through the paper's
 * stage loop ({@link Simulation#step}: BDF2, then the rigid-link projection and the velocity update),
 * against the paper's RK2 at the scene's stable step: with small steps it agrees, and the difference
 * falls as the step does.
 */
class DiaphragmBdf2Test {
    static final int RINGS = 10;
    /** Before the snap-throughs of the compressed walls from 0.65 s (see docs/diaphragm.md). */
    static final double SECONDS = 0.6;

    /** Displacements of the diaphragm nodes from rest at {@link #SECONDS}, m (3 per node). */
    static double[] run(DiaphragmScene scene, PrefactoredBdf2 integrator, double dt) {
        return run(scene, integrator, dt, SECONDS);
    }

    /** Displacements of the diaphragm nodes from rest at {@code seconds}, m (3 per node). */
    static double[] run(DiaphragmScene scene, PrefactoredBdf2 integrator, double dt, double seconds) {
        Simulation sim = scene.newSimulation();
        if (integrator != null) {
            sim.setIntegrator(integrator);
        }
        sim.runUntil(seconds, dt > 0 ? dt : scene.recommendedTimeStep());
        double[] d = new double[3 * scene.diaphragmNodes()];
        for (int k = 0; k < d.length; k++) {
            d[k] = sim.state().x[k] - sim.state().x0[k];
        }
        return d;
    }

    /** Relative RMS difference of two displacement fields, against the second. */
    static double relativeRms(double[] d, double[] ref) {
        double num = 0;
        double den = 0;
        for (int k = 0; k < d.length; k++) {
            num += (d[k] - ref[k]) * (d[k] - ref[k]);
            den += ref[k] * ref[k];
        }
        return Math.sqrt(num / den);
    }

    /**
     * On the edge-spring shell ({@link TissueModel#SPRINGS}) with the pressure and the band's former 5 mm
     * taper, the figures this test was written with (with the 1 mm taper, 8 ms read 5.3 %, 2026-11-23).
     */
    @Test
    void agreesWithRk2AtSmallStepsAndConvergesToIt() throws Exception {
        BoundaryConditions bc = new BoundaryConditions(BoundaryConditions.Attachment.BAND,
                BoundaryConditions.DEFAULT_BAND_PA_PER_M, 0.005, BoundaryConditions.MuscleLoad.PRESSURE, true);
        DiaphragmScene scene = SceneFixture.coarse(RINGS, 1, 2600,
                DiaphragmParameters.defaults().withTissueModel(TissueModel.SPRINGS), bc);
        double[] rk2 = run(scene, null, 0);
        double e1 = relativeRms(run(scene, new PrefactoredBdf2(), 1e-3), rk2);
        double e2 = relativeRms(run(scene, new PrefactoredBdf2(), 2e-3), rk2);
        double e8 = relativeRms(run(scene, new PrefactoredBdf2(), 8e-3), rk2);
        // Measured 0.07 %, 0.23 % and 3.4 % (RK2 at half its step: 0.03 %). A stage 1 that ignored the rigid
        // columns (the projection alone kept them) was 1.9 %, 16 % and 28 % off.
        assertTrue(e1 < 0.002, "relative RMS difference at 1 ms: " + e1);
        assertTrue(e2 < 0.01, "relative RMS difference at 2 ms: " + e2);
        assertTrue(e8 < 0.05, "relative RMS difference at 8 ms: " + e8);
        assertTrue(e1 < e2 && e2 < e8, "the difference falls with the step: " + e8 + ", " + e2 + ", " + e1);
    }

    /**
     * On the default material model (membrane triangles and transverse shear elements) at 0.5 s, against
     * RK2 at half its policy step. Before the shear elements (diagonals carrying 3 % of the membrane):
     * 2.2, 1.5, 0.52 % at 1, 0.5, 0.25 ms (2026-11-23 15:09 UTC). With them BDF2 follows RK2 far more
     * closely: measured 2026-11-23 17:17 UTC 0.023 % at 1 ms and 0.020 % at 0.25 ms, a floor (the
     * Krylov tolerance 1e-3 and the reference's own step) that a smaller step does not lower; the
     * step's own error shows at the larger steps, where the difference grows with the step.
     */
    @Test
    void agreesWithRk2OnTheMembraneTrianglesAsTheStepFalls() throws Exception {
        DiaphragmScene scene = SceneFixture.coarse(RINGS, 1, 2600, SceneFixture.PRESSURE);
        double seconds = 0.5;
        double[] rk2 = run(scene, null, scene.recommendedTimeStep() / 2, seconds);
        double e8 = relativeRms(run(scene, new PrefactoredBdf2(), 8e-3, seconds), rk2);
        double e4 = relativeRms(run(scene, new PrefactoredBdf2(), 4e-3, seconds), rk2);
        double e1 = relativeRms(run(scene, new PrefactoredBdf2(), 1e-3, seconds), rk2);
        double eQuarter = relativeRms(run(scene, new PrefactoredBdf2(), 2.5e-4, seconds), rk2);
        String all = e8 + " at 8 ms, " + e4 + " at 4 ms, " + e1 + " at 1 ms, " + eQuarter + " at 0.25 ms";
        assertTrue(e1 < 0.002, "relative RMS difference at 1 ms: " + all);
        assertTrue(eQuarter < 0.002, "relative RMS difference at 0.25 ms: " + all);
        assertTrue(e1 < e4 && e4 < e8, "the difference falls with the step above the floor: " + all);
    }
}
