package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshReport;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;

/** The project's parametric diaphragm: size, shape, thickness and mesh quality. */
class DoubleDomeGeneratorTest {
    @Test
    void defaultIsAClosedShellNearThePapersNodeCount() {
        DoubleDomeGenerator.Shape s = DoubleDomeGenerator.Shape.adult();
        TriangleMesh m = DoubleDomeGenerator.shell(s);
        assertEquals(2 * DoubleDomeGenerator.faceVertices(43), m.vertexCount());
        assertEquals(11_354, m.vertexCount());
        assertEquals(22_704, m.triangleCount());
        MeshReport r = MeshCleaner.clean(m, MeshCleaner.Options.defaults(), "dome").report();
        assertEquals(1, r.components());
        assertEquals(0, r.boundaryLoops(), "closed");
        assertEquals(0, r.nonManifoldEdges());
        assertEquals(0, r.degenerateTriangles());
        assertEquals(0, r.weldedVertices());
        assertTrue(TwoSurfaces.signedVolume(m) > 0, "outward winding");
    }

    @Test
    void theCommittedDefaultMeshIsWhatTheGeneratorMakes() throws Exception {
        // The committed mesh is part of the project: found through the project folder, a missing one fails.
        java.nio.file.Path file = org.tensim.io.ProjectFolder.resolve("meshes", "diaphragm-default.obj");
        assertTrue(java.nio.file.Files.isRegularFile(file), file + " is committed with the project");
        TriangleMesh read = org.tensim.io.mesh.MeshReaders.read(file, org.tensim.io.mesh.MeshUnits.MM);
        TriangleMesh made = DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult());
        assertEquals(made.vertexCount(), read.vertexCount());
        assertEquals(java.util.Arrays.toString(made.triangles()), java.util.Arrays.toString(read.triangles()));
        for (int v = 0; v < made.vertexCount(); v++) {
            for (int a = 0; a < 3; a++) {
                assertEquals(made.coord(v, a), read.coord(v, a), 1e-6, "vertex " + v); // written to 1 micrometre
            }
        }
    }

    @Test
    void adultSizeRightDomeHigherAndThin() {
        DoubleDomeGenerator.Shape s = DoubleDomeGenerator.Shape.adult().withRings(20);
        TriangleMesh m = DoubleDomeGenerator.shell(s);
        double[] b = m.bounds();
        assertEquals(0.240, b[3] - b[0], 1e-9, "transverse 240 mm");
        assertEquals(0.176, b[4] - b[1], 0.005, "antero-posterior about 176 mm");
        double right = Double.NEGATIVE_INFINITY;
        double left = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < m.vertexCount(); v++) {
            if (m.coord(v, 0) < 0) {
                right = Math.max(right, m.coord(v, 2));
            } else {
                left = Math.max(left, m.coord(v, 2));
            }
        }
        double diff = right - left;
        assertTrue(diff > 0.005 && diff < 0.02, "right dome higher by 0.5-2 cm, got " + diff + " m");
        TwoSurfaces two = TwoSurfaces.split(m);
        assertEquals(0.0025, two.thicknessM(), 1e-4);
        assertTrue(two.thicknessM() >= 0.002 && two.thicknessM() <= 0.003, "2-3 mm");
    }

    @Test
    void trianglesAreReasonablyShaped() {
        TriangleMesh m = DoubleDomeGenerator.upperSurface(DoubleDomeGenerator.Shape.adult().withRings(20));
        double worst = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            double longest = 0;
            for (int k = 0; k < 3; k++) {
                longest = Math.max(longest, TwoSurfaces.distance(m, m.corner(t, k), m.corner(t, (k + 1) % 3)));
            }
            // aspect: longest edge^2 / (2 area / longest) ... 1.15 for an equilateral triangle
            double height = 2 * m.area(t) / longest;
            worst = Math.max(worst, longest / height);
        }
        assertTrue(worst < 6, "worst longest-edge / height ratio " + worst);
    }
}
