package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.tensim.app.gui.GuiTestSupport.onEdt;
import static org.tensim.app.gui.GuiTestSupport.waitFor;

import java.awt.GraphicsEnvironment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.swing.JCheckBox;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.LinearMapping;
import org.tensim.scene.lungs.OrganMeshes;
import org.tensim.scene.lungs.ThoraxOrgans;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.DiaphragmOrgans;
import org.tensim.scene.tunable.DiaphragmOrgansViewScene;
import org.tensim.scene.tunable.DiaphragmViewFactory;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.solver.integrators.Integrators;
import org.tensim.testsupport.CoarseMeshes;
import org.tensim.tuning.DiaphragmOptions;

/**
 * The lungs and the liver in the window ({@code tensim gui --thorax DIR --lungs}), coarse (the decimated BodyParts3D
 * diaphragm of {@code GuiThoraxTest}, organ cells of 30 and 40 mm): the organs' body is drawn, its box in the View
 * panel shows and toggles the organs' layer, and the drawn surface is the lattices' embedded surface at the state's
 * positions, moving as the state moves. Skipped where {@code ../shared} or a display is absent.
 */
class GuiOrgansTest {
    @TempDir
    Path dir;

    @Test
    @Tag("gui")
    void theOrgansAreDrawnFromTheStateAndTheirBoxHidesThem() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Path thorax = GuiThoraxTest.THORAX;
        assumeTrue(Files.isRegularFile(thorax.resolve("parts.json")), thorax.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(GuiThoraxTest.MESH), GuiThoraxTest.MESH + " not found");
        Path mesh = CoarseMeshes.faceByFace(GuiThoraxTest.MESH, 0.006, dir.resolve("coarse.obj"));
        DiaphragmOptions options = DiaphragmOptions.parse(List.of("--mesh", mesh.toString(), "--units", "mm",
                "--thorax", thorax.toString()));
        DiaphragmViewFactory f = DiaphragmViewScene.factory(options.spec(null, 43), null);
        f.setOrgans(new DiaphragmOrgans(OrganMeshes.load(thorax, true),
                ThoraxOrgans.Options.defaults().withCells(0.03, 0.04).withLiver()));
        GuiCommand.setScripted(true);
        GuiWindow w = GuiCommand.open(f, null, null, null, false, 2, false, false, false, java.util.Map.of());
        try {
            waitFor("the organs on screen", () -> w.scene() != null && w.view().framesRendered() > 3);
            DiaphragmOrgansViewScene s = (DiaphragmOrgansViewScene) w.scene();
            assertEquals(Integrators.DEFAULT, w.tuning().integrator().name(), "explicit couplings: rk2");
            assertEquals(List.of(1), s.organBodies());
            assertTrue(s.organNodes() > 100, "organ nodes " + s.organNodes());
            Body mech = s.bodies().get(0);
            Body drawn = s.bodies().get(1);
            int vertices = 0;
            for (var lung : s.organs().lungs()) {
                vertices += lung.surface().vertexCount();
            }
            vertices += s.organs().liver().surface().vertexCount();
            assertEquals(vertices, drawn.nodeCount(), "every lung and liver vertex drawn");
            assertTrue(drawn.triangles().length > 0, "the organs' surfaces drawn");
            double[] db = bounds(mech.simulation().state().x, s.diaphragm().scene().diaphragmNodes());
            double[] ob = bounds(drawn.simulation().state().x, drawn.nodeCount());
            System.out.printf("diaphragm bounds %s mm, organs %s mm%n", java.util.Arrays.toString(db),
                    java.util.Arrays.toString(ob));
            assertTrue(ob[5] > db[5] && ob[2] < db[5], "the organs reach above the diaphragm's top, from below it");

            JCheckBox box = (JCheckBox) GuiWindowTest.find(w.controls(), "layer.organs");
            assertTrue(box.isVisible() && box.isSelected(), "the organs' box shows, ticked");
            assertTrue(w.view().organsShown());
            onEdt(box::doClick);
            assertFalse(box.isSelected());
            assertFalse(w.view().organsShown(), "unticked: the organs' layer hidden");
            onEdt(box::doClick);
            assertTrue(w.view().organsShown(), "ticked again: shown");

            // The drawn surface follows the state: after steps, each drawn vertex is its lattice mapping of the
            // state's positions, and the organs have moved.
            double[] rest = drawn.simulation().state().x.clone();
            for (int i = 0; i < 40; i++) {
                w.runner().stepOnce();
            }
            waitFor("40 steps", () -> w.runner().simTime() >= 40 * w.runner().timeStep() * 0.999);
            Thread.sleep(200);
            LinearMapping lungs = s.organs().lungs().get(0).body().surfaceMapping();
            double[] x = mech.simulation().state().x;
            double[] right = new double[3 * lungs.pointCount()];
            lungs.apply(x, right);
            double[] now = drawn.simulation().state().x;
            double worst = 0;
            double moved = 0;
            for (int k = 0; k < right.length; k++) {
                worst = Math.max(worst, Math.abs(now[k] - right[k]));
                moved = Math.max(moved, Math.abs(now[k] - rest[k]));
            }
            double[] x0 = mech.simulation().state().x0;
            double dome = 0;
            for (int k = 0; k < 3 * s.diaphragm().scene().diaphragmNodes(); k++) {
                dome = Math.max(dome, Math.abs(x[k] - x0[k]));
            }
            System.out.printf("organs: %d nodes, %d drawn vertices; after %.3f s the drawn right lung is its mapping"
                    + " to %.2e m and moved up to %.3e m, the diaphragm %.3e m%n", s.organNodes(), drawn.nodeCount(),
                    w.runner().simTime(), worst, moved, dome);
            assertTrue(worst < 1e-12, "drawn right lung = its lattice mapping of the state: " + worst + " m");
            // The organs start at rest on their pleura (no force at t = 0), so in these first 1 ms they move only as
            // the pleura, under them, starts to move: 1.8e-10 m against the diaphragm's largest 7.9e-6 m when
            // measured. Uncoupled they would not move at all (no load acts on them but the pleura's), and rounding
            // alone moves them by some 1e-16 m.
            assertTrue(dome > 0 && moved > 1e-6 * dome, "the drawn lungs moved with the state: " + moved
                    + " m, the diaphragm " + dome + " m");
            assertTrue(moved < 0.05, "and stayed near the thorax: " + moved + " m");
        } finally {
            onEdt(w::close);
        }
    }

    /** --lungs without a thorax or on the cube, and --liver alone, are usage errors naming the option. */
    @Test
    void organOptionsOutOfPlaceAreRefused() {
        for (String[] args : new String[][] {{"gui", "--lungs"}, {"gui", "--scene", "cube", "--lungs"},
            {"gui", "--liver"}}) {
            java.io.StringWriter err = new java.io.StringWriter();
            assertEquals(2, GuiCommandTest.run(err, args), String.join(" ", args) + ": " + err);
            assertTrue(err.toString().contains(args[args.length - 1]), err.toString());
        }
        java.io.StringWriter err = new java.io.StringWriter();
        GuiCommandTest.run(err, "gui", "--lungs");
        assertTrue(err.toString().contains("--thorax"), "names what --lungs needs: " + err);
    }

    /** Lower then upper corner of the first n points, mm, rounded. */
    private static double[] bounds(double[] x, int n) {
        double[] b = {1e9, 1e9, 1e9, -1e9, -1e9, -1e9};
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                b[a] = Math.min(b[a], Math.round(1e3 * x[3 * i + a]));
                b[3 + a] = Math.max(b[3 + a], Math.round(1e3 * x[3 * i + a]));
            }
        }
        return b;
    }
}
