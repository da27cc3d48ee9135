package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.tensim.app.gui.GuiTestSupport.assertDrawn;
import static org.tensim.app.gui.GuiTestSupport.differingPixels;
import static org.tensim.app.gui.GuiTestSupport.onEdt;
import static org.tensim.app.gui.GuiTestSupport.waitFor;

import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.AbstractButton;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.tuning.Settings;

/**
 * The window as a user sees it: it draws the scene, the picture moves while the
 * simulation runs, controls reach the simulation, presets and last-used
 * parameters work, and closing ends the simulation thread. Needs a display
 * (Xvfb: {@code ./tensim test} provides one); skipped only where there is none.
 */
@Tag("gui")
class GuiWindowTest {
    @TempDir
    Path dir;

    @BeforeAll
    static void needsDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        GuiCommand.setScripted(true);
    }

    static SceneFactory factory() {
        return CubeViewScene.factory();
    }

    static double probeY(GuiWindow w, int body) {
        Body b = w.scene().bodies().get(body);
        double[] d = new double[3];
        b.simulation().state().displacement(b.probeNode(), d);
        return d[1];
    }

    static void clickSteps(GuiWindow w, int n) throws Exception {
        AbstractButton step = (AbstractButton) find(w.controls(), "step");
        for (int i = 0; i < n; i++) {
            onEdt(() -> step.doClick(0));
        }
        waitFor(n + " single steps", () -> w.runner().steps() == n);
    }

    static java.awt.Component find(java.awt.Container c, String name) {
        for (java.awt.Component k : c.getComponents()) {
            if (name.equals(k.getName())) {
                return k;
            }
            if (k instanceof java.awt.Container sub) {
                java.awt.Component f = find(sub, name);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

    /**
     * The frame cap bounds the frames drawn: never more than the cap allows over a stretch of wall time. In the
     * tag {@code timing}, left out of the default run, as every check against a measured time.
     */
    @Test
    @org.junit.jupiter.api.Tag("timing")
    void theFrameCapBoundsTheFramesDrawn() throws Exception {
        GuiWindow w = GuiCommand.open(factory(), null, dir, null, true);
        try {
            waitFor("the first frames", () -> w.scene() != null && w.view().framesRendered() > 3);
            onEdt(() -> w.setFrameCap(10));
            Thread.sleep(300);
            long f0 = w.view().framesRendered();
            long t0 = System.nanoTime();
            Thread.sleep(2000);
            long frames = w.view().framesRendered() - f0;
            double wall = (System.nanoTime() - t0) / 1e9;
            assertTrue(frames <= 10 * wall + 3, frames + " frames in " + wall + " s at a cap of 10 per second");
            assertTrue(frames > 0, "still drawing");
        } finally {
            onEdt(w::close);
        }
    }

    /** The frame cap is the default one (40) at opening, set by the window and by the View menu, and the view keeps drawing. */
    @Test
    void theFrameCapIsSetByTheWindowAndTheMenu() throws Exception {
        GuiWindow w = GuiCommand.open(factory(), null, dir, null, true);
        try {
            waitFor("the first frames", () -> w.scene() != null && w.view().framesRendered() > 3);
            assertEquals(org.tensim.view.SceneView.DEFAULT_FRAME_CAP_FPS, w.view().frameCap(), "40 by default");
            onEdt(() -> w.setFrameCap(10));
            assertEquals(10, w.view().frameCap(), "the window sets it");
            long f0 = w.view().framesRendered();
            waitFor("frames at the cap of 10", () -> w.view().framesRendered() > f0 + 2);
            javax.swing.JMenuItem ten = null;
            for (java.awt.Component c : w.frame().getJMenuBar().getMenu(1).getMenuComponents()) {
                if ("fps.15".equals(c.getName())) {
                    ten = (javax.swing.JMenuItem) c;
                }
            }
            javax.swing.JMenuItem fifteen = ten;
            onEdt(() -> fifteen.doClick(0));
            assertEquals(15, w.view().frameCap(), "the View menu sets it");
        } finally {
            onEdt(w::close);
        }
    }

    @Test
    void drawsMovesAndControlsReachTheSimulation() throws Exception {
        GuiWindow w = GuiCommand.open(factory(), null, dir, null, true);
        try {
            waitFor("the first frames", () -> w.scene() != null && w.view().shownTime() > 0.3);
            BufferedImage a = w.view().capture();
            assertDrawn(a, "the cube scene");
            double t0 = w.view().shownTime();
            waitFor("more simulated time on screen", () -> w.view().shownTime() > t0 + 0.5);
            Thread.sleep(100);
            BufferedImage b = w.view().capture();
            assertDrawn(b, "the cube scene later");
            int changed = differingPixels(a, b);
            assertTrue(changed > 200, "the picture must change while running; " + changed + " pixels changed");
            assertTrue(w.view().framesRendered() > 5);
            onEdt(() -> w.chart().refresh());
            assertTrue(w.chart().sampleCount() > 10, "the chart gets probe samples");

            // Pause through the play button: the simulation stops advancing.
            AbstractButton play = (AbstractButton) find(w.controls(), "play");
            onEdt(() -> play.doClick(0));
            assertFalse(w.runner().isPlaying());

            // Reference run: reset, 300 single steps at the default force amplitude.
            onEdt(() -> ((AbstractButton) find(w.controls(), "reset")).doClick(0));
            waitFor("the reset", () -> w.runner().steps() == 0 && w.runner().simTime() == 0);
            clickSteps(w, 300);
            double reference = probeY(w, 0);
            assertTrue(reference < 0, "the force pushes P down: " + reference);

            // Same run with five times the force, typed into the control as a user would.
            ParameterControl amplitude = w.controls().control(CubeViewScene.FORCE_AMPLITUDE);
            onEdt(() -> amplitude.enter("2000"));
            assertEquals(2000, w.tuning().get(CubeViewScene.FORCE_AMPLITUDE));
            onEdt(() -> ((AbstractButton) find(w.controls(), "reset")).doClick(0));
            waitFor("the reset", () -> w.runner().steps() == 0 && w.runner().simTime() == 0);
            clickSteps(w, 300);
            double stronger = probeY(w, 0);
            assertTrue(stronger < 3 * reference, "five times the force must push P much further: " + stronger
                    + " m against " + reference + " m");

            // Orbit with the mouse (left drag on the canvas) while paused: the picture turns; Reset view
            // brings the initial framing back.
            Thread.sleep(300);
            BufferedImage home = w.view().capture();
            java.awt.Point c = w.view().canvas().getLocationOnScreen();
            int cx = c.x + w.view().canvas().getWidth() / 2;
            int cy = c.y + w.view().canvas().getHeight() / 2;
            java.awt.Robot robot = new java.awt.Robot();
            robot.mouseMove(cx, cy);
            robot.mousePress(java.awt.event.InputEvent.BUTTON1_DOWN_MASK);
            for (int i = 1; i <= 20; i++) {
                robot.mouseMove(cx + 8 * i, cy + 2 * i);
                robot.delay(15);
            }
            robot.mouseRelease(java.awt.event.InputEvent.BUTTON1_DOWN_MASK);
            Thread.sleep(400);
            BufferedImage turned = w.view().capture();
            int moved = differingPixels(home, turned);
            assertTrue(moved > 500, "dragging orbits the view: " + moved + " pixels changed");
            onEdt(() -> ((AbstractButton) find(w.controls(), "resetView")).doClick(0));
            Thread.sleep(400);
            int back = differingPixels(home, w.view().capture());
            assertTrue(back < moved / 10, "Reset view restores the framing: " + back + " pixels differ, against "
                    + moved + " after the drag");

            // A live change without reset reaches every spring of both cubes.
            ParameterControl k = w.controls().control(CubeViewScene.STIFFNESS);
            onEdt(() -> k.enter("1500"));
            waitFor("the stiffness to reach the springs", () -> w.scene().bodies().stream()
                    .allMatch(body -> body.simulation().state().springK[0] == 1500));

            // A refused value through the interface: shown as an error, nothing changes.
            onEdt(() -> k.enter("-3"));
            assertTrue(k.showsError());
            assertEquals(1500, w.tuning().get(CubeViewScene.STIFFNESS));
            assertTrue(w.status().warningText().contains(CubeViewScene.STIFFNESS), w.status().warningText());

            // A malformed preset is refused and the parameters stay as they were.
            Path bad = dir.resolve("bad.json");
            Files.writeString(bad, "{\"scene\":\"cube\",\"parameters\":{\"" + CubeViewScene.DAMPING + "\":\"lots\"}}");
            Settings before = w.tuning().snapshot();
            boolean[] loaded = new boolean[1];
            onEdt(() -> loaded[0] = w.loadPreset(bad));
            assertFalse(loaded[0]);
            assertEquals(before, w.tuning().snapshot());
            assertTrue(w.status().warningText().contains("parameters." + CubeViewScene.DAMPING));

            // Save, change, load back.
            Path good = dir.resolve("good.json");
            onEdt(() -> w.savePreset(good));
            onEdt(() -> k.enter("40"));
            onEdt(() -> loaded[0] = w.loadPreset(good));
            assertTrue(loaded[0]);
            assertEquals(1500, w.tuning().get(CubeViewScene.STIFFNESS));
        } finally {
            onEdt(w::close);
        }
        assertTrue(Files.readString(dir.resolve("last-cube.json")).contains("1500"), "last-used saved on close");

        // Next start restores the last-used parameters into the running simulation.
        GuiWindow again = GuiCommand.open(factory(), dir, dir, null, false);
        try {
            assertEquals(1500, again.tuning().get(CubeViewScene.STIFFNESS));
            assertEquals(2000, again.tuning().get(CubeViewScene.FORCE_AMPLITUDE));
            waitFor("the restored scene", () -> again.scene() != null && again.scene().bodies().stream()
                    .allMatch(body -> body.simulation().state().springK[3] == 1500));
        } finally {
            onEdt(again::close);
        }
        waitFor("the simulation thread to end", () -> Thread.getAllStackTraces().keySet().stream()
                .noneMatch(t -> t.getName().equals("tensim-simulation") && t.isAlive()));
    }
}
