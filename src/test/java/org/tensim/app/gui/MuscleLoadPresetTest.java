package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.ParameterBindingTest;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.RecordingTarget;
import org.tensim.tuning.Settings;
import org.tensim.tuning.TunableScenes;
import org.tensim.tuning.Tuning;

/**
 * The GUI's muscle load: the fibres' tension by default, with their amplitude; presets of version 2 record the
 * load, and a version-1 preset (all made with the pressure, the default load until then) loads as the pressure
 * at its amplitude, giving the same motion as the scene it was saved from.
 */
class MuscleLoadPresetTest {
    @TempDir
    Path dir;

    private final List<String> applied = new ArrayList<>();

    private Tuning tuning(ViewScene s, SceneFactory f) {
        Tuning t = new Tuning(s.name(), s.parameters(), s.defaultTimeStep(), f.hasTendonChoice(),
                Integrators.choices(), f.muscleLoad());
        t.bind(new RecordingTarget(applied));
        return t;
    }

    private static TunableParameter muscleAction(ViewScene s) {
        return s.parameters().stream().filter(p -> p.key().equals(DiaphragmViewScene.MUSCLE_ACTION)).findFirst()
                .orElseThrow();
    }

    @Test
    void theDefaultLoadIsTheFibresAtTheirActiveStress() {
        SceneFactory f = ParameterBindingTest.coarseDiaphragm();
        assertEquals(MuscleLoad.FIBRES, f.muscleLoad());
        DiaphragmViewScene s = (DiaphragmViewScene) f.create(true);
        TunableParameter m = muscleAction(s);
        assertEquals(DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, m.defaultValue());
        assertTrue(m.description().contains("active stress of the muscle fibres"), m.description());
        assertTrue(m.max() >= 30_000, "the fibres' range reaches 30 kPa: " + m.max());
        assertEquals(DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, s.scene().controls().muscleAmplitudePa());
        assertTrue(s.title().contains("muscle load fibres"), s.title());
        assertEquals(DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, muscleAction(DiaphragmViewScene.PARAMETERS));
        // the pressure by name, with its own amplitude and wording
        DiaphragmViewScene p = (DiaphragmViewScene) f.create(true, MuscleLoad.PRESSURE, Map.of());
        assertEquals(DiaphragmSetup.DEFAULT_MUSCLE_PA, muscleAction(p).defaultValue());
        assertTrue(muscleAction(p).description().contains("per unit area"), muscleAction(p).description());
        assertEquals(DiaphragmSetup.DEFAULT_MUSCLE_PA, p.scene().controls().muscleAmplitudePa());
        SceneFactory cube = CubeViewScene.factory();
        assertNull(cube.muscleLoad());
        assertThrows(IllegalArgumentException.class, () -> cube.create(true, MuscleLoad.FIBRES, Map.of()));
    }

    private static double muscleAction(List<TunableParameter> ps) {
        return ps.stream().filter(p -> p.key().equals(DiaphragmViewScene.MUSCLE_ACTION)).findFirst().orElseThrow()
                .defaultValue();
    }

    @Test
    void aVersion1PresetLoadsAsThePressureAndMovesAsTheSceneItWasSavedFrom() throws Exception {
        SceneFactory f = ParameterBindingTest.coarseDiaphragm();
        Tuning t = tuning(f.create(true), f);
        Path v1 = dir.resolve("v1.json");
        Files.writeString(v1, "{\"format\": \"tensim-gui-preset\", \"version\": 1, \"scene\": \"diaphragm\","
                + " \"integrator\": \"rk2\", \"tendon\": \"tensegrity\", \"parameters\": {\"muscleActionPa\": 3000.0}}");
        Settings read = PresetFile.read(v1, t);
        assertEquals(MuscleLoad.PRESSURE, read.muscleLoad());
        t.apply(read, v1.toString());
        assertEquals(MuscleLoad.PRESSURE, t.muscleLoad());
        assertEquals(List.of("muscleLoad=pressure", "muscleActionPa=3000.0"), applied,
                "the load first (it rebuilds the scene), then the values");
        // What the user had: the pressure scene at 3 kPa, as built when the pressure was the default.
        SceneFactory pressureFactory = TunableScenes.factory("diaphragm", org.tensim.tuning.DiaphragmOptions.parse(
                List.of("--rings", "6", "--muscle-load", "pressure")));
        ViewScene before = pressureFactory.create(true, Map.of(DiaphragmViewScene.MUSCLE_ACTION, 3000.0));
        ViewScene loaded = f.create(t.tensegrityTendon(), t.muscleLoad(), t.snapshot().values());
        double dt = before.defaultTimeStep();
        assertArrayEquals(ParameterBindingTest.run(before, dt, 150), ParameterBindingTest.run(loaded, dt, 150), 0,
                "the same motion");
        // ... and not what the fibres would do at the same value
        ViewScene fibres = f.create(true, Map.of(DiaphragmViewScene.MUSCLE_ACTION, 3000.0));
        double[] a = ParameterBindingTest.run(fibres, dt, 150);
        double[] b = ParameterBindingTest.run(f.create(true, MuscleLoad.PRESSURE, t.snapshot().values()), dt, 150);
        assertTrue(!java.util.Arrays.equals(a, b), "the fibres at 3 kPa move otherwise");
        // a version-1 preset without the muscle action meant the pressure's default amplitude
        Files.writeString(v1, "{\"version\": 1, \"scene\": \"diaphragm\", \"parameters\": {\"timeStepS\": 0.01}}");
        Settings partial = PresetFile.read(v1, tuning(f.create(true), f));
        assertEquals(MuscleLoad.PRESSURE, partial.muscleLoad());
        assertEquals(DiaphragmSetup.DEFAULT_MUSCLE_PA, partial.values().get(DiaphragmViewScene.MUSCLE_ACTION));
        // a version-1 file cannot name a load
        Files.writeString(v1, "{\"version\": 1, \"scene\": \"diaphragm\", \"muscleLoad\": \"fibres\"}");
        String m = assertThrows(PresetFile.PresetException.class, () -> PresetFile.read(v1, t)).getMessage();
        assertTrue(m.contains("'muscleLoad'") && m.contains("version"), m);
    }

    @Test
    void aVersion2PresetRecordsTheLoadAndRoundTrips() throws Exception {
        SceneFactory f = ParameterBindingTest.coarseDiaphragm();
        Tuning t = tuning(f.create(true), f);
        t.setMuscleLoad(MuscleLoad.PRESSURE);
        t.set(DiaphragmViewScene.MUSCLE_ACTION, 3100);
        Settings saved = t.snapshot();
        Path p = dir.resolve("v2.json");
        PresetFile.write(p, saved);
        String text = Files.readString(p);
        assertTrue(text.contains("\"version\" : " + PresetFile.VERSION) && text.contains("\"muscleLoad\" : \"pressure\""), text);
        Tuning other = tuning(f.create(true), f);
        assertEquals(MuscleLoad.FIBRES, other.muscleLoad());
        Settings read = PresetFile.read(p, other);
        assertEquals(saved, read);
        other.apply(read, p.toString());
        assertEquals(saved, other.snapshot());
        assertEquals(MuscleLoad.PRESSURE, other.muscleLoad());
        // a preset of the fibres written now reads back as the fibres
        other.setMuscleLoad(MuscleLoad.FIBRES);
        PresetFile.write(p, other.snapshot());
        assertEquals(MuscleLoad.FIBRES, PresetFile.read(p, t).muscleLoad());
        // an unknown load, or a load for the cube, is refused naming the field
        Files.writeString(p, "{\"version\": 2, \"scene\": \"diaphragm\", \"muscleLoad\": \"fibers\"}");
        String m = assertThrows(PresetFile.PresetException.class, () -> PresetFile.read(p, t)).getMessage();
        assertTrue(m.contains("'muscleLoad'") && m.contains("'fibers'") && m.contains("pressure"), m);
        ViewScene cube = CubeViewScene.create();
        Tuning c = new Tuning(cube.name(), cube.parameters(), cube.defaultTimeStep(), false,
                Integrators.choices());
        Files.writeString(p, "{\"version\": 2, \"scene\": \"cube\", \"muscleLoad\": \"fibres\"}");
        m = assertThrows(PresetFile.PresetException.class, () -> PresetFile.read(p, c)).getMessage();
        assertTrue(m.contains("'muscleLoad'") && m.contains("no muscle"), m);
    }

    @Test
    void lastUsedParametersOfAnotherLoadAreNotRestoredOverAnExplicitMuscleLoad() throws Exception {
        SceneFactory f = ParameterBindingTest.coarseDiaphragm();
        Path last = dir.resolve("last-diaphragm.json");
        Files.writeString(last, "{\"version\": 1, \"scene\": \"diaphragm\", \"parameters\": {\"muscleActionPa\": 2600}}");
        Tuning explicit = tuning(f.create(true), f);
        String note = GuiCommand.restore(explicit, last, true);
        assertTrue(note != null && note.contains("muscle load pressure") && note.contains("--muscle-load fibres"),
                note);
        assertEquals(MuscleLoad.FIBRES, explicit.muscleLoad());
        assertEquals(DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, explicit.get(DiaphragmViewScene.MUSCLE_ACTION));
        assertTrue(Files.exists(last), "a valid file is kept where it is");
        Tuning restored = tuning(f.create(true), f);
        assertNull(GuiCommand.restore(restored, last, false));
        assertEquals(MuscleLoad.PRESSURE, restored.muscleLoad());
        assertEquals(2600, restored.get(DiaphragmViewScene.MUSCLE_ACTION));
    }

    @Test
    void aPresetThatSwitchesTheLoadRelabelsTheMuscleSlider() throws Exception {
        SceneFactory f = ParameterBindingTest.coarseDiaphragm();
        ViewScene first = f.create(true);
        Tuning t = new Tuning(first.name(), first.parameters(), first.defaultTimeStep(), f.hasTendonChoice(),
                Integrators.choices(), f.muscleLoad(), f::parameters);
        t.bind(new RecordingTarget(applied));
        ParameterControl slider = new ParameterControl(t.parameter(DiaphragmViewScene.MUSCLE_ACTION), t, m -> { });
        t.addListener(slider::refresh);
        assertTrue(slider.labelText().startsWith("Muscle fibre active stress"), slider.labelText());
        Path v2 = dir.resolve("pressure.json");
        Files.writeString(v2, "{\"format\": \"tensim-gui-preset\", \"version\": 2, \"scene\": \"diaphragm\","
                + " \"muscleLoad\": \"pressure\", \"parameters\": {\"muscleActionPa\": 2000.0}}");
        t.apply(PresetFile.read(v2, t), v2.toString());
        assertEquals(MuscleLoad.PRESSURE, t.muscleLoad());
        assertTrue(slider.labelText().startsWith("Muscle action pressure"), slider.labelText());
        TunableParameter m = t.parameter(DiaphragmViewScene.MUSCLE_ACTION);
        assertEquals(DiaphragmSetup.DEFAULT_MUSCLE_PA, m.defaultValue(), "the pressure's default");
        assertTrue(m.description().contains("per unit area"), m.description());
        assertEquals(2000.0, t.get(DiaphragmViewScene.MUSCLE_ACTION), "the preset's value");
        // and back: the fibres' wording and default again, the value kept as the load's setter says
        t.setMuscleLoad(MuscleLoad.FIBRES);
        assertTrue(slider.labelText().startsWith("Muscle fibre active stress"), slider.labelText());
        assertEquals(DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, t.parameter(DiaphragmViewScene.MUSCLE_ACTION)
                .defaultValue());
        assertEquals(2000.0, t.get(DiaphragmViewScene.MUSCLE_ACTION));
        assertEquals(t.parameters().size(), first.parameters().size() + 1, "the scene's parameters and the step");
    }
}
