package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.ConfigDir;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.RecordingTarget;
import org.tensim.tuning.Settings;
import org.tensim.tuning.Tuning;

/** Presets: round trip, atomic writes, and every kind of malformed file refused with the field named. */
class PresetFileTest {
    @TempDir
    Path dir;

    Tuning tuning;
    List<String> applied;

    @BeforeEach
    void setUp() {
        ViewScene s = CubeViewScene.create();
        tuning = new Tuning(s.name(), s.parameters(), s.defaultTimeStep(), false, Integrators.choices());
        applied = new java.util.ArrayList<>();
        tuning.bind(new RecordingTarget(applied));
    }

    @Test
    void roundTripRestoresEveryValue() throws Exception {
        tuning.set(CubeViewScene.STIFFNESS, 2500);
        tuning.set(CubeViewScene.FORCE_AMPLITUDE, 123.5);
        tuning.set(Tuning.TIME_STEP, 5e-4);
        Settings saved = tuning.snapshot();
        Path f = dir.resolve("p.json");
        PresetFile.write(f, saved);

        ViewScene s = CubeViewScene.create();
        Tuning other = new Tuning(s.name(), s.parameters(), s.defaultTimeStep(), false, Integrators.choices());
        Settings read = PresetFile.read(f, other);
        assertEquals(saved, read);
        other.apply(read, f.toString());
        assertEquals(2500, other.get(CubeViewScene.STIFFNESS));
        assertEquals(123.5, other.get(CubeViewScene.FORCE_AMPLITUDE));
        assertEquals(5e-4, other.get(Tuning.TIME_STEP));
        assertEquals(saved, other.snapshot());
    }

    @Test
    void writeIsAtomicAndLeavesNoTemporaryFile() throws Exception {
        Path f = dir.resolve("p.json");
        Files.writeString(f, "old content");
        PresetFile.write(f, tuning.snapshot());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(f), files.toList(), "only the preset itself, no .tmp left behind");
        }
        assertTrue(Files.readString(f).contains("\"" + CubeViewScene.STIFFNESS + "\""));
    }

    @Test
    void partialPresetKeepsOtherValues() throws Exception {
        tuning.set(CubeViewScene.DAMPING, 9);
        Path f = write("{\"scene\":\"cube\",\"parameters\":{\"" + CubeViewScene.STIFFNESS + "\":300}}");
        tuning.apply(PresetFile.read(f, tuning), f.toString());
        assertEquals(300, tuning.get(CubeViewScene.STIFFNESS));
        assertEquals(9, tuning.get(CubeViewScene.DAMPING));
    }

    @Test
    void invalidJsonNamesFileAndLine() throws Exception {
        Path f = write("{\n  \"scene\": \"cube\",\n  \"parameters\": { \"stiffnessNPerM\": 12,, }\n}");
        String m = refused(f);
        assertTrue(m.contains(f.toString()), m);
        assertTrue(m.contains("line 3"), m);
    }

    @Test
    void truncatedFileIsRefused() throws Exception {
        Path f = dir.resolve("t.json");
        PresetFile.write(f, tuning.snapshot());
        String full = Files.readString(f);
        Files.writeString(f, full.substring(0, full.length() / 2));
        assertTrue(refused(f).contains("not valid JSON"));
    }

    @Test
    void wrongTypeNamesTheField() throws Exception {
        String m = refused(write("{\"scene\":\"cube\",\"parameters\":{\"" + CubeViewScene.STIFFNESS + "\":\"stiff\"}}"));
        assertTrue(m.contains("parameters." + CubeViewScene.STIFFNESS), m);
        assertTrue(m.contains("must be a number"), m);
    }

    @Test
    void outOfRangeNamesFieldValueAndRange() throws Exception {
        String m = refused(write("{\"scene\":\"cube\",\"parameters\":{\"" + CubeViewScene.STIFFNESS + "\":1e9}}"));
        assertTrue(m.contains("parameters." + CubeViewScene.STIFFNESS), m);
        assertTrue(m.contains("1.0E9"), m);
        assertTrue(m.contains("between 10 and 10000 N/m"), m);
    }

    @Test
    void unknownParameterAndFieldAreRefused() throws Exception {
        String m = refused(write("{\"scene\":\"cube\",\"parameters\":{\"ribAmplitudeDeg\":3}}"));
        assertTrue(m.contains("parameters.ribAmplitudeDeg") && m.contains("known"), m);
        m = refused(write("{\"scene\":\"cube\",\"paramters\":{}}"));
        assertTrue(m.contains("'paramters'"), m);
    }

    @Test
    void wrongSceneTendonIntegratorOrShapeAreRefused() throws Exception {
        assertTrue(refused(write("{\"scene\":\"diaphragm\"}")).contains("'scene'"));
        assertTrue(refused(write("{\"scene\":\"cube\",\"tendon\":\"rubber\"}")).contains("'tendon'"));
        assertTrue(refused(write("{\"scene\":\"cube\",\"integrator\":\"euler-forward\"}")).contains("'integrator'"));
        assertTrue(refused(write("{\"scene\":\"cube\",\"integrator\":3}")).contains("'integrator'"));
        assertTrue(refused(write("[1, 2]")).contains("top level"));
        assertTrue(refused(write("{\"scene\":\"cube\",\"parameters\":[1]}")).contains("'parameters'"));
        assertTrue(refused(write("{\"version\":7}")).contains("'version'"));
        assertTrue(refused(dir.resolve("missing.json")).contains("no such file"));
    }

    @Test
    void aRefusedPresetChangesNothing() throws Exception {
        tuning.set(CubeViewScene.STIFFNESS, 777);
        applied.clear();
        Settings before = tuning.snapshot();
        // The first value is fine, the second is not: neither may be applied.
        refused(write("{\"scene\":\"cube\",\"parameters\":{\"" + CubeViewScene.DAMPING + "\":5,\""
                + CubeViewScene.STIFFNESS + "\":-1}}"));
        assertEquals(before, tuning.snapshot());
        assertEquals(List.of(), applied, "nothing reached the simulation");
        // And a settings record that is wrong is refused by Tuning.apply as a whole too.
        java.util.Map<String, Double> v = new java.util.LinkedHashMap<>(before.values());
        v.put(CubeViewScene.DAMPING, 5.0);
        v.put(CubeViewScene.FORCE_FREQUENCY, 99.0);
        assertThrows(IllegalArgumentException.class,
                () -> tuning.apply(new Settings("cube", "rk2", true, v), "test"));
        assertEquals(before, tuning.snapshot());
        assertEquals(List.of(), applied);
    }

    @Test
    void malformedLastUsedFileIsSetAsideWithANote() throws Exception {
        Path f = ConfigDir.lastUsed(dir, "cube");
        Files.writeString(f, "{ broken");
        Settings before = tuning.snapshot();
        String note = GuiCommand.restore(tuning, f);
        assertTrue(note != null && note.contains(f.toString()), note);
        assertEquals(before, tuning.snapshot());
        assertTrue(Files.exists(dir.resolve("last-cube.json.bad")), "the bad file is kept for the user");
        assertTrue(!Files.exists(f));
        assertNull(GuiCommand.restore(tuning, f), "no file: nothing to say");
    }

    @Test
    void configDirFollowsXdg() {
        assertEquals(Path.of("/x/cfg/tensim"), ConfigDir.resolve(java.util.Map.of("XDG_CONFIG_HOME", "/x/cfg"), "/home/u"));
        assertEquals(Path.of("/home/u/.config/tensim"), ConfigDir.resolve(java.util.Map.of(), "/home/u"));
        assertEquals(Path.of("/home/u/.config/tensim"),
                ConfigDir.resolve(java.util.Map.of("XDG_CONFIG_HOME", "relative/dir"), "/home/u"), "relative: ignored");
    }

    private Path write(String json) throws IOException {
        Path f = Files.createTempFile(dir, "preset", ".json");
        Files.writeString(f, json);
        return f;
    }

    private String refused(Path f) {
        PresetFile.PresetException e = assertThrows(PresetFile.PresetException.class, () -> PresetFile.read(f, tuning));
        return e.getMessage();
    }
}
