package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.mesh.VertexClustering;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.Simulation;
import org.tensim.testsupport.SharedData;

/** The real BodyParts3D diaphragm through the same pipeline (skipped when the mesh is absent). */
@org.junit.jupiter.api.TestInstance(org.junit.jupiter.api.TestInstance.Lifecycle.PER_CLASS)
class BodyPartsDiaphragmTest {
    private TwoSurfaces loaded;

    static final Path MESH = SharedData.BODYPARTS3D_DIAPHRAGM;

    private TwoSurfaces load() throws Exception {
        assumeTrue(Files.isRegularFile(MESH), "needs the BodyParts3D diaphragm mesh at " + MESH.toAbsolutePath());
        if (loaded == null) {
            loaded = TwoSurfaces.split(MeshLoader.load(MESH, MeshUnits.MM).mesh());
        }
        return loaded;
    }

    @Test
    void fullMeshSplitsIntoTwoFacesAndSteps() throws Exception {
        TwoSurfaces s = load();
        assertEquals(0.0030, s.thicknessM(), 0.0004, "about 3 mm apart");
        assertTrue(s.upperCount() > 0.4 * s.mesh().vertexCount() && s.lowerCount() > 0.4 * s.mesh().vertexCount());
        DiaphragmScene scene = DiaphragmScene.build(s, SceneFixture.bodyPartsBoxes(), DiaphragmParameters.defaults(),
                BreathingCycle.quiet(), new DiaphragmControls(1, 2300), null);
        assertTrue(scene.attachedNodes() > 100, "attached " + scene.attachedNodes());
        // No node is near the spine segment placed from the rib boxes, so the crura are taken from the
        // mesh: the free nodes within the threshold above its lowest point are fixed, and only those.
        assertTrue(scene.attachedToSpine() > 10, "crura fixed: " + scene.attachedToSpine());
        double low = Double.POSITIVE_INFINITY;
        for (int v = 0; v < scene.diaphragmNodes(); v++) {
            low = Math.min(low, s.mesh().coord(v, 2));
        }
        for (int v = 0; v < scene.diaphragmNodes(); v++) {
            if (scene.topology().node(v).isFixed()) {
                assertTrue(s.mesh().coord(v, 2) <= low + DiaphragmParameters.defaults().attachThresholdM() + 1e-12,
                        "fixed node " + v + " is not among the lowest");
            }
        }
        assertTrue(scene.topology().rigidLinks().size() > 100);
        assertEquals(0.12, scene.tendonAreaFraction(), 0.02);
        Simulation sim = scene.newSimulation();
        for (int i = 0; i < 30; i++) {
            sim.step(scene.recommendedTimeStep());
        }
        assertTrue(sim.projection().maxRelativeError() < 1e-9);
    }

    @Test
    void simplifiedMeshBreathesWithTheDomeDescending() throws Exception {
        TwoSurfaces full = load();
        int[] groups = new int[full.mesh().vertexCount()];
        for (int v = 0; v < groups.length; v++) {
            groups[v] = full.isUpper(v) ? 1 : 0;
        }
        VertexClustering.Result r = VertexClustering.simplify(full.mesh(), groups, 0.014);
        TriangleMesh m = r.mesh();
        assertTrue(m.vertexCount() < full.mesh().vertexCount() / 5, "simplified to " + m.vertexCount());
        boolean[] up = new boolean[m.vertexCount()];
        for (int v = 0; v < up.length; v++) {
            up[v] = r.groups()[v] == 1;
        }
        DiaphragmScene scene = DiaphragmScene.build(TwoSurfaces.of(m, up), SceneFixture.bodyPartsBoxes(),
                DiaphragmParameters.defaults(), BreathingCycle.quiet(), new DiaphragmControls(1, 2600), null,
                SceneFixture.PRESSURE);
        Simulation sim = scene.newSimulation();
        sim.runUntil(scene.cycle().inspirationS(), scene.recommendedTimeStep());
        int a = scene.apexNode();
        double dz = sim.state().x[3 * a + 2] - sim.state().x0[3 * a + 2];
        // The real mesh's broad, tall domes with many attached nodes descend less than the double dome at
        // the same muscle amplitude (docs/diaphragm.md). Measured (pressure) 2026-11-23: -1.92 mm with the
        // transverse shear elements, -2.75 mm with the diagonals of before (7 mm clusters: -4.58 and -5.49
        // mm); 2026-12-01: -1.875 mm. Band: -1.875 mm +/- 12 %: the tissue-model changes since 2026-11-23 moved
        // it by 2.4 %, the element change before them by 43 %, and a lost load or attachment by far more.
        assertEquals(-1.875e-3, dz, 0.225e-3, "apex moved " + dz * 1e3 + " mm");
    }
}
