package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The attachment condition's modes as physics, on a 10 mm block whose base lies on a plate that slides by
 * (3, -1, 2) mm: {@code fix} holds the base where it was whatever the plate does, {@code tie} hangs the block's
 * weight on springs to the points the plate carries from the base's rest points (each within its load over k of
 * them, the springs together carrying the weight), {@code drive} (the default) is checked by RigidScenesTest.
 */
class AttachmentModesTest {
    /** The plate's slide, m. */
    private static final double[] SLIDE = {0.003, -0.001, 0.002};

    @TempDir
    Path dir;

    /** The block under gravity, its base attached to the sliding plate by {@code mode} (and its keys). */
    private Scene block(String mode) {
        return block(dir, 5, mode);
    }

    /** As {@link #block(String)}, the block's lattice of {@code cellMm} cells, the file written in {@code dir}. */
    static Scene block(Path dir, double cellMm, String mode) {
        return SceneFiles.load(dir, "attach.yaml", """
                version: 1
                units: {length: mm}
                bodies:
                  block:
                    type: volume
                    box: [10, 10, 10]
                    cell: %s
                    material: {E: 2 kPa, nu: 0.25, density: 1000 kg/m^3, damping_time: 20 ms}
                  plate:
                    type: rigid
                    box: {min: [-5, -2, -5], max: [15, 0, 15]}
                    motion: {type: translation, displacement: [3, -1, 2], law: go}
                laws:
                  go: {type: ramp, start: 0 s, duration: 0.5 s, from: 0, to: 1}
                regions:
                  base: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}
                conditions:
                  - {type: gravity, acceleration: [0, -9.81, 0]}
                  - {type: attachment, region: base, with: plate, threshold: 0.1, %s}
                run: {integrator: implicit-euler, dt: 0.01 s, duration: 3 s}
                """.formatted(cellMm, mode));
    }

    private static SystemState run(Scene s, SceneBody b) {
        Simulation sim = new Simulation(SystemState.compile(b.topology()), Integrators.create(s.run().integrator()));
        for (long i = 0; i < s.run().steps(); i++) {
            sim.step(s.run().dtS());
        }
        return sim.state();
    }

    @Test
    void aFixedBaseStaysWhereItWasWhileThePlateSlides() {
        Scene s = block("mode: fix");
        SceneBody b = s.bodies().get("block");
        BitSet base = s.regions().get("base").in("block");
        assertEquals(9, base.cardinality());
        Topology t = b.topology();
        assertEquals(9, t.nodes().stream().filter(n -> n.isFixed()).count(), "the base's 9 nodes are fixed");
        assertEquals(27, t.nodeCount(), "no node added");
        SystemState st = run(s, b);
        double worst = 0;
        double sagged = 0;
        for (int n = 0; n < t.nodeCount(); n++) {
            for (int a = 0; a < 3; a++) {
                double moved = Math.abs(st.position(n, a) - st.x0[3 * n + a]);
                if (base.get(n)) {
                    worst = Math.max(worst, moved);
                } else {
                    sagged = Math.max(sagged, moved);
                }
            }
        }
        System.out.printf("attachment fix: base moved %.3g m, the rest of the block up to %.3g m%n", worst, sagged);
        assertEquals(0, worst, 1e-15, "the fixed base does not follow the plate");
        assertTrue(sagged > 1e-5, "the block above it sags under its weight: " + sagged);
    }

    @Test
    void aTiedBaseHangsTheWeightOnSpringsToThePointsThePlateCarries() {
        double k = 5;
        Scene s = block("mode: tie, stiffness: " + k + " N/m, damping: 0.05 N*s/m");
        SceneBody b = s.bodies().get("block");
        BitSet base = s.regions().get("base").in("block");
        Topology t = b.topology();
        assertEquals(36, t.nodeCount(), "one anchor node a tied node");
        assertEquals(9, t.nodes().stream().filter(n -> n.isDriven()).count(), "the anchors are driven");
        assertEquals(0, t.nodes().stream().filter(n -> n.isFixed()).count());
        double mass = 0;
        for (int n = 0; n < 27; n++) { // the block's own nodes (the anchors, driven, carry nothing)
            mass += t.node(n).mass();
        }
        double weight = 9.81 * mass;
        SystemState st = run(s, b);
        double[] carried = new double[3];
        double farthest = 0;
        for (int n = base.nextSetBit(0); n >= 0; n = base.nextSetBit(n + 1)) {
            double off2 = 0;
            for (int a = 0; a < 3; a++) {
                // Where the plate carries the node's rest point, and the spring's pull towards it.
                double want = st.x0[3 * n + a] + SLIDE[a];
                double off = st.position(n, a) - want;
                carried[a] += k * -off;
                off2 += off * off;
            }
            farthest = Math.max(farthest, Math.sqrt(off2));
        }
        System.out.printf("attachment tie: weight %.6g N, carried by the ties (%.3g, %.6g, %.3g) N, farthest node"
                + " %.4g mm from its carried point, weight / k %.4g mm%n", weight, carried[0], carried[1],
                carried[2], farthest * 1e3, weight / k * 1e3);
        // Settled, the ties carry the weight, straight up; no node is further from its carried point than the
        // whole weight over k (each carries a share of it), and they do give.
        assertEquals(weight, carried[1], 0.01 * weight, "the ties carry the weight");
        assertEquals(0, carried[0], 1e-3 * weight, "no sideways pull once settled");
        assertEquals(0, carried[2], 1e-3 * weight, "no sideways pull once settled");
        assertTrue(farthest <= weight / k, "within F / k = " + weight / k + " m: " + farthest);
        assertTrue(farthest > 0.5 * weight / k / base.cardinality(), "the ties stretch: " + farthest);
    }

    @Test
    void anUnknownModeIsRefusedWithTheModes() {
        SceneException e = assertThrows(SceneException.class, () -> block("mode: tied"));
        assertTrue(e.getMessage().contains("\"tied\" is not one of drive, fix, tie, band; did you mean 'tie'?"),
                e.getMessage());
        e = assertThrows(SceneException.class, () -> block("mode: tie"));
        assertTrue(e.getMessage().contains("conditions[1].stiffness: missing: the key is required"), e.getMessage());
        e = assertThrows(SceneException.class, () -> block("mode: fix, stiffness: 5 N/m"));
        assertTrue(e.getMessage().contains("stiffness goes with mode: tie"), e.getMessage());
    }
}
