package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The attachment's {@code mode: band} as physics, on a 10 mm block whose base lies on a plate that slides by
 * (3, -1, 2) mm: the ties' total stiffness is the band's stiffness per unit area times the area its nodes carry
 * (k_b times the area the base's nodes carry, converging at first order to the base's, where a tie per node adds
 * stiffness with every node),
 * and hung on them under gravity the block's weight is carried by the ties: at rest, the stiffness-weighted mean
 * of the base's offsets from the points the plate carries is the weight over the total stiffness.
 */
class AttachmentBandModeTest {
    /** The plate's slide, m. */
    private static final double[] SLIDE = {0.003, -0.001, 0.002};
    /** The band's stiffness per unit area, Pa/m. */
    private static final double KB = 1e5;

    @TempDir
    Path dir;

    /** The block of {@link AttachmentModesTest} on its sliding plate, attached by {@code mode}. */
    private Scene block(double cellMm, String mode) {
        return AttachmentModesTest.block(dir, cellMm, mode);
    }

    /** The springs from the block's nodes to the driven anchors: their total stiffness, N/m. */
    private static double tieStiffness(Topology t, int blockNodes) {
        double k = 0;
        for (Spring s : t.springs()) {
            if (s.b() >= blockNodes && t.node(s.b()).isDriven() && s.restLength() == 0) {
                k += s.stiffness();
            }
        }
        return k;
    }

    private static int blockNodes(Topology t) {
        int n = 0;
        while (n < t.nodeCount() && !t.node(n).isDriven()) {
            n++;
        }
        return n;
    }

    @Test
    void theBandsTotalStiffnessIsItsAreasAndConvergesWhereATiePerNodeGrows() {
        double area = 1e-4; // the base, 10 mm x 10 mm
        double[] cells = {5, 2.5, 1.25};
        double[] band = new double[cells.length];
        double[] perNode = new double[cells.length];
        for (int i = 0; i < cells.length; i++) {
            Topology t = block(cells[i], "mode: band, stiffness: " + KB + " Pa/m").bodies().get("block").topology();
            band[i] = tieStiffness(t, blockNodes(t));
            Topology u = block(cells[i], "mode: tie, stiffness: 10 N/m").bodies().get("block").topology();
            perNode[i] = tieStiffness(u, blockNodes(u));
            System.out.printf("band at %.3g mm cells: total %.6g N/m (k_b A %.6g), a tie per node %.6g N/m%n",
                    cells[i], band[i], KB * area, perNode[i]);
        }
        // The base's nodes carry the base and, of the side faces, the half row of cells next to it (the surface's
        // vertices there are carried half by them): k_b (A + P h / 2), P the base's perimeter, converging to k_b A
        // at first order.
        for (int i = 0; i < cells.length; i++) {
            double carriedArea = area + 0.04 * cells[i] * 1e-3 / 2;
            assertEquals(KB * carriedArea, band[i], 1e-9 * KB * carriedArea, "k_b times the carried area at "
                    + cells[i] + " mm");
        }
        double order = Math.log((band[0] - KB * area) / (band[2] - KB * area)) / Math.log(cells[0] / cells[2]);
        System.out.printf("band: measured order of convergence to k_b A %.3f%n", order);
        assertEquals(1, order, 0.05, "first order in the cell size");
        assertTrue(perNode[2] > 5 * perNode[0], "a tie per node grows with the nodes: " + perNode[0] + " to "
                + perNode[2] + " N/m");
    }

    @Test
    void theBlocksWeightHangsOnTheBandsTies() {
        Scene s = block(2.5, "mode: band, stiffness: " + KB + " Pa/m, taper: 0.05");
        SceneBody b = s.bodies().get("block");
        Topology t = b.topology();
        int n = blockNodes(t);
        double mass = 0;
        for (int i = 0; i < n; i++) {
            mass += t.node(i).mass();
        }
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create(s.run().integrator()));
        for (long i = 0; i < s.run().steps(); i++) {
            sim.step(s.run().dtS());
        }
        SystemState st = sim.state();
        double[] carried = new double[3];
        for (Spring sp : t.springs()) {
            if (sp.b() >= n && t.node(sp.b()).isDriven() && sp.restLength() == 0) {
                for (int a = 0; a < 3; a++) {
                    carried[a] += sp.stiffness() * (st.position(sp.b(), a) - st.position(sp.a(), a));
                }
            }
        }
        double weight = 9.81 * mass;
        System.out.printf("band: weight %.6g N, the ties carry (%.3g, %.6g, %.3g) N%n", weight, carried[0],
                carried[1], carried[2]);
        assertEquals(weight, carried[1], 0.02 * weight, "the ties carry the weight at rest");
        assertEquals(0, carried[0], 0.02 * weight);
        assertEquals(0, carried[2], 0.02 * weight);
        BitSet base = s.regions().get("base").in("block");
        for (int i = base.nextSetBit(0); i >= 0; i = base.nextSetBit(i + 1)) {
            assertEquals(st.x0[3 * i] + SLIDE[0], st.position(i, 0), 1e-3, "node " + i + " follows the plate");
        }
    }

    @Test
    void aBandWithoutAStiffnessOrWiderThanItsThresholdIsRefused() {
        SceneException e = assertThrows(SceneException.class, () -> block(5, "mode: band"));
        assertTrue(e.getMessage().contains("stiffness"), e.getMessage());
        e = assertThrows(SceneException.class, () -> block(5, "mode: band, stiffness: 1e5 Pa/m, taper: 0.2"));
        assertTrue(e.getMessage().contains("taper") && e.getMessage().contains("attach.yaml"), e.getMessage());
        e = assertThrows(SceneException.class, () -> block(5, "mode: band, stiffness: 10 N/m"));
        assertTrue(e.getMessage().contains("Pa/m") || e.getMessage().contains("dimension"), e.getMessage());
        e = assertThrows(SceneException.class, () -> block(5, "mode: drive, taper: 0.05"));
        assertTrue(e.getMessage().contains("mode: band"), e.getMessage());
    }
}
