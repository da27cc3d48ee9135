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
import org.tensim.scene.file.CoupledBodies;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.FileViewScene;
import org.tensim.solver.Simulation;

/**
 * {@code tensim gui FILE}: a scene file opens with its own integrator and step, its volumes drawn by their surfaces;
 * bodies touching each other run in one simulation as {@code tensim run} runs them, and a diaphragm file opens the
 * diaphragm's view.
 */
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

    /** The liver example opens with its parameters' controls and prints its line as every scripted run. */
    @Test
    @Tag("gui")
    void runForOnTheLiverPrintsItsLine() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        org.junit.jupiter.api.Assumptions.assumeTrue(java.nio.file.Files.exists(
                Path.of("../shared/meshes/thorax/liver.obj")), "missing ../shared/meshes/thorax/liver.obj");
        Map<String, Object> m = GuiCommandTest.scriptedSummary("gui", "docs/examples/liver.yaml", "--run-for", "2",
                "--unpaced", "--set", "E=8");
        assertEquals("file-liver", m.get("scene"));
        assertTrue(((Number) m.get("steps")).longValue() > 0, "steps made: " + m);
        assertEquals(null, m.get("diverged"));
    }

    /**
     * Bodies touching each other open as one simulation (the slab and the block with the contact), each body's surface
     * drawn: the line counts the shared lattice's nodes and both surfaces' vertices, at the file's rk2 and 0.2 ms.
     */
    @Test
    @Tag("gui")
    void runForOnBodiesTouchingEachOtherPrintsItsLine() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Scene s = SceneLoader.load(BLOCK_ON_SLAB);
        int nodes = 0;
        for (org.tensim.scene.file.SceneBody b : s.bodies().values()) {
            nodes += b.topology().nodeCount() + b.surface().mesh().vertexCount();
        }
        Map<String, Object> m = GuiCommandTest.scriptedSummary("gui", BLOCK_ON_SLAB.toString(), "--run-for", "2",
                "--unpaced");
        assertEquals("file-block-on-slab", m.get("scene"));
        assertEquals(nodes, ((Number) m.get("nodes")).intValue(), m.toString());
        assertEquals("rk2", m.get("integrator"));
        assertEquals(2e-4, ((Number) m.get("dt_s")).doubleValue(), 1e-15);
        assertTrue(((Number) m.get("steps")).longValue() > 0, "steps made: " + m);
        assertEquals(null, m.get("diverged"));
    }

    /**
     * The window's coupled scene, paused after some hundred steps, holds the positions the headless run's state (the
     * same construction, {@link CoupledBodies#simulations}) reaches in as many steps of the file's step, to the bit:
     * the block has sunk into the slab.
     */
    @Test
    @Tag("gui")
    void theWindowStepsBodiesTouchingEachOtherAsTheHeadlessRun() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        GuiWindow w = GuiCommand.open(FileViewScene.factory(BLOCK_ON_SLAB), null, null, null, true);
        double[] x;
        long steps;
        try {
            GuiTestSupport.waitFor("some hundred steps", () -> w.scene() != null && w.runner().steps() > 300);
            GuiTestSupport.onEdt(() -> w.play(false));
            long[] seen = {-1};
            GuiTestSupport.waitFor("the runner to stop", () -> {
                long n = w.runner().steps();
                boolean still = n == seen[0];
                seen[0] = n;
                sleep(100);
                return still;
            });
            steps = w.runner().steps();
            x = w.scene().bodies().get(0).simulation().state().x.clone();
        } finally {
            GuiTestSupport.onEdt(w::close);
        }
        Simulation headless = CoupledBodies.simulations(CoupledBodies.merge(SceneLoader.load(BLOCK_ON_SLAB)), "rk2")
                .get("slab+block");
        for (long i = 0; i < steps; i++) {
            headless.step(2e-4);
        }
        for (int k = 0; k < x.length; k++) {
            assertEquals(headless.state().x[k], x[k], 0, "position value " + k + " after " + steps + " steps");
        }
        int last = x.length - 2; // the y of the block's last node
        assertTrue(x[last] < headless.state().x0[last] - 1e-5, "the block sank: " + x[last] + " from "
                + headless.state().x0[last]);
    }

    /** The diaphragm example, coarse, opens the diaphragm's view at the file's rk2 and its recommended step. */
    @Test
    @Tag("gui")
    void runForOnTheDiaphragmFilePrintsItsLine() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Map<String, Object> m = GuiCommandTest.scriptedSummary("gui", "docs/examples/diaphragm.yaml", "--set",
                "bodies.diaphragm.rings=6", "--run-for", "2", "--unpaced");
        assertEquals("diaphragm", m.get("scene"));
        assertEquals("rk2", m.get("integrator"));
        assertTrue(String.valueOf(m.get("window_title")).contains("Diaphragm"), m.toString());
        assertTrue(((Number) m.get("steps")).longValue() > 0, "steps made: " + m);
        assertEquals(null, m.get("diverged"));
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static final Path BLOCK_ON_SLAB = Path.of("docs/examples/block-on-slab.yaml");

    /**
     * A scene file's window: one control per named parameter, labelled with its unit (a rebuild one says it
     * restarts); a live value typed in reaches the running springs without a restart, a rebuild one makes a new
     * scene (a finer lattice) from rest.
     */
    @Test
    @Tag("gui")
    void theControlsAreTheFilesParametersLiveOrRebuilding() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Path file = java.nio.file.Files.writeString(dir.resolve("bar.yaml"),
                org.tensim.scene.tunable.FileViewSceneParametersTest.VOLUME);
        GuiWindow w = GuiCommand.open(FileViewScene.factory(file), null, null, null, true);
        try {
            GuiTestSupport.waitFor("the first steps", () -> w.scene() != null && w.runner().steps() > 3);
            assertEquals("E (kPa)", w.controls().control("E").labelText());
            assertEquals("g (m/s^2)", w.controls().control("g").labelText());
            assertEquals("cell (mm), restarts", w.controls().control("cell").labelText());
            org.tensim.solver.Simulation sim = w.scene().bodies().get(0).simulation();
            double k0 = sim.state().springK[0];
            GuiTestSupport.onEdt(() -> w.controls().control("E").enter("6"));
            GuiTestSupport.waitFor("E to reach the springs", () -> Math.abs(sim.state().springK[0] - 2 * k0) < 1e-12 * k0);
            assertTrue(w.scene().bodies().get(0).simulation() == sim, "the same running simulation");
            assertTrue(sim.time() > 0, "not restarted");
            int nodes = sim.state().nodeCount;
            GuiTestSupport.onEdt(() -> w.controls().control("cell").enter("4"));
            GuiTestSupport.waitFor("a finer lattice", () -> w.scene().bodies().get(0).simulation().state().nodeCount
                    > nodes);
            org.tensim.solver.SystemState rebuilt = w.scene().bodies().get(0).simulation().state();
            double kFresh = org.tensim.solver.SystemState.compile(org.tensim.scene.file.SceneLoader.load(file,
                    java.util.List.of("cell=4", "E=6")).bodies().get("v").topology()).springK[0];
            assertEquals(kFresh, rebuilt.springK[0], 0, "the rebuild keeps E = 6 kPa");
        } finally {
            GuiTestSupport.onEdt(w::close);
        }
    }

    @org.junit.jupiter.api.io.TempDir
    Path dir;
}
