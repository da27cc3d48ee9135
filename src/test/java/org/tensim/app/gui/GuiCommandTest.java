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
import picocli.CommandLine;

class GuiCommandTest {
    @TempDir
    Path dir;

    static int run(StringWriter err, String... args) {
        CommandLine cl = Main.commandLine();
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    @Test
    void badSceneOrMeshIsRefusedWithTheValueNamed() {
        // refused before any output: usage errors (exit 2), as picocli's own
        StringWriter err = new StringWriter();
        assertEquals(org.tensim.io.RunStatus.USAGE_EXIT, run(err, "gui", "--scene", "teapot"));
        assertTrue(err.toString().contains("'teapot'") && err.toString().contains("cube"), err.toString());
        StringWriter err2 = new StringWriter();
        assertEquals(org.tensim.io.RunStatus.USAGE_EXIT, run(err2, "gui", "--scene", "cube", "--mesh", "organ.obj"));
        assertTrue(err2.toString().contains("organ.obj"), err2.toString());
        StringWriter err3 = new StringWriter();
        assertEquals(org.tensim.io.RunStatus.USAGE_EXIT, run(err3, "gui", "--scene", "diaphragm", "--mesh", dir.resolve("none.obj").toString()));
        assertTrue(err3.toString().contains("none.obj") && err3.toString().contains("no such file"), err3.toString());
        StringWriter err4 = new StringWriter();
        assertEquals(org.tensim.io.RunStatus.USAGE_EXIT, run(err4, "gui", "--scene", "diaphragm", "--resolution", "1"));
        assertTrue(err4.toString().contains("--resolution"), err4.toString());
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
