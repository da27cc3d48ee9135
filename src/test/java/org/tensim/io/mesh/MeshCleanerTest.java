package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.tensim.testsupport.SharedData;

/** Welding, degenerate triangles, components, boundary loops and non-manifold edges. */
class MeshCleanerTest {
    /** A unit square of two triangles whose shared corners are duplicated (as in STL), plus extras. */
    @Test
    void duplicatesAreWeldedDegeneratesDroppedAndTopologyCounted() {
        double[] xyz = {
            0, 0, 0, 1, 0, 0, 1, 1, 0, // triangle 0
            0, 0, 0, 1, 1, 0, 0, 1, 0, // triangle 1: corners 3, 4 duplicate 0, 2
            1, 0, 0, 1, 0, 0, 1, 1, 0, // triangle 2: two equal corners after welding
            5, 5, 5, 6, 5, 5, 5, 6, 5, // triangle 3: a separate speck
            0, 0, 0, 2, 0, 0, 3, 0, 0, // triangle 4: collinear, zero area
        };
        int[] tri = new int[15];
        for (int i = 0; i < 15; i++) {
            tri[i] = i;
        }
        TriangleMesh raw = new TriangleMesh(xyz, tri);
        MeshCleaner.Result all = MeshCleaner.clean(raw, new MeshCleaner.Options(1e-9, 0), "square");
        MeshReport r = all.report();
        assertEquals(2, r.degenerateTriangles());
        assertEquals(3, r.triangles());
        assertEquals(2, r.components());
        assertEquals(2, r.boundaryLoops(), "the square's rim and the speck's rim");
        assertEquals(7, r.boundaryEdges());
        assertEquals(0, r.droppedComponents());
        assertEquals(7, all.mesh().vertexCount(), "4 square corners + 3 speck corners");
        MeshReport dropped = MeshCleaner.clean(raw, new MeshCleaner.Options(1e-9, 0.5), "square").report();
        assertEquals(1, dropped.droppedComponents());
        assertEquals(2, dropped.keptTriangles());
        assertEquals(4, dropped.keptVertices());
    }

    @Test
    void threeTrianglesOnOneEdgeMakeANonManifoldEdge() {
        double[] xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
        int[] tri = {0, 1, 2, 1, 0, 3, 0, 1, 4};
        MeshReport r = MeshCleaner.clean(new TriangleMesh(xyz, tri), MeshCleaner.Options.defaults(), "fin").report();
        assertEquals(1, r.nonManifoldEdges());
        assertEquals(1, r.components());
    }

    @Test
    void weldingWithinATolerance() {
        double[] xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1 + 4e-7, 3e-7, 0, 1, 1, 0, 0, 1 - 2e-7, 0};
        int[] tri = {0, 1, 2, 3, 4, 5};
        MeshCleaner.Result loose = MeshCleaner.clean(new TriangleMesh(xyz, tri), new MeshCleaner.Options(1e-6, 0), "w");
        assertEquals(2, loose.report().weldedVertices());
        assertEquals(4, loose.mesh().vertexCount());
        MeshCleaner.Result tight = MeshCleaner.clean(new TriangleMesh(xyz, tri), new MeshCleaner.Options(1e-8, 0), "w");
        assertEquals(6, tight.mesh().vertexCount());
    }

    /** The real BodyParts3D diaphragm: a real, imperfect mesh (see its ATTRIBUTION.md). */
    @Test
    void bodyParts3dDiaphragmIsReadWithItsDefects() throws Exception {
        Path p = SharedData.BODYPARTS3D_DIAPHRAGM;
        assumeTrue(Files.isRegularFile(p), "needs the BodyParts3D diaphragm mesh at " + p.toAbsolutePath());
        MeshCleaner.Result r = MeshLoader.load(p, MeshUnits.MM);
        MeshReport rep = r.report();
        assertEquals(14357, rep.rawVertices());
        assertEquals(28000, rep.rawTriangles());
        assertEquals(3, rep.nonManifoldEdges());
        assertEquals(56, rep.components(), "1 main body + small specks (edge-connected)");
        assertEquals(55, rep.droppedComponents());
        double[] b = r.mesh().bounds();
        // Documented bounds, mm: X -122.3..120.9, Z 985.9..1192.6.
        assertEquals(-0.1223, b[0], 1e-4);
        assertEquals(1.1926, b[5], 1e-4);
    }
}
