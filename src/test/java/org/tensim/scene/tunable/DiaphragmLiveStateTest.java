package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.solver.Simulation;

/**
 * Which colour each node is drawn in, and the readouts, on the generated double dome (no bones: nothing touches).
 * The thorax's contact marks are in {@link ThoraxLiveStateTest}.
 */
class DiaphragmLiveStateTest {
    private static final DiaphragmSpec COARSE = DiaphragmSpec.defaults().withMesh(DiaphragmSpec.Mesh.defaults()
            .withRings(10));

    private static float[] rgb(float[] c, int i) {
        return Arrays.copyOfRange(c, 3 * i, 3 * i + 3);
    }

    @Test
    void markedNodesTakeTheirMarkColourAndTheOthersKeepTheirOwn() {
        float[] own = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f};
        float[][] palette = {null, {0.2f, 0.5f, 1f}, {1, 1, 0}};
        float[] out = new float[own.length];
        LiveState.paint(own, new byte[] {0, 1, 2, 0}, palette, out);
        assertArrayEquals(new float[] {1, 0, 0}, rgb(out, 0));
        assertArrayEquals(palette[1], rgb(out, 1));
        assertArrayEquals(palette[2], rgb(out, 2));
        assertArrayEquals(new float[] {0.5f, 0.5f, 0.5f}, rgb(out, 3));
        // Unmarked again at the next frame: its own colour comes back.
        LiveState.paint(own, new byte[4], palette, out);
        assertArrayEquals(own, out);
    }

    @Test
    void muscleTendonAndAttachedNodesEachHaveTheirOwnColour() {
        DiaphragmViewScene v = (DiaphragmViewScene) DiaphragmViewScene.factory(COARSE).create(true);
        DiaphragmScene s = v.scene();
        float[] c = v.bodies().get(0).vertexColours();
        int[] seen = new int[3];
        for (int i = 0; i < s.diaphragmNodes(); i++) {
            float[] expected = s.isAttached(i) ? DiaphragmViewScene.ATTACHED
                    : s.isTendon(i) ? DiaphragmViewScene.TENDON_COLOUR : DiaphragmViewScene.MUSCLE_COLOUR;
            assertArrayEquals(expected, rgb(c, i), "node " + i);
            seen[s.isAttached(i) ? 0 : s.isTendon(i) ? 1 : 2]++;
        }
        assertTrue(seen[0] > 0 && seen[1] > 0 && seen[2] > 0, Arrays.toString(seen));
        LiveState live = v.liveState();
        List<String> legend = live.legend().stream().map(LiveState.Legend::label).toList();
        assertEquals(List.of("muscle", "central tendon", "attached (origins)"), legend, "no contact without bones");
    }

    @Test
    void domeDescentIsTheFallOfEachDomesTopFromRestAndNothingIsMarkedWithoutBones() {
        DiaphragmViewScene v = (DiaphragmViewScene) DiaphragmViewScene.factory(COARSE).create(true);
        DiaphragmScene s = v.scene();
        Simulation sim = v.bodies().get(0).simulation();
        DiaphragmLiveState live = (DiaphragmLiveState) v.liveState();
        assertEquals(-1, live.readout("Contact area"), "no bones: no contact readout");
        byte[] marks = new byte[sim.state().nodeCount];
        double[] out = new double[live.readouts().size()];
        live.measure(sim, marks, out);
        int right = live.readout("Right dome descent");
        int left = live.readout("Left dome descent");
        assertEquals(0, out[right], 1e-9);
        assertEquals(0, out[left], 1e-9);
        assertEquals(100 * s.tendonAreaFraction(), out[live.readout("Tendon share of upper surface")], 1e-9);
        // Lower the right half of the diaphragm by 4 mm and the left by 1 mm: the tops fall by as much, whether read
        // at a local top or on a midclavicular line.
        double[] bounds = s.surfaces().mesh().bounds();
        double centre = 0.5 * (bounds[0] + bounds[3]);
        for (int i = 0; i < s.diaphragmNodes(); i++) {
            sim.state().x[3 * i + 2] -= sim.state().x[3 * i] < centre ? 0.004 : 0.001;
        }
        live.measure(sim, marks, out);
        assertEquals(4, out[right], 1e-9);
        assertEquals(1, out[left], 1e-9);
        for (byte b : marks) {
            assertEquals(0, b);
        }
    }
}
