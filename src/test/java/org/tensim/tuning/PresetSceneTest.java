package org.tensim.tuning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.ViewScene;

/**
 * A preset holds the diaphragm's whole scene: its {@code "diaphragm"} object, with the keys of a spec file's,
 * read through the same parser; older presets still load, and a bad key or value is refused naming the file
 * and the key.
 */
class PresetSceneTest {
    @TempDir
    Path dir;

    private Tuning tuning() {
        SceneFactory f = ParameterBindingTest.coarseDiaphragm();
        ViewScene s = f.create(true);
        return new Tuning(s.name(), s.parameters(), s.defaultTimeStep(), f.hasTendonChoice(),
                org.tensim.solver.integrators.Integrators.choices(), f.muscleLoad());
    }

    /**
     * Every option of the diaphragm, each with a value it accepts, in two scenes (rib boxes or a thorax: not
     * both); files made under the test's folder.
     */
    private List<List<String>> everyOption() throws Exception {
        Path mesh = Files.writeString(dir.resolve("d.obj"), "");
        Path labels = Files.writeString(dir.resolve("d.labels"), "");
        Path boxes = Files.writeString(dir.resolve("boxes.json"), "{}");
        Path thorax = Files.createDirectories(dir.resolve("thorax"));
        List<String> ribs = List.of("--units", "m", "--thickness", "3", "--rings", "12", "--boxes", boxes.toString(),
                "--tendon-rule", "geodesic", "--model", "default", "--rib-amplitude", "1.5", "--muscle-action", "2000",
                "--period", "5", "--ie-ratio", "1.5", "--expiratory-pause", "0.1", "--attach-threshold", "15",
                "--attachment", "band",
                "--band-stiffness", "3e5", "--band-all-segments", "--muscle-load", "pressure", "--weld-tolerance",
                "0.002", "--min-piece-fraction", "0.02", "--tendon-normal", "0,0.1,1", "--tendon-point", "1,2,3",
                "--tendon-fraction", "0.2", "--tissue-model", "springs", "--action-line", "0,10,40",
                "--action-line", "0,-10,40", "--cage", "surfaces");
        List<String> inThorax = List.of("--mesh", mesh.toString(), "--labels", labels.toString(), "--thorax",
                thorax.toString(), "--no-contact", "--contact-stiffness", "2e6", "--liver-support", "1e5",
                "--abdominal-support", "8e4", "--abdominal-pressure", "250", "--apposition-pressure", "120",
                "--muscle-load", "pressure");
        return List.of(ribs, inThorax);
    }

    @Test
    void aPresetRoundTripsEveryOptionOfTheScene() throws Exception {
        Set<String> given = new TreeSet<>();
        Set<String> written = new TreeSet<>();
        int n = 0;
        for (List<String> every : everyOption()) {
            every.stream().filter(a -> a.startsWith("--")).forEach(a -> given.add(a.replace("--no-", "--")
                    .substring(2)));
            Tuning t = tuning();
            t.setMuscleLoad(MuscleLoad.PRESSURE);
            t.setSceneOptions(PresetScene.withoutMuscleLoad(every));
            Path p = dir.resolve("sub").resolve("whole" + n++ + ".json");
            Files.createDirectories(p.getParent());
            PresetFile.write(p, t.snapshot());
            Json.mapper().readTree(p.toFile()).get("diaphragm").fieldNames().forEachRemaining(written::add);

            Settings read = PresetFile.read(p, tuning());
            assertEquals(MuscleLoad.PRESSURE, read.muscleLoad());
            assertTrue(PresetScene.same(t.sceneOptions(), read.sceneOptions()), read.sceneOptions().toString());
            List<String> back = new ArrayList<>(read.sceneOptions());
            back.addAll(List.of("--muscle-load", "pressure"));
            assertEquals(DiaphragmOptions.parse(every).spec(null, 43), DiaphragmOptions.parse(back).spec(null, 43),
                    "the same scene");
            // what the window opens from the preset is that scene too
            assertEquals(read.sceneOptions(), PresetFile.scene(p).options());
        }
        assertEquals(new TreeSet<>(DiaphragmOptions.names()), given, "the test gives every option");
        Set<String> expected = new TreeSet<>(given);
        expected.remove("muscle-load"); // the preset's own field "muscleLoad"
        assertEquals(expected, written, "every option is written");
    }

    @Test
    void olderPresetsStillLoadAndHoldNoScene() throws Exception {
        Path v2 = dir.resolve("v2.json");
        Files.writeString(v2, "{\"format\": \"tensim-gui-preset\", \"version\": 2, \"scene\": \"diaphragm\","
                + " \"integrator\": \"rk2\", \"tendon\": \"tensegrity\", \"muscleLoad\": \"pressure\","
                + " \"parameters\": {\"timeStepS\": 0.001}}");
        Tuning t = tuning();
        Settings s = PresetFile.read(v2, t);
        assertNull(s.sceneOptions(), "not recorded");
        assertNull(PresetFile.scene(v2));
        t.apply(s, v2.toString());
        assertEquals(0.001, t.get(Tuning.TIME_STEP));
        assertEquals(MuscleLoad.PRESSURE, t.muscleLoad());
        // the project's own preset holds its 14-ring scene
        Path shipped = org.tensim.io.ProjectFolder.resolve("docs", "presets", "diaphragm-realtime.json");
        assertEquals(List.of("--rings", "14"), PresetFile.read(shipped, tuning()).sceneOptions());
    }

    @Test
    void optionsGivenBesideAPresetChangeItsSceneOptionByOption() throws Exception {
        Path thorax = Files.createDirectories(dir.resolve("thorax"));
        List<String> held = List.of("--rings", "14", "--period", "5");
        List<String> merged = PresetScene.merge(held, List.of("--resolution", "20", "--thorax", thorax.toString()));
        DiaphragmSpec s = DiaphragmOptions.parse(merged).spec(null, 43);
        assertEquals(20, s.mesh().rings(), "the option given replaces the preset's, whatever its alias");
        assertEquals(5.0, s.breathing().periodS(), "the preset's other options stay");
        assertEquals(thorax.toAbsolutePath().normalize(), s.cage().thorax().toAbsolutePath().normalize());
        assertTrue(PresetScene.same(held, List.of("--resolution", "14", "--period", "5")));
        assertTrue(!PresetScene.same(held, List.of("--rings", "20", "--period", "5")));
    }

    @Test
    void aBadKeyOrValueIsRefusedNamingTheFileAndTheKey() throws Exception {
        Path p = dir.resolve("bad.json");
        String head = "{\"version\": 3, \"scene\": \"diaphragm\", \"diaphragm\": ";
        Object[][] cases = {
            {"{\"bogus\": 1}", "diaphragm.bogus"},
            {"{\"rings\": 2}", "--rings"},
            {"{\"rings\": \"many\"}", "diaphragm.rings"},
            {"{\"resolution\": 3}", "diaphragm.resolution"},
            {"{\"mesh\": \"missing.obj\"}", "diaphragm.mesh"},
            {"{\"tissue-model\": \"rubber\"}", "--tissue-model"},
            {"{\"contact\": \"yes\", \"period\": [1, 2]}", "--period"},
            {"3", "diaphragm"},
            {"{\"muscle-load\": \"fibres\"}, \"muscleLoad\": \"pressure\"", "diaphragm.muscle-load"},
        };
        for (Object[] c : cases) {
            Files.writeString(p, head + c[0] + "}");
            String m = assertThrows(PresetFile.PresetException.class, () -> PresetFile.read(p, tuning()),
                    c[0].toString()).getMessage();
            assertTrue(m.contains(p.toString()) && m.contains(c[1].toString()), c[0] + ": " + m);
        }
        Files.writeString(p, "{\"version\": 2, \"scene\": \"diaphragm\", \"diaphragm\": {}}");
        String m = assertThrows(PresetFile.PresetException.class, () -> PresetFile.read(p, tuning())).getMessage();
        assertTrue(m.contains(p.toString()) && m.contains("'diaphragm'") && m.contains("version"), m);
    }
}
