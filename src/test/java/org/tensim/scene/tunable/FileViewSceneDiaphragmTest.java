package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
        assertEquals(0, ((DiaphragmViewFactory) f).builds(), "the first scene is the loader's diaphragm, not built again");
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
        assertEquals(1, ((DiaphragmViewFactory) f).builds(), "a new scene is built anew");
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

    /**
     * A diaphragm file's regions, conditions and probes reach the view as {@code tensim run} applies them: the
     * fixed tendon's nodes are fixed in the view's scene (in both tendon models), the force is on the same nodes,
     * the chart follows the first probe, and a rebuild with a larger tendon share fixes the larger tendon. Stepped,
     * the fixed nodes stay where they are while the dome moves.
     */
    @Test
    void aDiaphragmFilesRegionsConditionsAndProbesRunInTheView(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        Path file = java.nio.file.Files.writeString(dir.resolve("d.yaml"), """
                version: 1
                bodies:
                  d: {type: diaphragm, rings: 6, period: 100 ms}
                regions:
                  tendon: {body: d, part: tendon}
                  lower: {body: d, part: lower}
                conditions:
                  - {type: fixed, region: tendon}
                  - {type: force, region: lower, direction: [0, 0, -1], total: 2 N}
                probes:
                  l: {region: lower, quantity: mean}
                run: {dt: auto, duration: 0.05 s}
                """);
        org.tensim.scene.file.Scene loaded = SceneLoader.load(file);
        org.tensim.model.Topology run = loaded.bodies().get("d").topology();
        java.util.BitSet tendon = loaded.regions().get("tendon").in("d");
        assertTrue(tendon.cardinality() > 0, "the tendon region selects nodes");
        SceneFactory f = FileViewScene.factory(file, List.of());
        for (boolean tensegrity : new boolean[] {true, false}) {
            DiaphragmViewScene view = assertInstanceOf(DiaphragmViewScene.class, f.create(tensegrity));
            org.tensim.model.Topology shown = view.scene().topology();
            assertEquals(run.nodeCount(), shown.nodeCount());
            for (int i = 0; i < run.nodeCount(); i++) {
                assertEquals(run.node(i).isFixed(), shown.node(i).isFixed(), "node " + i + " fixed as in tensim run");
            }
            assertEquals(run.forces().size(), shown.forces().size(), "the force on the lower surface's nodes");
            Body body = view.bodies().get(0);
            assertEquals(loaded.probes().get(0).nodes()[0], body.probeNode(), "the chart on the file's first probe");
            double[] x0 = body.simulation().state().x.clone();
            for (int k = 0; k < 20; k++) {
                body.simulation().step(view.defaultTimeStep());
            }
            double[] x = body.simulation().state().x;
            double fixedMoved = 0;
            double freeMoved = 0;
            for (int i = 0; i < view.scene().diaphragmNodes(); i++) {
                double d = Math.abs(x[3 * i + 2] - x0[3 * i + 2]);
                if (tendon.get(i)) {
                    fixedMoved = Math.max(fixedMoved, d);
                } else {
                    freeMoved = Math.max(freeMoved, d);
                }
            }
            assertEquals(0, fixedMoved, 0, "the fixed tendon does not move (tensegrity " + tensegrity + ")");
            assertTrue(freeMoved > 1e-5, "the rest of the dome moves: " + freeMoved + " m");
        }
        // A restarting control rebuilds the diaphragm; the file's regions are resolved on the rebuilt one.
        java.util.BitSet larger = SceneLoader.load(file, List.of("bodies.d.tendon_fraction=0.25")).regions()
                .get("tendon").in("d");
        assertTrue(larger.cardinality() > tendon.cardinality(), "a larger share, a larger tendon");
        DiaphragmViewScene rebuilt = (DiaphragmViewScene) f.create(true,
                Map.of(DiaphragmViewScene.TENDON_SHARE, 0.25));
        java.util.BitSet fixed = new java.util.BitSet();
        for (int i = 0; i < rebuilt.scene().diaphragmNodes(); i++) {
            fixed.set(i, rebuilt.scene().topology().node(i).isFixed());
        }
        java.util.BitSet fixedTendon = (java.util.BitSet) fixed.clone();
        fixedTendon.and(larger);
        assertEquals(larger, fixedTendon, "the rebuilt scene fixes the larger tendon's every node");
    }
}
