package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The large-step BDF2 solver on a coarse diaphragm (all of the scene: fixed and driven nodes,
 * axial and viscous damping, abdominal support, rigid links), against the paper's RK2 at the
 * scene's stable step: with small steps it agrees, and the difference falls as the step does.
 */
class DiaphragmBdf2Test {
    static final int RINGS = 10;
    static final double SECONDS = 0.5;

    /** Displacements of the diaphragm nodes from rest at {@link #SECONDS}, m (3 per node). */
    static double[] run(DiaphragmScene scene, PrefactoredBdf2 integrator, double dt) {
        Simulation sim = scene.newSimulation();
        if (integrator != null) {
            sim.setIntegrator(integrator);
        }
        sim.runUntil(SECONDS, dt > 0 ? dt : scene.recommendedTimeStep());
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

    /** On the edge-spring shell ({@link TissueModel#SPRINGS}), the figures this test was written with. */
    @Test
    void agreesWithRk2AtSmallStepsAndConvergesToIt() throws Exception {
        DiaphragmScene scene = SceneFixture.coarse(RINGS, 1, 2600,
                DiaphragmParameters.defaults().withTissueModel(TissueModel.SPRINGS));
        double[] rk2 = run(scene, null, 0);
        double e1 = relativeRms(run(scene, new PrefactoredBdf2(), 1e-3), rk2);
        double eHalf = relativeRms(run(scene, new PrefactoredBdf2(), 5e-4), rk2);
        // Measured 0.53 % and 0.10 % (10 rings, 0.5 s; 2 ms gives 1.0 %); 1.33 % and 0.45 % on 2026-11-23.
        assertTrue(e1 < 0.02, "relative RMS difference at 1 ms: " + e1);
        assertTrue(eHalf < 0.005, "relative RMS difference at 0.5 ms: " + eHalf);
        assertTrue(eHalf < e1 / 2.5, "halving the step divides the difference by more than 2.5 (second order): "
                + e1 + " -> " + eHalf);
    }

    /**
     * On the membrane triangles (the default material model) BDF2 is further from RK2 at the same
     * steps, Newton converged or not (measured 2026-11-23: 3.4, 2.0, 0.91 % at 1, 0.5, 0.25 ms; 4.5 %
     * at 1 ms with 8 Newton iterations): the difference is BDF2's truncation error on this model, and
     * it still falls with the step.
     */
    @Test
    void agreesWithRk2OnTheMembraneTrianglesAsTheStepFalls() throws Exception {
        DiaphragmScene scene = SceneFixture.coarse(RINGS, 1, 2600);
        double[] rk2 = run(scene, null, 0);
        double e1 = relativeRms(run(scene, new PrefactoredBdf2(), 1e-3), rk2);
        double eHalf = relativeRms(run(scene, new PrefactoredBdf2(), 5e-4), rk2);
        assertTrue(e1 < 0.04, "relative RMS difference at 1 ms: " + e1);
        assertTrue(eHalf < 0.025, "relative RMS difference at 0.5 ms: " + eHalf);
        assertTrue(eHalf < e1 / 1.5, "halving the step: " + e1 + " -> " + eHalf);
    }
}
