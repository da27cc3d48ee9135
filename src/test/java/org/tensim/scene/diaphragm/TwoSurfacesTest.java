package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;

/** Splitting a thin shell into its faces, and offsetting a single surface. */
class TwoSurfacesTest {
    private static final DoubleDomeGenerator.Shape SHAPE = DoubleDomeGenerator.Shape.adult().withRings(12);

    @Test
    void shellSplitsIntoItsGeneratedFacesWhicheverWayItIsWound() {
        TriangleMesh shell = DoubleDomeGenerator.shell(SHAPE);
        int face = DoubleDomeGenerator.faceVertices(12);
        TwoSurfaces s = TwoSurfaces.split(shell);
        int wrong = 0;
        for (int v = 0; v < shell.vertexCount(); v++) {
            wrong += s.isUpper(v) != (v < face) ? 1 : 0;
        }
        // Only rim vertices, where the two faces meet, may go either way.
        assertTrue(wrong <= 6 * 12, "misclassified " + wrong);
        int[] t = shell.triangles();
        for (int i = 0; i < t.length; i += 3) { // reverse every triangle: an inward-wound file
            int x = t[i + 1];
            t[i + 1] = t[i + 2];
            t[i + 2] = x;
        }
        TwoSurfaces r = TwoSurfaces.split(new TriangleMesh(shell.coordinates(), t));
        for (int v = 0; v < shell.vertexCount(); v++) {
            assertEquals(s.isUpper(v), r.isUpper(v), "vertex " + v);
        }
        for (int v = 0; v < face; v += 17) {
            assertEquals(v + face, s.partner(v), "nearest lower vertex is the offset copy of " + v);
        }
    }

    @Test
    void singleSurfaceIsOffsetByTheThicknessTowardsTheAbdomen() {
        TriangleMesh up = DoubleDomeGenerator.upperSurface(SHAPE);
        TwoSurfaces s = TwoSurfaces.offset(up, 0.003);
        assertEquals(2 * up.vertexCount(), s.mesh().vertexCount());
        assertEquals(0.003, s.thicknessM(), 1e-4);
        assertEquals(up.vertexCount(), s.upperCount());
        // The apex's copy lies below it.
        int apex = 0;
        assertTrue(s.mesh().coord(up.vertexCount() + apex, 2) < s.mesh().coord(apex, 2));
        assertEquals(2 * up.triangleCount(), s.mesh().triangleCount());
    }
}
