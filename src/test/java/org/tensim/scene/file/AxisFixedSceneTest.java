package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * {@code fixed} with {@code axes}: a cube's eight corners (edge springs only) whose base is held in z alone, under a
 * gravity with a sideways part, slides sideways as a free body falls, {@code x0 + g t^2 / 2} on x and y (a rigid
 * translation stretches no spring), while its base stays at z = 0 and its top sinks onto it, under rk2 and bdf2 (rk2 to the
 * round-off of g t^2 / 2, bdf2 within 1e-5) and every other integrator.
 */
class AxisFixedSceneTest {
    private static final double[] G = {1.5, -2.0, -9.81};
    private static final double T = 0.5;

    @TempDir
    Path dir;

    private Topology cube(String integrator) {
        Scene s = SceneFiles.load(dir, "c.yaml", "version: 1\n"
                + "bodies:\n  c: {type: cube, side: 1 m, node_mass: 1 kg, stiffness: 100 N/m, damping: 2 N*s/m,"
                + " element: none}\n"
                + "regions:\n  base: {indices: [0, 1, 2, 3]}\n"
                + "conditions:\n  - {type: fixed, region: base, axes: [z]}\n"
                + "  - {type: gravity, acceleration: [" + G[0] + ", " + G[1] + ", " + G[2] + "]}\n"
                + "run: {integrator: " + integrator + ", dt: 1 ms, duration: " + T + " s}\n");
        return s.bodies().get("c").topology();
    }

    private void slidesSidewaysOnItsBase(String integrator, double tolerance) {
        Topology t = cube(integrator);
        SystemState state = SystemState.compile(t);
        Simulation sim = new Simulation(state, Integrators.create(integrator));
        sim.runUntil(T, 1e-3);
        double free = T * T / 2;
        double topSink = 0;
        for (int i = 0; i < 8; i++) {
            for (int a = 0; a < 2; a++) {
                double u = state.x[3 * i + a] - state.x0[3 * i + a];
                assertEquals(G[a] * free, u, tolerance * Math.abs(G[a] * free),
                        integrator + ": node " + i + " axis " + "xy".charAt(a) + " falls freely");
            }
            double uz = state.x[3 * i + 2] - state.x0[3 * i + 2];
            if (i < 4) {
                assertEquals(0, uz, 0, integrator + ": base node " + i + " held in z");
                assertEquals(0, state.v[3 * i + 2], 0, integrator + ": base node " + i + " at rest in z");
            } else {
                topSink += uz / 4;
            }
        }
        // The top on its four columns of 100 N/m each: static sag m g / k = 0.098 m, about which it oscillates.
        System.out.printf("%s: sideways %.6g m (free fall %.6g m), top z %.4g m%n", integrator,
                state.x[0] - state.x0[0], G[0] * free, topSink);
        assertTrue(topSink < -0.01 && topSink > -0.25, integrator + ": the top sinks onto its base: " + topSink);
    }

    @Test
    void aBaseHeldInZSlidesSidewaysUnderRk2() {
        slidesSidewaysOnItsBase("rk2", 1e-9);
    }

    @Test
    void aBaseHeldInZSlidesSidewaysUnderBdf2() {
        slidesSidewaysOnItsBase("bdf2", 1e-5); // 2.2e-6 measured: its start-up step
    }

    /** Every integrator holds the axis; the first-order ones miss g t^2 / 2 by about dt / T (0.2 %). */
    @org.junit.jupiter.params.ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.MethodSource("org.tensim.solver.integrators.Integrators#choiceNames")
    void everyIntegratorHoldsTheAxis(String integrator) {
        slidesSidewaysOnItsBase(integrator, 0.01);
    }
}
