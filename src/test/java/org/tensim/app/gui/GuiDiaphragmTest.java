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
import java.nio.file.Path;
import javax.swing.AbstractButton;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.ParameterBindingTest;

/**
 * The GUI on the diaphragm (coarse, so that it moves quickly): drawn as a shaded
 * surface with muscle and tendon in two colours, the picture changes while it
 * runs, and a control typed into the interface changes the simulation.
 */
@Tag("gui")
class GuiDiaphragmTest {
    @TempDir
    Path dir;

    @BeforeAll
    static void needsDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        GuiCommand.setScripted(true);
    }

    static double apexZ(GuiWindow w) {
        Body b = w.scene().bodies().get(0);
        double[] d = new double[3];
        b.simulation().state().displacement(b.probeNode(), d);
        return d[2];
    }

    static void click(GuiWindow w, String name) throws Exception {
        AbstractButton b = (AbstractButton) GuiWindowTest.find(w.controls(), name);
        onEdt(() -> b.doClick(0));
    }

    @Test
    void diaphragmOpensWithTheLargeStepSolverOnAllCoresAndShowsItsErrorEstimate() throws Exception {
        GuiWindow w = GuiCommand.open(ParameterBindingTest.coarseDiaphragm(), null, dir, null, true, 2, true);
        try {
            waitFor("the diaphragm on screen", () -> w.scene() != null && w.view().framesRendered() > 3);
            assertEquals(Integrators.REAL_TIME, w.tuning().integrator().name());
            assertEquals(Integrators.REAL_TIME_STEP_S, w.runner().timeStep());
            assertEquals(Integrators.REAL_TIME,
                    w.scene().bodies().get(0).simulation().integrator().name(), "the running simulation's");
            assertEquals(2, w.runner().threads(), "--threads 2 reaches the step");
            // BDF2 estimates its error once two steps of the same size are behind it.
            waitFor("an error estimate", () -> Double.isFinite(w.runner().errorEstimate()) && w.runner().steps() > 3);
            double e = w.runner().errorEstimate();
            assertTrue(e >= 0 && e < 1, "a relative error estimate: " + e);
            Thread.sleep(600); // the status bar refreshes every 250 ms
            String[] text = new String[1];
            onEdt(() -> text[0] = w.status().numbersText());
            assertTrue(text[0].contains("real-time x") && text[0].contains("error ~"), text[0]);
        } finally {
            onEdt(w::close);
        }
    }

    /**
     * --period, --rib-amplitude and --muscle-action start the controls at their values, over what was used last
     * (saved here with other values first): the first scene breathes at the period typed.
     */
    @Test
    void breathingOptionsOnTheCommandLineWinOverTheLastUsedControls() throws Exception {
        java.util.Map<String, java.util.Map.Entry<String, Double>> given = java.util.Map.of(
                DiaphragmViewScene.BREATHING_PERIOD, java.util.Map.entry("--period", 6.0),
                DiaphragmViewScene.RIB_AMPLITUDE, java.util.Map.entry("--rib-amplitude", 0.5));
        org.tensim.tuning.Tuning last = new org.tensim.tuning.Tuning("diaphragm", DiaphragmViewScene.PARAMETERS,
                1e-4, true, org.tensim.solver.integrators.Integrators.choices());
        last.set(DiaphragmViewScene.BREATHING_PERIOD, 8);
        last.set(DiaphragmViewScene.RIB_AMPLITUDE, 2);
        org.tensim.tuning.PresetFile.write(org.tensim.tuning.ConfigDir.lastUsed(dir, "diaphragm"), last.snapshot());
        GuiWindow w = GuiCommand.open(ParameterBindingTest.coarseDiaphragm(), dir, null, null, false, 1, false, false,
                false, given);
        try {
            waitFor("the diaphragm on screen", () -> w.scene() != null);
            assertEquals(6.0, w.tuning().get(DiaphragmViewScene.BREATHING_PERIOD));
            assertEquals(0.5, w.tuning().get(DiaphragmViewScene.RIB_AMPLITUDE));
            org.tensim.scene.diaphragm.DiaphragmScene s = ((DiaphragmViewScene) w.scene()).scene();
            assertEquals(6.0, s.spec().breathing().periodS(), "the scene breathes at the period typed");
            assertEquals(6.0, s.cycle().periodS());
        } finally {
            onEdt(w::close);
        }
        var e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> GuiCommand.open(
                ParameterBindingTest.coarseDiaphragm(), null, null, null, false, 1, false, false, false,
                java.util.Map.of(DiaphragmViewScene.BREATHING_PERIOD, java.util.Map.entry("--period", 40.0))));
        assertTrue(e.getMessage().startsWith("--period 40.0: "), e.getMessage());
    }

    @Test
    void saveLabelsWritesTheDiaphragmOnScreenNeverOverAFileUnaskedAndTheReadoutsShow() throws Exception {
        GuiWindow w = GuiCommand.open(ParameterBindingTest.coarseDiaphragm(), null, dir, null, false);
        try {
            waitFor("the diaphragm on screen", () -> w.scene() != null && w.view().framesRendered() > 3);
            java.nio.file.Path file = dir.resolve("gui.labels");
            boolean[] saved = new boolean[2];
            onEdt(() -> saved[0] = w.labels().saveLabels(file, false));
            assertTrue(saved[0], "saved");
            byte[] first = java.nio.file.Files.readAllBytes(file);
            onEdt(() -> saved[1] = w.labels().saveLabels(file, false));
            assertFalse(saved[1], "an existing file is not replaced unasked");
            org.junit.jupiter.api.Assertions.assertArrayEquals(first, java.nio.file.Files.readAllBytes(file));
            org.tensim.scene.diaphragm.DiaphragmScene s = ((DiaphragmViewScene) w.scene()).scene();
            org.tensim.io.mesh.VertexLabel[] read = org.tensim.io.mesh.VertexLabelsFile.read(file, s.diaphragmNodes());
            for (int v = 0; v < read.length; v++) {
                assertEquals(s.isAttached(v), read[v].isOrigin(), "vertex " + v);
                assertEquals(s.isTendon(v) && !s.isAttached(v), read[v] == org.tensim.io.mesh.VertexLabel.TENDON,
                        "vertex " + v);
            }
            Thread.sleep(600); // the readouts refresh every 250 ms
            String[] shown = new String[2];
            onEdt(() -> {
                shown[0] = w.live().shown("Right dome descent");
                shown[1] = w.live().shown("Tendon share of upper surface");
            });
            assertEquals("0.00", shown[0], "at rest");
            assertEquals(String.format(java.util.Locale.ROOT, "%.2f", 100 * s.tendonAreaFraction()), shown[1]);
        } finally {
            onEdt(w::close);
        }
    }

    /** A click at the middle of the view, as the brush's mouse listener turns it into a ray, paints the mesh there. */
    @Test
    void theLabelBrushPaintsWhereTheViewPointsAndTheRunRestartsWithThePaintedLabels() throws Exception {
        GuiWindow w = GuiCommand.open(ParameterBindingTest.coarseDiaphragm(), null, dir, null, false);
        try {
            waitFor("the diaphragm on screen", () -> w.scene() != null && w.view().framesRendered() > 3);
            DiaphragmViewScene before = (DiaphragmViewScene) w.scene();
            int[] painted = new int[1];
            onEdt(() -> {
                org.jogamp.java3d.Canvas3D c = w.view().canvas();
                double[][] ray = BrushPanel.ray(c, c.getWidth() / 2, c.getHeight() / 2);
                painted[0] = w.labels().stroke(ray[0], ray[1], org.tensim.io.mesh.VertexLabel.TENDON, 0.04);
            });
            assertTrue(painted[0] > 0, "the ray through the view's middle meets the diaphragm: " + painted[0]);
            waitFor("the run restarted with the painted labels", () -> w.scene() != before && w.scene() != null);
            org.tensim.scene.diaphragm.DiaphragmScene after = ((DiaphragmViewScene) w.scene()).scene();
            assertTrue(after.tendonAreaFraction() > before.scene().tendonAreaFraction(), after.tendonAreaFraction()
                    + " against " + before.scene().tendonAreaFraction());
            org.tensim.io.mesh.VertexLabel[] kept = org.tensim.io.mesh.VertexLabelsFile.read(
                    dir.resolve("painted.labels"), after.diaphragmNodes());
            for (int v = 0; v < kept.length; v++) {
                assertEquals(kept[v] == org.tensim.io.mesh.VertexLabel.TENDON, after.isTendon(v), "vertex " + v);
            }
        } finally {
            onEdt(w::close);
        }
    }

    @Test
    void diaphragmIsDrawnMovesAndRespondsToTheMuscleControl() throws Exception {
        GuiWindow w = GuiCommand.open(ParameterBindingTest.coarseDiaphragm(), null, dir, null, true);
        try {
            waitFor("the diaphragm on screen", () -> w.scene() != null && w.view().framesRendered() > 3);
            assertTrue(w.scene() instanceof DiaphragmViewScene);
            click(w, "realtime"); // as fast as possible: it moves sooner
            click(w, "layer.vectors"); // displacement vectors x100 make small motions visible
            waitFor("some breathing", () -> w.view().shownTime() > 0.05);
            BufferedImage a = w.view().capture();
            assertDrawn(a, "the diaphragm");
            int[] colours = GuiSurfaceTest.musclePixelsAndTendonPixels(a);
            assertTrue(colours[0] > 300 && colours[1] > 30, "muscle (red) and tendon (pale) on screen: " + colours[0]
                    + " red, " + colours[1] + " pale pixels");
            double t0 = w.view().shownTime();
            waitFor("more breathing", () -> w.view().shownTime() > t0 + 0.05);
            Thread.sleep(100);
            BufferedImage b = w.view().capture();
            int changed = differingPixels(a, b);
            assertTrue(changed > 200, "the picture must change while it breathes; " + changed + " pixels changed");

            // The muscle control, through its field: the same 100 steps from rest with more muscle action
            // pull the dome apex further down.
            click(w, "play");
            click(w, "reset");
            waitFor("the reset", () -> w.runner().steps() == 0 && w.runner().simTime() == 0);
            GuiWindowTest.clickSteps(w, 100);
            double quiet = apexZ(w);
            onEdt(() -> w.controls().control(DiaphragmViewScene.MUSCLE_ACTION).enter("30000"));
            assertEquals(30000, w.tuning().get(DiaphragmViewScene.MUSCLE_ACTION));
            click(w, "reset");
            waitFor("the reset", () -> w.runner().steps() == 0 && w.runner().simTime() == 0);
            GuiWindowTest.clickSteps(w, 100);
            double forced = apexZ(w);
            // 100 steps are 13 ms from rest: the apex has barely moved (the ribs may even lift it a little),
            // but twice the default fibre stress (30 against 15 kPa) must already have pulled it down by more than
            // 0.1 micrometre.
            assertTrue(forced < quiet - 1e-7 && forced < 0, "more muscle action lowers the apex further: " + forced
                    + " m against " + quiet + " m");
            assertEquals(30000, ((DiaphragmViewScene) w.scene()).scene().controls().muscleAmplitudePa(),
                    "the value reaches the rebuilt scene's controls");
        } finally {
            onEdt(w::close);
        }
    }
}
