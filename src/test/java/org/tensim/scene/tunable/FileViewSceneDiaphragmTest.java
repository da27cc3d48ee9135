package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.file.SceneLoader;

/**
 * A diaphragm scene file opens the diaphragm's own view scene, built from the spec {@code tensim run} builds from the
 * same file and options: the same nodes, breathing and recommended step, at the file's integrator, the controls
 * starting at the file's values (a period outside the built-in range widens it).
 */
class FileViewSceneDiaphragmTest {
    private static final Path FILE = Path.of("docs/examples/diaphragm.yaml");

    @Test
    void theDiaphragmFileOpensTheDiaphragmViewAtTheFilesValues() {
        List<String> sets = List.of("bodies.diaphragm.rings=6", "bodies.diaphragm.period=1.5 s",
                "bodies.diaphragm.rib_amplitude=0.5", "bodies.diaphragm.tendon_fraction=0.2");
        DiaphragmScene run = ((DiaphragmSetup.Built) SceneLoader.load(FILE, sets).bodies().get("diaphragm").built())
                .scene();
        SceneFactory f = FileViewScene.factory(FILE, sets);
        assertInstanceOf(DiaphragmViewFactory.class, f, "the diaphragm's factory, as gui --scene diaphragm");
        DiaphragmViewScene view = assertInstanceOf(DiaphragmViewScene.class, f.create(true));
        DiaphragmScene shown = view.scene();
        assertEquals(run.diaphragmNodes(), shown.diaphragmNodes());
        assertEquals(run.topology().nodeCount(), shown.topology().nodeCount());
        assertEquals(1.5, shown.spec().breathing().periodS());
        assertEquals(0.5, shown.spec().breathing().ribAmplitude());
        assertEquals(0.2, shown.parameters().tendonAreaFraction(), 1e-15);
        assertEquals("rk2", view.defaultIntegrator(), "the file's integrator");
        assertEquals(run.recommendedTimeStep(), view.defaultTimeStep(), 0, "dt: auto, the step tensim run takes");
        Map<String, TunableParameter> c = view.parameters().stream()
                .collect(Collectors.toMap(TunableParameter::key, p -> p));
        assertEquals(1.5, c.get(DiaphragmViewScene.BREATHING_PERIOD).defaultValue());
        assertEquals(1.5, c.get(DiaphragmViewScene.BREATHING_PERIOD).min(), "widened from 2 s to hold the file's");
        assertEquals(0.5, c.get(DiaphragmViewScene.RIB_AMPLITUDE).defaultValue());
        assertEquals(0.2, c.get(DiaphragmViewScene.TENDON_SHARE).defaultValue(), 1e-15);
        assertEquals(run.parameters().muscleYoungPa(), c.get(DiaphragmViewScene.TISSUE_STIFFNESS).defaultValue());
        // A scene the window makes from the controls' values is the file's again.
        Map<String, Double> values = view.parameters().stream()
                .collect(Collectors.toMap(TunableParameter::key, TunableParameter::defaultValue));
        DiaphragmScene again = ((DiaphragmViewScene) f.create(true, values)).scene();
        assertEquals(1.5, again.spec().breathing().periodS());
        assertEquals(0.2, again.parameters().tendonAreaFraction(), 1e-15);
    }

    @Test
    void aStepInTheFileIsTheViewsStep() {
        ViewScene view = FileViewScene.factory(FILE, List.of("bodies.diaphragm.rings=6", "run.dt=1 ms",
                "run.integrator=bdf2")).create(true);
        assertEquals(1e-3, view.defaultTimeStep(), 1e-18);
        assertEquals("bdf2", view.defaultIntegrator());
    }

    /** The view builds the diaphragm from its spec alone: a file's extra blocks are refused rather than dropped. */
    @Test
    void aDiaphragmFileWithExtraConditionsOrProbesIsRefusedNamingTensimRun(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        String[] extras = {"conditions:\n  - {type: gravity, acceleration: [0, 0, -9.81]}\n",
            "regions:\n  tendon: {body: d, part: tendon}\nprobes:\n  t: {region: tendon, quantity: mean}\n"};
        for (String extra : extras) {
            Path file = java.nio.file.Files.writeString(dir.resolve("d.yaml"),
                    "version: 1\nbodies:\n  d: {type: diaphragm, rings: 6}\n" + extra + "run: {dt: auto, duration: 0.1 s}\n");
            var e = org.junit.jupiter.api.Assertions.assertThrows(org.tensim.scene.file.SceneException.class,
                    () -> FileViewScene.factory(file, List.of()));
            org.junit.jupiter.api.Assertions.assertTrue(e.getMessage().contains("tensim run " + file)
                    && e.getMessage().contains("d.yaml"), e.getMessage());
        }
    }
}
