package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The default action lines' points ({@link DomeTops}): on the surface, not at a vertex, so that
 * they stay where they are when the mesh changes.
 */
class DomeTopsTest {
    private static final double X0 = -0.0437;
    private static final double Y0 = 0.0113;
    /** x of the highest point of the adult double dome's upper surface for x below 0, from its formula, m. */
    private static final double ANALYTIC_TOP_X = -0.04057;

    /**
     * The square [-0.12, 0.12]^2 m in n x n cells, lifted to the cap z = -(3 dx^2 + 2 dx dy + 5 dy^2) (m) and
     * offset 2.5 mm downwards into a shell (the cap is its upper surface).
     */
    private static TwoSurfaces cap(int n) {
        TriangleMesh flat = FlatMeshes.square(0.12, n);
        double[] xyz = flat.coordinates();
        for (int v = 0; v < flat.vertexCount(); v++) {
            double dx = xyz[3 * v] - X0;
            double dy = xyz[3 * v + 1] - Y0;
            xyz[3 * v + 2] = -(3 * dx * dx + 2 * dx * dy + 5 * dy * dy);
        }
        return TwoSurfaces.offset(new TriangleMesh(xyz, flat.triangles()), 0.0025);
    }

    @Test
    void theTopOfAQuadraticCapIsFoundBetweenTheVerticesOnAnyMesh() {
        for (int n : new int[] {20, 33, 47}) {
            double[][] tops = DomeTops.tops(cap(n), 0);
            assertEquals(X0, tops[0][0], 1e-9, n + " cells: x of the top");
            assertEquals(Y0, tops[0][1], 1e-9, n + " cells: y of the top");
            // the other half rises towards its edge x = 0: its highest point is on that edge, where
            // dz/dy = -(2 dx + 10 dy) = 0 with dx = -X0
            assertEquals(0, tops[1][0], 1e-12, n + " cells: the half x >= 0 peaks on its edge");
            assertEquals(Y0 + X0 / 5, tops[1][1], 1e-9, n + " cells: y on the edge");
        }
    }

    @Test
    void theDoubleDomesRightTopStaysWithinAMillimetreAndAHalfFrom14To43Rings() {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int rings : new int[] {14, 20, 28, 43}) {
            TwoSurfaces s = TwoSurfaces.split(DoubleDomeGenerator.shell(
                    DoubleDomeGenerator.Shape.adult().withRings(rings)));
            double x = DiaphragmScene.defaultActionLines(s).get(0).x();
            // The analytic top of the upper surface's formula (DoubleDomeGenerator) is at x = -40.57 mm. The
            // fit is centred on the highest vertex, not on the top, and the flat top is not a quadratic over
            // its 24 mm radius: its top lies 2.9-4.1 mm from the analytic one (measured 2026-12-01: -37.66,
            // -37.06, -36.43, -36.80 mm at 14, 20, 28, 43 rings). Band: that offset, 2.0-5.0 mm; the highest
            // vertices (-44.5, -41.7 mm at 14 and 20 rings) fall outside it.
            assertTrue(x > ANALYTIC_TOP_X + 0.0020 && x < ANALYTIC_TOP_X + 0.0050,
                    rings + " rings: right dome's top at x = " + x * 1e3 + " mm");
            lo = Math.min(lo, x);
            hi = Math.max(hi, x);
        }
        // the highest vertices lay at x = -44.5, -41.7, -37.3, -38.8 mm (7.2 mm apart); the fit's, 1.23 mm apart
        assertTrue(hi - lo < 1.5e-3, "right dome's action line moves by " + (hi - lo) * 1e3 + " mm between meshes");
    }
}
