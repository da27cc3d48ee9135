package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.tensim.app.gui.GuiTestSupport.assertDrawn;
import static org.tensim.app.gui.GuiTestSupport.differingPixels;
import static org.tensim.app.gui.GuiTestSupport.onEdt;
import static org.tensim.app.gui.GuiTestSupport.waitFor;

import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.swing.AbstractButton;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.tuning.MembraneTestScene;
import org.tensim.tuning.Tuning;

/**
 * Shaded two-colour surfaces, the tendon model switch (a rebuild), displacement
 * vectors, and divergence caught and reported.
 */
@Tag("gui")
class GuiSurfaceTest {
    @TempDir
    Path dir;

    @BeforeAll
    static void needsDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        GuiCommand.setScripted(true);
    }

    /** Pixels that are clearly red (muscle) and clearly pale (tendon). */
    static int[] musclePixelsAndTendonPixels(BufferedImage img) {
        int red = 0;
        int pale = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int c = img.getRGB(x, y);
                int r = (c >> 16) & 255;
                int g = (c >> 8) & 255;
                int b = c & 255;
                if (r > 90 && r > 2 * g && r > 2 * b) {
                    red++;
                } else if (r > 150 && g > 150 && b > 120 && Math.abs(r - g) < 40) {
                    pale++;
                }
            }
        }
        return new int[] {red, pale};
    }

    @Test
    void surfaceInTwoColoursAndTendonSwitchRebuilds() throws Exception {
        GuiWindow w = GuiCommand.open(MembraneTestScene.factory(), null, dir, null, true);
        try {
            waitFor("frames", () -> w.scene() != null && w.view().shownTime() > 0.3);
            assertTrue(w.tuning().tensegrityTendon());
            assertTrue(w.scene().bodies().get(0).simulation().state().linkCount() > 0);
            // A scene with a surface starts without the spring wireframe and the nodes (read on the Swing thread,
            // after the scene was shown).
            boolean[] ticked = new boolean[2];
            onEdt(() -> {
                ticked[0] = ((AbstractButton) GuiWindowTest.find(w.controls(), "layer.springs")).isSelected();
                ticked[1] = ((AbstractButton) GuiWindowTest.find(w.controls(), "layer.nodes")).isSelected();
            });
            assertTrue(!ticked[0] && !ticked[1], "springs and nodes hidden at start over a surface");
            Thread.sleep(300);
            BufferedImage img = w.view().capture();
            assertDrawn(img, "the membrane");
            int[] rp = musclePixelsAndTendonPixels(img);
            assertTrue(rp[0] > 500 && rp[1] > 100, "muscle and tendon colours on screen: " + rp[0] + " red, " + rp[1]
                    + " pale pixels");

            // Displacement vectors on: more is drawn.
            onEdt(() -> w.layer("vectors", true));
            Thread.sleep(300);
            assertTrue(differingPixels(img, w.view().capture()) > 50, "vectors drawn");

            // Tendon to mass-spring through the radio button: a new scene without rigid links.
            var before = w.scene();
            AbstractButton ms = (AbstractButton) GuiWindowTest.find(w.controls(), "tendon.massSpring");
            onEdt(() -> ms.doClick(0));
            waitFor("the rebuilt scene", () -> w.scene() != before);
            assertEquals(0, w.scene().bodies().get(0).simulation().state().linkCount());
            assertTrue(!w.tuning().tensegrityTendon());
            waitFor("frames of the new scene", () -> w.view().shownTime() > 0.2);
            assertDrawn(w.view().capture(), "the rebuilt membrane");

            // A parameter that needs a new scene: typed in, the scene is rebuilt with it, the tendon choice kept.
            var third = w.scene();
            onEdt(() -> w.controls().control(MembraneTestScene.GRAVITY).enter("2"));
            waitFor("the scene rebuilt with the new gravity", () -> w.scene() != third);
            assertEquals(-2, w.scene().bodies().get(0).simulation().state().gravity().y(), 0);
            assertEquals(0, w.scene().bodies().get(0).simulation().state().linkCount());
        } finally {
            onEdt(w::close);
        }
    }

    @Test
    void divergenceIsCaughtReportedAndClearedByReset() throws Exception {
        GuiWindow w = GuiCommand.open(CubeViewScene.factory(), null, null, null, true);
        try {
            waitFor("frames", () -> w.scene() != null && w.view().shownTime() > 0.1);
            onEdt(() -> w.controls().control(CubeViewScene.STIFFNESS).enter("10000"));
            onEdt(() -> w.controls().control(Tuning.TIME_STEP).enter("0.05"));
            waitFor("the divergence", () -> w.runner().divergence() != null);
            // The critical step is estimated in the background (CriticalStepWatch): its warning may come later.
            waitFor("the status bar", () -> w.status().warningText().contains("Diverged")
                    && w.status().warningText().contains("critical estimate"));
            String text = w.status().warningText();
            assertTrue(text.contains("critical estimate"), text);
            assertTrue(!w.runner().isPlaying(), "paused on divergence");
            onEdt(() -> w.controls().control(Tuning.TIME_STEP).enter("0.001"));
            onEdt(() -> ((AbstractButton) GuiWindowTest.find(w.controls(), "reset")).doClick(0));
            waitFor("the reset", () -> w.runner().divergence() == null);
            onEdt(() -> ((AbstractButton) GuiWindowTest.find(w.controls(), "play")).doClick(0));
            waitFor("running again", () -> w.runner().simTime() > 0.2);
        } finally {
            onEdt(w::close);
        }
    }
}
