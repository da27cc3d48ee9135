package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Spring;

/** The {@code parameters:} block: defaults, units, --set NAME=VALUE with range checks, live or rebuild keys. */
class SceneParametersTest {
    static final String CUBE = String.join("\n",
            "version: 1",
            "bodies:",
            "  c: {type: cube, stiffness: 100 N/m, damping: 2 N*s/m}",
            "regions:",
            "  bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}",
            "  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}",
            "conditions:",
            "  - {type: fixed, region: bottom}",
            "  - {type: force, region: top, direction: [0, -1, 0], magnitude: 40 N}",
            "  - {type: gravity, acceleration: [0, -9.81, 0]}",
            "run: {dt: 1 ms, duration: 0.01 s}",
            "parameters:",
            "  k: {path: bodies.c.stiffness, unit: kN/m, range: [0.01, 1], apply: live, description: spring"
                    + " stiffness}",
            "  force: {path: \"conditions[1].magnitude\", unit: N, range: [0, 100], apply: live}",
            "  g: {path: \"conditions[2].acceleration[1]\", unit: m/s^2, range: [-20, 0], apply: live}",
            "  side: {path: bodies.c.side, unit: cm, range: [100, 2000], apply: rebuild}",
            "  c: {path: bodies.c.damping, unit: N*s/m, range: [0, 10], apply: live}",
            "");

    @TempDir
    Path dir;

    private static double firstSpringStiffness(Scene s) {
        return s.bodies().get("c").topology().springs().get(0).stiffness();
    }

    @Test
    void defaultsAreTheFilesValuesInTheParametersUnits() {
        Scene s = SceneFiles.load(dir, "cube.yaml", CUBE.replace("  c: {type: cube,", "  c: {type: cube, side: 10 m,"));
        SceneParameter k = s.parameter("k");
        assertEquals(0.1, k.defaultValue(), 1e-15, "100 N/m in kN/m");
        assertEquals(0.1, k.value(), 1e-15);
        assertEquals(1000, k.siPerUnit(), 1e-12);
        assertEquals(QuantityKind.STIFFNESS, k.kind());
        assertTrue(k.live());
        assertEquals("spring stiffness", k.description());
        assertEquals(1000, s.parameter("side").defaultValue(), 1e-9, "10 m in cm");
        assertFalse(s.parameter("side").live());
        assertEquals(-9.81, s.parameter("g").defaultValue(), 0);
        assertEquals(List.of("k", "force", "g", "side", "c"), s.parameters().stream().map(SceneParameter::name)
                .toList());
    }

    @Test
    void setByNameChangesTheBuiltSceneWithBareNumbersInTheParametersUnit() {
        String text = CUBE.replace("  c: {type: cube,", "  c: {type: cube, side: 10 m,");
        assertEquals(100, firstSpringStiffness(SceneFiles.load(dir, "a.yaml", text)), 1e-12);
        Scene s = SceneFiles.load(dir, "b.yaml", text, "k=0.25", "side=500", "g=-3 m/s^2");
        assertEquals(250, firstSpringStiffness(s), 1e-9, "0.25 kN/m");
        for (Spring sp : s.bodies().get("c").topology().springs()) {
            assertTrue(sp.stiffness() == 250 || sp.stiffness() == 0, "every cable and edge at 250 N/m");
        }
        assertEquals(5.0, s.bodies().get("c").bounds()[3], 1e-12, "side 500 cm");
        assertEquals(-3, s.bodies().get("c").topology().gravity().y(), 0);
        assertEquals(0.25, s.parameter("k").value(), 1e-15);
        assertEquals(0.1, s.parameter("k").defaultValue(), 1e-15, "the default stays the file's");
        assertEquals(List.of("k=0.25", "side=500", "g=-3 m/s^2"), s.overrides(), "recorded as given");
        Scene units = SceneFiles.load(dir, "c.yaml", text, "k=300N/m");
        assertEquals(300, firstSpringStiffness(units), 1e-9, "a value with its own unit");
    }

    @Test
    void setByNameOutsideTheRangeIsRefusedNamingTheOptionAndThePath() {
        SceneException e = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "a.yaml", CUBE
                .replace("  c: {type: cube,", "  c: {type: cube, side: 10 m,"), "k=2"));
        assertTrue(e.getMessage().startsWith("--set k=2: bodies.c.stiffness: 2 is outside parameter k's range"
                + " [0.01, 1] kN/m"), e.getMessage());
        SceneException wrongUnit = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "b.yaml", CUBE
                .replace("  c: {type: cube,", "  c: {type: cube, side: 10 m,"), "k=3 kPa"));
        assertTrue(wrongUnit.getMessage().startsWith("--set k=3 kPa: bodies.c.stiffness: \"3 kPa\" is not a"
                + " stiffness"), wrongUnit.getMessage());
    }

    @Test
    void aPathSetDirectlyIsRangeCheckedByItsParameterToo() {
        SceneException e = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "a.yaml", CUBE
                .replace("  c: {type: cube,", "  c: {type: cube, side: 10 m,"), "bodies.c.stiffness=5000"));
        assertTrue(e.getMessage().contains("5 is outside parameter k's range"), e.getMessage());
    }

    @Test
    void liveKeysAreDecidedByTheCode() {
        SceneNode root = SceneTree.read("x.yaml", (CUBE + "laws:\n  w: {type: sine, amplitude: 1, frequency: 1 Hz}\n"
                + "  r: {type: ramp, duration: 1 s}\n").getBytes(java.nio.charset.StandardCharsets.UTF_8));
        for (String live : List.of("bodies.c.stiffness", "bodies.c.damping", "conditions[1].magnitude",
                "conditions[1].direction[1]", "conditions[2].acceleration[1]", "laws.w.amplitude", "laws.r.to")) {
            assertEquals(null, LiveKeys.whyNotLive(root, live), live);
        }
        for (String rebuild : List.of("bodies.c.side", "bodies.c.node_mass", "laws.w.frequency", "laws.r.duration",
                "run.dt", "regions.bottom.box.max[1]", "conditions[0].region")) {
            String why = LiveKeys.whyNotLive(root, rebuild);
            assertTrue(why != null && why.startsWith(rebuild + " can only apply on rebuild"), rebuild + ": " + why);
        }
    }

    @Test
    void checkListsEachParameterWithItsUnitRangeAndApplyMode() {
        picocli.CommandLine cl = org.tensim.app.Main.commandLine();
        java.io.StringWriter out = new java.io.StringWriter();
        cl.setOut(new java.io.PrintWriter(out));
        assertEquals(0, cl.execute("check", "docs/examples/cube.yaml", "--set", "force=500"));
        assertTrue(out.toString().contains("parameter force: conditions[1].magnitude = 500 N (default 400), range"
                + " [0, 1000] N, applies live\n"), out.toString());
        assertTrue(out.toString().contains("parameter stiffness: bodies.mss.stiffness = 100 N/m (default 100), range"
                + " [10, 1000] N/m, applies live\n"), out.toString());
    }
}
