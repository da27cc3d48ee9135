package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.FileViewScene;

/** {@code tensim gui FILE}: a scene file opens with its own integrator and step, its volumes drawn by their surfaces. */
class GuiSceneFileTest {
    @Test
    void aVolumeIsItsLatticeThenItsSurfaceCarriedThroughTheMapping() {
        Path file = Path.of("docs/examples/cantilever.yaml");
        Scene s = SceneLoader.load(file);
        var scene = FileViewScene.factory(file).create(true);
        assertEquals(2, scene.bodies().size(), "the lattice, then its surface");
        Body lattice = scene.bodies().get(0);
        Body surface = scene.bodies().get(1);
        var embedded = s.bodies().get("beam").surface();
        assertEquals(embedded.mesh().vertexCount(), surface.nodeCount());
        assertEquals(3 * embedded.mesh().triangleCount(), surface.triangles().length);
        assertEquals("implicit-euler", scene.defaultIntegrator());
        assertEquals(0.5, scene.defaultTimeStep());
        for (int i = 0; i < 3; i++) {
            lattice.simulation().step(0.5);
            surface.simulation().step(0.5);
        }
        double[] expected = new double[3 * surface.nodeCount()];
        embedded.mapping().apply(lattice.simulation().state().x, expected);
        double[] shown = surface.simulation().state().x;
        double moved = 0;
        for (int k = 0; k < expected.length; k++) {
            assertEquals(expected[k], shown[k], 1e-15, "surface value " + k);
            moved = Math.max(moved, Math.abs(shown[k] - surface.simulation().state().x0[k]));
        }
        assertTrue(moved > 0, "the surface moved with the loaded lattice");
    }

    @Test
    void builtInSceneOptionsAreRefusedBesideAFile() {
        StringWriter err = new StringWriter();
        int code = GuiCommandTest.run(err, "gui", "docs/examples/cube.yaml", "--scene", "cube", "--run-for", "1");
        assertTrue(code != 0, "refused");
        assertTrue(err.toString().contains("--scene") && err.toString().contains("scene file"), err.toString());
    }

    @Test
    @Tag("gui")
    void runForOnAScenefilePrintsItsLine() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Map<String, Object> m = GuiCommandTest.scriptedSummary("gui", "docs/examples/cantilever.yaml", "--run-for",
                "2", "--unpaced");
        assertEquals("file-cantilever", m.get("scene"));
        // The lattice's 189 nodes and the surface's 170 (display only).
        assertEquals(189 + 170, ((Number) m.get("nodes")).intValue(), m.toString());
        assertEquals("implicit-euler", m.get("integrator"));
        assertTrue(((Number) m.get("steps")).longValue() > 0, "steps made: " + m);
        assertEquals(null, m.get("diverged"));
    }
}
