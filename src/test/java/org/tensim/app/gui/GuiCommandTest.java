package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.GraphicsEnvironment;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.app.Main;
import org.tensim.tuning.TunableScenes;
import picocli.CommandLine;

class GuiCommandTest {
    private static final int USAGE = org.tensim.io.RunStatus.USAGE_EXIT;

    @TempDir
    Path dir;

    static int run(StringWriter err, String... args) {
        CommandLine cl = Main.commandLine();
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    /**
     * Runs a scripted {@code gui} command ({@code --run-for}, whose summary is its last line on stdout), checks that
     * it exits 0, and returns that summary.
     */
    static java.util.Map<String, Object> scriptedSummary(String... args) throws Exception {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        java.io.PrintStream saved = System.out;
        StringWriter err = new StringWriter();
        int code;
        System.setOut(new java.io.PrintStream(out, true, java.nio.charset.StandardCharsets.UTF_8));
        try {
            code = run(err, args);
        } finally {
            System.setOut(saved);
        }
        String printed = out.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertEquals(0, code, err + printed);
        String[] lines = printed.trim().split("\\R");
        return org.tensim.io.Json.mapper().readValue(lines[lines.length - 1],
                new com.fasterxml.jackson.core.type.TypeReference<java.util.Map<String, Object>>() { });
    }

    @Test
    void badSceneOrMeshIsRefusedWithTheValueNamed() {
        StringWriter err = new StringWriter();
        // An option value out of its range is a usage error (docs/outputs.md: exit code 2).
        assertEquals(2, run(err, "gui", "--scene", "teapot"));
        assertTrue(err.toString().contains("'teapot'") && err.toString().contains("cube"), err.toString());
        StringWriter err2 = new StringWriter();
        assertEquals(2, run(err2, "gui", "--scene", "cube", "--mesh", "organ.obj"));
        assertTrue(err2.toString().contains("organ.obj"), err2.toString());
        StringWriter err3 = new StringWriter();
        assertEquals(1, run(err3, "gui", "--scene", "diaphragm", "--mesh", dir.resolve("none.obj").toString()));
        assertTrue(err3.toString().contains("none.obj") && err3.toString().contains("no such file"), err3.toString());
        StringWriter err4 = new StringWriter();
        assertEquals(2, run(err4, "gui", "--scene", "diaphragm", "--resolution", "1"));
        assertTrue(err4.toString().contains("--resolution"), err4.toString());
        StringWriter err5 = new StringWriter();
        assertEquals(2, run(err5, "gui", "--scene", "diaphragm", "--muscle-load", "fibers"));
        assertTrue(err5.toString().contains("--muscle-load") && err5.toString().contains("'fibers'")
                && err5.toString().contains("fibres"), err5.toString());
        StringWriter err6 = new StringWriter();
        assertEquals(2, run(err6, "gui", "--scene", "cube", "--muscle-load", "fibres"));
        assertTrue(err6.toString().contains("--muscle-load") && err6.toString().contains("cube"), err6.toString());
    }

    @Test
    void theDiaphragmOpensAtThePapersResolutionWithTheLargeStepSolver() {
        GuiCommand c = new GuiCommand();
        new CommandLine(c).parseArgs();
        assertEquals(org.tensim.scene.diaphragm.DiaphragmSpec.PAPER_RINGS,
                c.options.spec(null, TunableScenes.defaultRings()).mesh().rings(),
                "no pick is read unless --pick names one: the paper's 43 rings");
        assertEquals("diaphragm", c.scene);
        assertTrue(TunableScenes.opensInRealTime("diaphragm") && !TunableScenes.opensInRealTime("cube"));
    }

    @Test
    void badRunForOrThreadsIsRefusedWithTheValueNamed() {
        for (String bad : new String[] {"0", "-2", "NaN"}) {
            StringWriter err = new StringWriter();
            assertEquals(USAGE, run(err, "gui", "--scene", "cube", "--run-for", bad));
            assertTrue(err.toString().contains("--run-for") && err.toString().contains(bad), err.toString());
        }
        StringWriter err = new StringWriter();
        assertEquals(USAGE, run(err, "gui", "--scene", "cube", "--threads", "-1"));
        assertTrue(err.toString().contains("--threads") && err.toString().contains("-1"), err.toString());
    }

    @Test
    @Tag("gui")
    void runForClosesTheWindowAndPrintsWhatItMeasuredAsTheLastLine() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        java.util.Map<String, Object> m = scriptedSummary("gui", "--scene", "cube", "--config-dir", dir.toString(),
                "--fresh", "--run-for", "1.5", "--unpaced");
        assertEquals("cube", m.get("scene"));
        assertEquals(40, ((Number) m.get("nodes")).intValue(), "the two cubes' 2 x 20 nodes");
        assertEquals("rk2", m.get("integrator"));
        assertEquals(false, m.get("paced"));
        double wall = ((Number) m.get("wall_s")).doubleValue();
        // It closed by itself (the command returned); no upper bound on the wall time, which load stretches.
        assertTrue(wall >= 1.5, "ran its 1.5 s: " + m);
        double dt = ((Number) m.get("dt_s")).doubleValue();
        double sim = ((Number) m.get("sim_s")).doubleValue();
        long steps = ((Number) m.get("steps")).longValue();
        assertTrue(steps > 0 && ((Number) m.get("frames")).longValue() > 0, "it ran and drew: " + m);
        // The figures are consistent with one another: simulated time is steps x dt, rates are per wall second.
        assertEquals(steps * dt, sim, 2 * dt, m.toString());
        // (wall_s is rounded to 1 ms in the summary: 1e-3 relative.)
        double rtf = ((Number) m.get("realtime_factor")).doubleValue();
        assertEquals(sim / wall, rtf, 1e-3 * rtf + 1e-4, m.toString());
        double sps = ((Number) m.get("steps_per_s")).doubleValue();
        assertEquals(steps / wall, sps, 1e-3 * sps + 0.1, m.toString());
        double fps = ((Number) m.get("fps")).doubleValue();
        assertEquals(((Number) m.get("frames")).doubleValue() / wall, fps, 1e-3 * fps + 0.1, m.toString());
        assertEquals(null, m.get("diverged"));
        assertTrue(m.containsKey("error_estimate") && m.containsKey("edt_longest_delay_ms"), m.toString());
    }

    /**
     * A pick given with {@code --pick}: the mechanics at its rings carry the 43-ring mesh, drawn; the title and the
     * summary name the pick, its error and its file; a pick of another scene is refused.
     */
    @Test
    @Tag("gui")
    void aPickNamedRunsTheMechanicsAtItsRingsCarryingThePapersMesh() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Path pick = dir.resolve("picked.json");
        org.tensim.io.Json.write(pick, java.util.Map.of("format", "tensim-resolution-pick", "rings", 6,
                "relative_rms_error", 0.04, "tolerance", 0.1, "reason", "the coarsest within 10 %", "scene",
                org.tensim.experiment.diaphragm.ResolutionPick.sceneOf(
                        org.tensim.scene.diaphragm.DiaphragmSpec.defaults())));
        java.util.Map<String, Object> m = scriptedSummary("gui", "--pick", pick.toString(), "--config-dir",
                dir.toString(), "--fresh", "--run-for", "1");
        assertEquals(pick.toString(), ((java.util.Map<?, ?>) m.get("resolution_pick")).get("source"));
        assertEquals(0.04, ((Number) m.get("resolution_error")).doubleValue(), 1e-12);
        assertEquals(11_354, ((Number) m.get("drawn_nodes")).intValue(), "the paper's mesh is drawn");
        java.util.Map<String, Object> six = scriptedSummary("gui", "--rings", "6", "--config-dir", dir.toString(),
                "--fresh", "--run-for", "1");
        assertEquals(six.get("drawn_nodes"), m.get("mechanical_nodes"), "the pick's 6 rings run, as --rings 6");
        assertEquals(six.get("drawn_nodes"), six.get("mechanical_nodes"), "--rings 6 runs unmapped");
        assertTrue(String.valueOf(m.get("window_title")).contains(pick.toString()), m.toString());
        assertEquals(null, six.get("resolution_pick"));

        Path other = dir.resolve("other.json");
        org.tensim.io.Json.write(other, java.util.Map.of("format", "tensim-resolution-pick", "rings", 6,
                "relative_rms_error", 0.04, "tolerance", 0.1, "reason", "r", "scene", java.util.Map.of("mesh",
                        "generated double dome", "muscle_load", "pressure")));
        StringWriter err = new StringWriter();
        assertEquals(1, run(err, "gui", "--pick", other.toString(), "--config-dir", dir.toString(), "--fresh"));
        assertTrue(err.toString().contains("no measured resolution study matches"), err.toString());
    }

    @Test
    void aPickWithRingsOrTheCubeOrMissingIsRefused() {
        Path pick = dir.resolve("absent.json");
        StringWriter err = new StringWriter();
        assertEquals(USAGE, run(err, "gui", "--scene", "cube", "--pick", pick.toString()));
        assertTrue(err.toString().contains("--pick") && err.toString().contains("cube"), err.toString());
        StringWriter err2 = new StringWriter();
        assertEquals(1, run(err2, "gui", "--pick", pick.toString()));
        assertTrue(err2.toString().contains("absent.json") && err2.toString().contains("no such file"),
                err2.toString());
    }

    /** {@code gui --model paper} opens the paper's model (its tissue springs) with the paper's RK2; the default not. */
    @Test
    @Tag("gui")
    void thePaperModelOpensInTheGuiWithThePapersIntegrator() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        java.util.Map<String, Object> paper = runFor("--model", "paper");
        java.util.Map<String, Object> standard = runFor("--model", "default");
        assertEquals("diaphragm", paper.get("scene"));
        assertEquals("rk2", paper.get("integrator"), "the paper's integrator");
        assertEquals(org.tensim.solver.integrators.Integrators.REAL_TIME, standard.get("integrator"));
        // The paper's network on the same mesh: its threshold attachment drives the nodes near the bones itself,
        // where the default's band ties them to anchor nodes of their own; and its tissue is springs.
        assertTrue(((Number) paper.get("nodes")).intValue() < ((Number) standard.get("nodes")).intValue(),
                paper.get("nodes") + " against " + standard.get("nodes"));
        assertTrue(!paper.get("springs").equals(standard.get("springs")), "the paper's tissue springs, not the"
                + " material shell's: " + paper.get("springs") + " against " + standard.get("springs"));
        assertEquals(null, paper.get("diverged"));
        assertTrue(((Number) paper.get("steps")).longValue() > 0, paper.toString());
    }

    private java.util.Map<String, Object> runFor(String... extra) throws Exception {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        java.io.PrintStream saved = System.out;
        StringWriter err = new StringWriter();
        java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("gui", "--rings", "6",
                "--config-dir", dir.toString(), "--fresh", "--run-for", "1.5", "--unpaced"));
        args.addAll(java.util.List.of(extra));
        int code;
        System.setOut(new java.io.PrintStream(out, true, java.nio.charset.StandardCharsets.UTF_8));
        try {
            code = run(err, args.toArray(String[]::new));
        } finally {
            System.setOut(saved);
        }
        assertEquals(0, code, err.toString());
        String[] lines = out.toString(java.nio.charset.StandardCharsets.UTF_8).trim().split("\\R");
        return org.tensim.io.Json.mapper().readValue(lines[lines.length - 1],
                new com.fasterxml.jackson.core.type.TypeReference<java.util.Map<String, Object>>() { });
    }

    @Test
    @Tag("gui")
    void screenshotOptionWritesAPictureOfTheRunningScene() throws Exception {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display: run under Xvfb (./tensim test does)");
        Path png = dir.resolve("shot.png");
        StringWriter err = new StringWriter();
        assertEquals(0, run(err, "gui", "--scene", "cube", "--config-dir", dir.toString(), "--fresh",
                "--screenshot", png.toString(), "--after", "0.5"), err.toString());
        var img = ImageIO.read(png.toFile());
        assertTrue(img.getWidth() > 600 && img.getHeight() > 400, img.getWidth() + "x" + img.getHeight());
        GuiTestSupport.assertDrawn(img, "the window screenshot");
    }
}
