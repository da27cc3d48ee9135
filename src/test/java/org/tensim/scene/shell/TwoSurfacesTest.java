package org.tensim.scene.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;

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

    @Test
    void thicknessIsTheGapBetweenTheFacesNotBetweenTheirNearestVertices() {
        // Two parallel squares 3 mm apart, meshed apart: the lower grid is shifted by half a cell in
        // x and y, so no vertex lies opposite another. The nearest vertex is sqrt(3^2 + 2 (h/2)^2)
        // away, the face exactly 3 mm.
        int n = 10;
        double h = 0.004;
        double gap = 0.003;
        double[] xyz = new double[2 * 3 * (n + 1) * (n + 1)];
        int[] tri = new int[2 * 6 * n * n];
        int nv = (n + 1) * (n + 1);
        int k = 0;
        for (int f = 0; f < 2; f++) {
            double shift = f == 0 ? 0 : h / 2;
            for (int j = 0; j <= n; j++) {
                for (int i = 0; i <= n; i++) {
                    int v = f * nv + j * (n + 1) + i;
                    xyz[3 * v] = i * h + shift;
                    xyz[3 * v + 1] = j * h + shift;
                    xyz[3 * v + 2] = f == 0 ? gap : 0;
                }
            }
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    int a = f * nv + j * (n + 1) + i;
                    int[] q = {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1};
                    for (int c = 0; c < 6; c++) {
                        tri[k++] = q[c];
                    }
                }
            }
        }
        boolean[] upper = new boolean[2 * nv];
        java.util.Arrays.fill(upper, 0, nv, true);
        TwoSurfaces s = TwoSurfaces.of(new TriangleMesh(xyz, tri), upper);
        assertEquals(gap, s.thicknessM(), 1e-12);
        int v = 5 * (n + 1) + 5; // an interior upper vertex
        double pair = TwoSurfaces.distance(s.mesh(), v, s.partner(v));
        assertEquals(Math.sqrt(gap * gap + h * h / 2), pair, 1e-12, "its nearest lower vertex is farther");
    }
}
