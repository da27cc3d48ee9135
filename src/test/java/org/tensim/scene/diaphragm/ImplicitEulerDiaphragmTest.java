package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.ImplicitEuler;

/**
 * Implicit Euler on the whole diaphragm scene (ribs driven, action lines, tendon links,
 * abdominal support) follows the paper's RK2 solution: at the end of one inspiration of a
 * coarse model its displacement field approaches RK2's from 1 to 0.5 ms, then stays within the
 * bias of its rigid columns (below).
 * (docs/diaphragm.md: at steps of 2.5 ms and more this coarse model ends on another
 * state, 3 mm higher; the real-time study shows it.)
 */
class ImplicitEulerDiaphragmTest {
    @Test
    void followsTheRk2SolutionUpToTheRigidColumnsBias() throws IOException {
        DiaphragmScene scene = SceneFixture.coarse(10, 1, 2600);
        double ti = scene.cycle().inspirationS();
        double[] rk2 = endOfInspiration(scene, null, scene.recommendedTimeStep(), ti);
        double[] coarseStep = endOfInspiration(scene, new ImplicitEuler().setTolerance(1e-8), 1e-3, ti);
        double[] fineStep = endOfInspiration(scene, new ImplicitEuler().setTolerance(1e-8), 5e-4, ti);
        double[] finestStep = endOfInspiration(scene, new ImplicitEuler().setTolerance(1e-8), 2.5e-4, ti);
        double[] rest = scene.newSimulation().state().x0;
        double eCoarse = relativeRms(rest, rk2, coarseStep, scene.diaphragmNodes());
        double eFine = relativeRms(rest, rk2, fineStep, scene.diaphragmNodes());
        double eFinest = relativeRms(rest, rk2, finestStep, scene.diaphragmNodes());
        String errors = eCoarse + " at 1 ms, " + eFine + " at 0.5 ms, " + eFinest + " at 0.25 ms";
        // At 1 ms the coarse model still ends on another branch of the late snap-through
        // (docs/diaphragm.md). Below 0.5 ms the error no longer falls with the step: a bias from
        // stage 1 advancing the shell without the rigid columns, the cause found and fixed in bdf2
        // (LinkTangent) and not yet in implicit Euler (docs/diaphragm.md, "Limitations"). Measured
        // before the transverse shear elements: 0.285, 0.0315, 0.0271 at 1, 0.5, 0.25 ms; with them
        // (which tie the columns' tilt to the faces, so that the columns' absence from stage 1 costs
        // more): 0.105, 0.0215, 0.0452 undamped (2026-11-23 17:18 UTC), the apex within 0.07 mm of RK2's;
        // with their Kelvin-Voigt damping 0.111, 0.0355, 0.0388 (18:17-18:37 UTC).
        assertTrue(eFine < eCoarse, "error falls from 1 to 0.5 ms: " + errors);
        assertTrue(eFine < 0.05 && eFinest < 0.05, "within 5 % of RK2 at 0.5 and 0.25 ms: " + errors);
        int apex = scene.apexNode();
        assertEquals(rk2[3 * apex + 2], finestStep[3 * apex + 2], 0.5e-3, "apex height, m");
    }

    private static double[] endOfInspiration(DiaphragmScene scene, ImplicitEuler integrator, double dt, double t) {
        Simulation sim = scene.newSimulation();
        if (integrator != null) {
            sim.setIntegrator(integrator);
        }
        sim.runUntil(t, dt);
        assertEquals(t, sim.time(), 0.5 * dt);
        return sim.state().x.clone();
    }

    /** sqrt(sum |u - u_ref|^2 / sum |u_ref|^2) over the diaphragm nodes, u = x - rest. */
    private static double relativeRms(double[] rest, double[] ref, double[] x, int nodes) {
        double num = 0;
        double den = 0;
        for (int k = 0; k < 3 * nodes; k++) {
            double ur = ref[k] - rest[k];
            double u = x[k] - rest[k];
            num += (u - ur) * (u - ur);
            den += ur * ur;
        }
        return Math.sqrt(num / den);
    }
}
