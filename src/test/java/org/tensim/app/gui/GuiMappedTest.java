package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.tensim.app.gui.GuiTestSupport.onEdt;
import static org.tensim.app.gui.GuiTestSupport.waitFor;

import java.awt.GraphicsEnvironment;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.DiaphragmMappedViewScene;
import org.tensim.scene.tunable.DiaphragmViewFactory;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.TunableScenes;

/**
 * The window with the mechanics coarser than the drawn mesh (coarse settings: 6 rings carrying 10): the fine mesh is
 * drawn and moves with the mechanics, the status bar says which resolution runs and its error, and the full-model
 * switch rebuilds the scene unmapped.
 */
@Tag("gui")
class GuiMappedTest {
    @TempDir
    Path dir;

    @BeforeAll
    static void needsDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        GuiCommand.setScripted(true);
    }

    @Test
    void theFineMeshIsDrawnCarriedByTheMechanicsAndOneSwitchRunsTheFullModel() throws Exception {
        DiaphragmViewFactory f = (DiaphragmViewFactory) TunableScenes.factory("diaphragm",
                DiaphragmOptions.parse(java.util.List.of("--rings", "10")));
        f.mapMechanics(new DiaphragmViewFactory.Mechanics(6, 0.07, "a test's pick"));
        GuiWindow w = GuiCommand.open(f, null, dir, null, true, 1, true);
        try {
            long end = System.nanoTime() + 120_000_000_000L;
            while (!(w.scene() != null && w.view().framesRendered() > 3 && w.runner().simTime() > 0.5)
                    && w.runner().divergence() == null && System.nanoTime() < end) {
                Thread.sleep(20);
            }
            assertTrue(w.runner().simTime() > 0.5, "the mapped diaphragm moving: t = " + w.runner().simTime()
                    + " s, frames " + w.view().framesRendered() + ", divergence " + w.runner().divergence());
            ViewScene s = w.scene();
            assertTrue(s instanceof DiaphragmMappedViewScene, s.getClass().getName());
            ViewScene.Resolution r = s.resolution();
            assertTrue(r.mechanicalNodes() < r.drawnNodes(), r.toString());
            assertEquals(0.07, r.error());
            Body mechanics = s.bodies().get(0);
            Body drawn = s.bodies().get(1);
            assertEquals(0, mechanics.triangles().length, "the mechanics are not drawn");
            assertTrue(drawn.triangles().length > 0);
            // the drawn apex moves down with the mechanics' apex (paused to read both at one step)
            onEdt(() -> w.play(false));
            waitFor("the pause", () -> !w.runner().isPlaying());
            Thread.sleep(200);
            double[] d = new double[3];
            double[] dm = new double[3];
            drawn.simulation().state().displacement(drawn.probeNode(), d);
            mechanics.simulation().state().displacement(mechanics.probeNode(), dm);
            assertTrue(d[2] < -2e-4, "drawn apex displacement " + d[2] + " m at " + w.runner().simTime() + " s,"
                    + " the mechanics' " + dm[2] + " m");
            assertEquals(dm[2], d[2], 0.2 * Math.abs(dm[2]), "the drawn apex against the mechanics' apex");
            onEdt(() -> w.play(true));
            Thread.sleep(600); // the status bar refreshes every 250 ms
            String[] text = new String[1];
            onEdt(() -> text[0] = w.status().resolutionText());
            assertTrue(text[0].contains("7.0 % error") && text[0].contains(String.format(java.util.Locale.ROOT,
                    "%,d", r.drawnNodes())), text[0]);

            GuiDiaphragmTest.click(w, "fullModel");
            waitFor("the full model", () -> w.scene() instanceof DiaphragmViewScene);
            ViewScene.Resolution full = w.scene().resolution();
            assertEquals(r.drawnNodes(), full.mechanicalNodes(), "every drawn node runs: " + full);
            waitFor("the status bar's update", () -> {
                String[] t = new String[1];
                try {
                    onEdt(() -> t[0] = w.status().resolutionText());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
                return t[0].startsWith("full model");
            });
        } finally {
            onEdt(w::close);
        }
    }
}
