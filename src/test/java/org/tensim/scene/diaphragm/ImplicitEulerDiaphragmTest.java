package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.ImplicitEuler;

/**
 * Implicit Euler on the whole diaphragm scene (ribs driven, action lines, tendon links,
 * abdominal support, the material model's rigid columns) converges to the paper's RK2 solution
 * over one inspiration of a coarse model: at 0.5 s, while the dome is still moving, its error
 * falls as the step (first order) from 1 to 0.5 to 0.25 ms, and at the end of inspiration it ends
 * on RK2's state. It does since the rigid links are kept within its step
 * ({@link org.tensim.solver.links.LinkTangent}); before, stage 1 let the shell relax across the
 * columns and the error stopped falling with the step (docs/diaphragm.md).
 *
 * <p>The reference is RK2 at half its policy step (as in {@code DiaphragmBdf2Test}): before the
 * shear elements were damped, RK2 at its policy step was itself 13 % (0.5 s) and 4.6 % (end of
 * inspiration) from it. With them damped RK2 at its policy step and at a quarter of it are 0.024 % and 0.018 %
 * (0.5 s), 0.047 % and 0.022 % (end) from the half step (2026-11-23 18:06-18:20 UTC).
 */
class ImplicitEulerDiaphragmTest {
    static final double MOVING = 0.5; // s, mid-inspiration

    @Test
    void convergesToTheRk2Solution() throws IOException {
        DiaphragmScene scene = SceneFixture.coarse(10, 1, 2600, SceneFixture.PRESSURE);
        double ti = scene.cycle().inspirationS();
        double[] steps = {1e-3, 5e-4, 2.5e-4};
        Simulation rk2 = scene.newSimulation();
        Simulation[] ie = new Simulation[steps.length];
        for (int i = 0; i < steps.length; i++) {
            ie[i] = scene.newSimulation();
            ie[i].setIntegrator(new ImplicitEuler().setTolerance(1e-8));
        }
        double[] rest = rk2.state().x0;
        int nodes = scene.diaphragmNodes();
        double[][] errors = new double[2][steps.length];
        double[] times = {MOVING, ti};
        for (int j = 0; j < times.length; j++) {
            rk2.runUntil(times[j], scene.recommendedTimeStep() / 2);
            for (int i = 0; i < steps.length; i++) {
                ie[i].runUntil(times[j], steps[i]);
                assertEquals(times[j], ie[i].time(), 0.5 * steps[i]);
                errors[j][i] = relativeRms(rest, rk2.state().x, ie[i].state().x, nodes);
            }
        }
        String moving = errors[0][0] + ", " + errors[0][1] + ", " + errors[0][2] + " at 1, 0.5, 0.25 ms";
        String end = errors[1][0] + ", " + errors[1][1] + ", " + errors[1][2] + " at 1, 0.5, 0.25 ms";
        // Measured 2026-11-23 18:06-18:20 UTC: 0.298 %, 0.150 %, 0.078 % at 0.5 s (order 1.0), 0.043 %,
        // 0.044 %, 0.044 % at the end of inspiration (RK2's own floor); before the links entered the
        // step 0.90 %, 0.32 %, 0.13 % at 0.5 s and 11.1 %, 3.6 %, 3.9 % at the end (docs/diaphragm.md).
        assertTrue(errors[0][1] < 0.6 * errors[0][0] && errors[0][2] < 0.6 * errors[0][1],
                "error at 0.5 s falls as the step (first order): " + moving);
        assertTrue(errors[0][2] < 0.002, "within 0.2 % of RK2 at 0.5 s with 0.25 ms: " + moving);
        for (double e : errors[1]) {
            assertTrue(e < 0.001, "within 0.1 % of RK2 at the end of inspiration: " + end);
        }
        int apex = scene.apexNode();
        assertEquals(rk2.state().x[3 * apex + 2], ie[2].state().x[3 * apex + 2], 0.05e-3, "apex height, m");
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
