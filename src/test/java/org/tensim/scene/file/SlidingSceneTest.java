package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The pleural sliding: a block between the floor and the ceiling of a rigid box (a cavity) that
 * moves up by 2 mm and sideways by 6 mm and 3 mm over one inspiration of a breathing law. Its top and bottom faces
 * slide on the box: they follow it up exactly (neither separating nor penetrating), and, the sliding being
 * frictionless, the box's sideways motion drags nothing along.
 */
class SlidingSceneTest {
    @TempDir
    Path dir;

    @ParameterizedTest(name = "hard {0}, {1}")
    @CsvSource({"false, implicit-euler, 1e-7", "true, bdf2-contact, 1e-12"})
    void aBlockInAMovingBoxSlidesWithoutFrictionNeitherSeparatingNorPenetrating(boolean hard, String integrator,
            double tolerance) {
        Scene s = SceneFiles.load(dir, "slide.yaml", """
                version: 1
                units: {length: mm}
                bodies:
                  block: {type: volume, box: [10, 10, 10], cell: 5, material: {E: 1 kPa, damping_time: 10 ms}}
                  box:
                    type: rigid
                    box: {min: [-20, 0, -20], max: [30, 10, 30]}
                    cavity: true
                    motion: {type: translation, displacement: [6, 2, 3], law: breath}
                laws:
                  breath: {type: breathing, period: 2 s, inspiration: 0.5}
                regions:
                  floor: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}
                  ceiling: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}
                  pleura: {union: [floor, ceiling]}
                conditions:
                  - {type: sliding, region: pleura, with: box, stiffness: 50 N/m, hard: %s}
                run: {integrator: %s, dt: 5 ms, duration: 1 s}
                """.formatted(hard, integrator));
        SceneBody b = s.bodies().get("block");
        BitSet floor = s.regions().get("floor").in("block");
        BitSet ceiling = s.regions().get("ceiling").in("block");
        assertEquals(2 * 18, b.topology().contacts().size(), "two pairs (both sides) a sliding node");
        Simulation sim = new Simulation(SystemState.compile(b.topology()), Integrators.create(integrator));
        SystemState st = sim.state();
        double worstGap = 0;
        double worstDrag = 0;
        for (long i = 0; i < s.run().steps(); i++) {
            sim.step(s.run().dtS());
            double up = 0.002 * s.laws().get("breath").value(sim.time());
            for (int n = 0; n < st.nodeCount; n++) {
                double y0 = st.x0[3 * n + 1];
                if (floor.get(n)) {
                    worstGap = Math.max(worstGap, Math.abs(st.position(n, 1) - up));
                } else if (ceiling.get(n)) {
                    worstGap = Math.max(worstGap, Math.abs(0.010 + up - st.position(n, 1)));
                }
                worstDrag = Math.max(worstDrag, Math.abs(st.position(n, 0) - st.x0[3 * n]));
                worstDrag = Math.max(worstDrag, Math.abs(st.position(n, 2) - st.x0[3 * n + 2]));
                assertTrue(Double.isFinite(y0));
            }
        }
        double up = 0.002 * s.laws().get("breath").value(sim.time());
        double[] mean = new double[3];
        for (int n = 0; n < st.nodeCount; n++) {
            for (int a = 0; a < 3; a++) {
                mean[a] += (st.position(n, a) - st.x0[3 * n + a]) / st.nodeCount;
            }
        }
        double meanDy = mean[1];
        System.out.printf("sliding (hard %s): box up %.4f mm and 6.7 mm sideways; block up %.6f mm; largest"
                + " separation or penetration %.3g m; mean sideways motion (%.3g, %.3g) m, a node's at most %.3g m%n",
                hard, up * 1e3, meanDy * 1e3, worstGap, mean[0], mean[2], worstDrag);
        assertEquals(0.002, up, 1e-12, "end of inspiration: the box has risen 2 mm");
        assertTrue(worstGap <= tolerance, "the faces stay on the box: " + worstGap + " m");
        assertEquals(up, meanDy, 1e-6, "the block rises with the box");
        // Frictionless: the box's 6.7 mm sideways motion moves the block not at all (its mean, to round-off); a
        // node moves sideways only by the block's own symmetric Poisson bulge as it is lifted (tens of nm).
        assertEquals(0, mean[0], 1e-15, "no drag along x");
        assertEquals(0, mean[2], 1e-15, "no drag along z");
        assertTrue(worstDrag < 1e-6, "a node's sideways motion is the bulge's, not the box's: " + worstDrag + " m");
    }
}
