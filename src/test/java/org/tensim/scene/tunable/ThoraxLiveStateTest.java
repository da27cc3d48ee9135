package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Map;
import java.util.TreeSet;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.experiment.diaphragm.BreathingMetrics;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.model.ContactBody;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.solver.ContactForces;
import org.tensim.solver.Simulation;

/**
 * The diaphragm in the shared thorax, decimated as in {@code ThoraxCommandTest}: the nodes touching a bone are marked
 * from the simulation's state into the frame handed to the view, without allocating; the readouts and the run's
 * contact area agree with the pairs; the labels saved by the window's action read back to the same tendon and
 * origins. Skipped, naming the file, where {@code ../shared} is absent.
 */
class ThoraxLiveStateTest {
    static final Path THORAX = org.tensim.testsupport.SharedData.THORAX;
    static final Path MESH = org.tensim.testsupport.SharedData.BODYPARTS3D_DIAPHRAGM;

    @TempDir
    static Path dir;

    private static DiaphragmSpec spec;
    private static DiaphragmSetup.Inputs inputs;
    private static SceneFactory factory;

    @BeforeAll
    static void buildOnce() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        Path mesh = org.tensim.testsupport.CoarseMeshes.faceByFace(MESH, 0.006, dir.resolve("coarse.obj"));
        spec = DiaphragmSpec.defaults().withMesh(DiaphragmSpec.Mesh.defaults().withFile(mesh, MeshUnits.parse("mm")))
                .withCage(DiaphragmSpec.Cage.defaults().withThorax(THORAX));
        inputs = DiaphragmSetup.read(spec);
        factory = DiaphragmViewScene.factory(spec, inputs);
    }

    /** Moves pair e's node 1 mm past its gap into its bone (at t = 0, where every bone is at rest). */
    private static void pushIn(DiaphragmScene s, Simulation sim, int e, double[] d) {
        ContactForces c = sim.state().contacts;
        ContactBody body = s.topology().contactBodies().get(c.body(e));
        double[] x = sim.state().x;
        int v = c.node(e);
        double[] g = new double[3];
        double dist = body.surface().distance(x[3 * v], x[3 * v + 1], x[3 * v + 2], g, 0);
        double move = dist - c.gap(e) + 1e-3;
        for (int a = 0; a < 3; a++) {
            x[3 * v + a] -= move * g[a];
        }
        c.distances(sim.time(), x, d);
        assertTrue(d[e] < c.gap(e), "pair " + e + " pushed in: d " + d[e] + ", gap " + c.gap(e));
    }

    @Test
    void theNodesTouchingABoneAreMarkedInTheFrameWithTheirAreaAndDepthAndNothingIsAllocated() {
        DiaphragmViewScene view = (DiaphragmViewScene) factory.create(true);
        DiaphragmScene s = view.scene();
        Simulation sim = view.bodies().get(0).simulation();
        ContactForces c = sim.state().contacts;
        assertTrue(c.count() > 10, "pairs: " + c.count());
        double[] d = new double[c.count()];
        c.distances(0, sim.state().x, d);
        for (int e = 0; e < c.count(); e++) {
            assertTrue(d[e] >= c.gap(e) - 1e-12, "at rest no pair is in contact (pair " + e + ")");
        }
        // Push three pairs' nodes into their bones (the liver's support is no bone: the readouts leave it out).
        TreeSet<Integer> pushed = new TreeSet<>();
        for (int e = 0; e < c.count() && pushed.size() < 3; e += c.count() / 7) {
            if (s.isBoneContact(c.body(e)) && pushed.add(c.node(e))) {
                pushIn(s, sim, e, d);
            }
        }
        TreeSet<Integer> touching = new TreeSet<>();
        double deepest = 0;
        c.distances(0, sim.state().x, d);
        for (int e = 0; e < c.count(); e++) {
            if (!s.isBoneContact(c.body(e))) {
                continue;
            }
            if (c.gap(e) - d[e] > 0) {
                touching.add(c.node(e));
            }
            deepest = Math.max(deepest, -d[e]);
        }
        assertTrue(touching.containsAll(pushed), touching + " has " + pushed);
        double[] area = s.nodeAreasM2();
        double expectedArea = touching.stream().mapToDouble(v -> area[v]).sum();

        DiaphragmLiveState live = (DiaphragmLiveState) view.liveState();
        FrameBuffer frames = new FrameBuffer(view.bodies(), live);
        frames.afterStep(sim);
        FrameBuffer.Frame f = frames.takeNewer();
        for (int i = 0; i < f.marks.length; i++) {
            assertEquals(touching.contains(i) ? DiaphragmLiveState.IN_CONTACT : 0, f.marks[i], "node " + i);
        }
        assertEquals(1e6 * expectedArea, f.readouts[live.readout("Contact area")], 1e-6);
        assertEquals(1e3 * deepest, f.readouts[live.readout("Bone penetration now")], 1e-9);
        assertTrue(f.readouts[live.readout("Max bone penetration")] >= 1e3 * deepest);
        assertEquals(1e6 * s.attachedAreaM2(), f.readouts[live.readout("Attached area")], 1e-6);
        assertArrayEquals(f.readouts, frames.readouts().latest(), "the window reads the same figures");

        // Drawn: the touching nodes in the contact colour, the attached green, the others their tissue's.
        float[] own = view.bodies().get(0).vertexColours();
        float[] drawn = new float[own.length];
        LiveState.paint(own, f.marks, live.markColours(), drawn);
        int attachedSeen = 0;
        for (int i = 0; i < s.diaphragmNodes(); i++) {
            float[] expected = touching.contains(i) ? DiaphragmViewScene.IN_CONTACT_COLOUR
                    : s.isAttached(i) ? DiaphragmViewScene.ATTACHED
                    : s.isTendon(i) ? DiaphragmViewScene.TENDON_COLOUR : DiaphragmViewScene.MUSCLE_COLOUR;
            attachedSeen += s.isAttached(i) && !touching.contains(i) ? 1 : 0;
            assertArrayEquals(expected, Arrays.copyOfRange(drawn, 3 * i, 3 * i + 3), "node " + i);
        }
        assertTrue(attachedSeen > 0);

        // The run's figures count the same area (BreathingMetrics, summary.json).
        BreathingMetrics metrics = new BreathingMetrics(s, 1);
        metrics.afterStep(sim);
        assertEquals(1e6 * expectedArea, metrics.fields().get("max_contact_area_mm2"), 1e-6);
        assertEquals(1e6 * expectedArea, metrics.fields().get("contact_area_expiration_mm2"), 1e-6);

        // Per step, nothing is allocated (after a warm-up that lets the JIT compile the pass).
        org.tensim.testsupport.AllocationCounter counter = org.tensim.testsupport.AllocationCounter.currentThread();
        for (int i = 0; i < 3000; i++) {
            frames.afterStep(sim);
        }
        assertEquals(0, counter.bytesAllocatedBy(() -> {
            for (int i = 0; i < 500; i++) {
                frames.afterStep(sim);
            }
        }, 3), "bytes allocated by 500 frames' marks and readouts");
    }

    @Test
    void savedLabelsReadBackToTheTunedTendonAndTheSameOrigins() throws Exception {
        DiaphragmViewScene view = (DiaphragmViewScene) factory.create(true);
        DiaphragmScene s = view.scene();
        int n = s.diaphragmNodes();
        Path file = dir.resolve("rules.labels");
        assertEquals(n, view.saveLabels(file, false));
        VertexLabel[] read = VertexLabelsFile.read(file, n);
        for (int v = 0; v < n; v++) {
            assertEquals(s.isAttached(v), read[v].isOrigin(), "vertex " + v + ": origin where attached");
            if (!read[v].isOrigin()) {
                assertEquals(s.isTendon(v), read[v] == VertexLabel.TENDON, "vertex " + v);
            }
        }
        assertTrue(Arrays.stream(read).anyMatch(l -> l == VertexLabel.ORIGIN_COSTAL)
                && Arrays.stream(read).anyMatch(l -> l == VertexLabel.ORIGIN_LUMBAR), "costal and lumbar origins");
        // An existing file is not replaced without being asked.
        byte[] saved = Files.readAllBytes(file);
        assertThrows(java.nio.file.FileAlreadyExistsException.class, () -> view.saveLabels(file, false));
        assertArrayEquals(saved, Files.readAllBytes(file));

        // The tuned boundary is what is saved, and a scene built from the file has that tendon and saves the same file.
        DiaphragmViewScene tuned = (DiaphragmViewScene) factory.create(true, Map.of(DiaphragmViewScene.TENDON_SHARE,
                0.08));
        assertTrue(tuned.scene().tendonAreaFraction() < s.tendonAreaFraction());
        Path tunedFile = dir.resolve("tuned.labels");
        tuned.saveLabels(tunedFile, false);
        VertexLabel[] tunedLabels = VertexLabelsFile.read(tunedFile, n);
        DiaphragmSpec withFile = spec.withMesh(spec.mesh().withLabels(tunedFile));
        DiaphragmSetup.Inputs in = new DiaphragmSetup.Inputs(inputs.surfaces(), inputs.report(), inputs.boxes(),
                inputs.bones(), tunedLabels, inputs.source());
        DiaphragmViewScene reread = (DiaphragmViewScene) DiaphragmViewScene.factory(withFile, in).create(true);
        for (int v = 0; v < n; v++) {
            assertEquals(tunedLabels[v] == VertexLabel.TENDON, reread.scene().isTendon(v), "vertex " + v);
        }
        Path again = dir.resolve("again.labels");
        reread.saveLabels(again, false);
        assertArrayEquals(Files.readAllBytes(tunedFile), Files.readAllBytes(again), "a label file's origins are kept");
        assertEquals(null, reread.parameters().stream().filter(p -> p.key().startsWith("tendon")).findFirst()
                .orElse(null), "with a label file the tendon is the file's");
    }
}
