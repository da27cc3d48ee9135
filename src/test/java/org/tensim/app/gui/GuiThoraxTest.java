package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.GraphicsEnvironment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.solver.integrators.Integrators;
import org.tensim.testsupport.CoarseMeshes;

/**
 * {@code tensim gui --thorax}: the decimated BodyParts3D diaphragm of {@code ThoraxCommandTest} in the shared thorax
 * opens, plays two seconds of wall time (or until its first step) and reports the live readouts (dome descent, contact area, penetration,
 * attached area) in its closing line. With a thorax the window opens with the thorax's real-time setting
 * ({@code bdf2-contact-realtime}: 1 Newton x 8 CG at 25 ms, the links tied in the preconditioner; docs/thorax.md,
 * "Real time in the thorax"), not the double dome's real-time step that drifts there. Skipped where
 * {@code ../shared} or a display is absent.
 */
class GuiThoraxTest {
    static final Path THORAX = org.tensim.testsupport.SharedData.THORAX;
    static final Path MESH = org.tensim.testsupport.SharedData.BODYPARTS3D_DIAPHRAGM;

    @TempDir
    Path dir;

    @Test
    @Tag("gui")
    void theThoraxOpensRunsAndReportsItsReadouts() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        Path mesh = CoarseMeshes.faceByFace(MESH, 0.006, dir.resolve("coarse.obj"));
        Map<String, Object> m = GuiCommandTest.scriptedSummary("gui", "--mesh", mesh.toString(), "--units", "mm",
                "--thorax", THORAX.toString(), "--config-dir", dir.toString(), "--fresh", "--run-for", "2");
        System.out.println("gui --thorax: " + m);
        assertEquals("diaphragm", m.get("scene"));
        assertEquals(Integrators.CONTACT_REAL_TIME, m.get("integrator"), m.toString());
        assertEquals(Integrators.REAL_TIME_STEP_S, ((Number) m.get("dt_s")).doubleValue(), 1e-12, m.toString());
        assertTrue(((Number) m.get("steps")).longValue() > 0, m.toString());
        for (String key : new String[] {"right_dome_descent_mm", "left_dome_descent_mm", "contact_area_mm2",
            "bone_penetration_mm", "max_bone_penetration_mm", "cartilage_marker_cranial_mm"}) {
            assertTrue(m.get(key) instanceof Number, key + " in " + m);
        }
        assertTrue(((Number) m.get("attached_area_mm2")).doubleValue() > 1000, m.toString());
        assertTrue(((Number) m.get("tendon_area_percent")).doubleValue() > 5, m.toString());
    }

    /**
     * {@code tensim gui --cage surfaces} (a coarse generated dome among the swept cage's bones) opens at the
     * real-time step, which holds there with the contact projection (docs/thorax.md), not the thorax's converged one.
     */
    @Test
    @Tag("gui")
    void theSweptCageOpensAtTheRealTimeStep() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Map<String, Object> m = GuiCommandTest.scriptedSummary("gui", "--cage", "surfaces", "--rings", "12",
                "--config-dir", dir.toString(), "--fresh", "--run-for", "2");
        assertEquals(Integrators.REAL_TIME, m.get("integrator"), m.toString());
        assertEquals(Integrators.REAL_TIME_STEP_S, ((Number) m.get("dt_s")).doubleValue(), 1e-12, m.toString());
        assertTrue(((Number) m.get("steps")).longValue() > 0, m.toString());
        assertTrue(m.get("contact_area_mm2") instanceof Number, m.toString());
    }
}
