package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@link DomeHeights} on a sloping plane, where the answers are known: read on a line, the top is the plane's
 * height on that line (exactly, since the cut of a plane is linear along each edge), not the highest node of a
 * strip about it; and it follows the surface when the surface slides across the line.
 */
class DomeHeightsTest {
    private static final int N = 11; // 11 x 11 nodes, 0.1 apart, on [0, 1]^2

    /** z = 0.3 x + 0.1 y on a grid of two triangles per cell; 3 coordinates per node. */
    private static double[] plane() {
        double[] x = new double[3 * N * N];
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                int v = i * N + j;
                x[3 * v] = 0.1 * i;
                x[3 * v + 1] = 0.1 * j;
                x[3 * v + 2] = 0.3 * x[3 * v] + 0.1 * x[3 * v + 1];
            }
        }
        return x;
    }

    private static int[] triangles() {
        int[] c = new int[6 * (N - 1) * (N - 1)];
        int n = 0;
        for (int i = 0; i + 1 < N; i++) {
            for (int j = 0; j + 1 < N; j++) {
                int a = i * N + j;
                int[] two = {a, a + N, a + N + 1, a, a + N + 1, a + 1};
                for (int k : two) {
                    c[n++] = k;
                }
            }
        }
        return c;
    }

    @Test
    void theLineIsReadOnTheLineNotAtTheEdgeOfAStripAboutIt() {
        double[] x = plane();
        double xl = 0.55;
        DomeHeights h = new DomeHeights(new int[][] {{0, 1, 2}, null}, new int[][] {null, triangles()},
                new double[] {Double.NaN, xl});
        assertTrue(h.onLine(1));
        assertEquals(0.3 * xl + 0.1 * 1.0, h.top(x, 1), 1e-15, "the plane's height at (x_l, y max)");
        double strip = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < N * N; v++) {
            if (Math.abs(x[3 * v] - xl) < 0.1) {
                strip = Math.max(strip, x[3 * v + 2]);
            }
        }
        assertEquals(0.28, strip, 1e-12, "a strip of +/- 0.1 reads its upper edge, x = 0.6");
        // The surface slides 0.05 towards +x: the line now cuts it where x was 0.5.
        for (int v = 0; v < N * N; v++) {
            x[3 * v] += 0.05;
        }
        assertEquals(0.3 * 0.5 + 0.1, h.top(x, 1), 1e-15);
        // And it falls by 2 mm everywhere: the top falls by 2 mm.
        for (int v = 0; v < N * N; v++) {
            x[3 * v + 2] -= 0.002;
        }
        assertEquals(0.3 * 0.5 + 0.1 - 0.002, h.top(x, 1), 1e-15);
        // A half read at its own top: the highest of its candidates.
        assertEquals(Math.max(x[2], Math.max(x[5], x[8])), h.top(x, 0), 0);
    }

    @Test
    void theDoubleDomesLeftIsReadOnItsMidclavicularLineByTheScenesOwnTriangles() throws Exception {
        DiaphragmScene s = DiaphragmSetup.build(org.tensim.scene.diaphragm.DiaphragmSpec.defaults().withMesh(
                DiaphragmSpec.Mesh.defaults().withRings(12))).scene();
        DomeHeights h = MeasuringSites.domeHeights(s, MeasuringSites.DOME_TOP_RADIUS_M);
        double[] x = s.surfaces().mesh().coordinates();
        assertTrue(h.onLine(1), "the double dome's left rises towards the right dome: no top of its own");
        double top = h.top(x, 1);
        // The line's top lies between the lowest and highest upper node within 5 mm of the line.
        double[] b = s.surfaces().mesh().bounds();
        double xl = 0.5 * (b[0] + b[3]) + 0.25 * (b[3] - b[0]);
        double hi = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < s.diaphragmNodes(); v++) {
            if (s.surfaces().isUpper(v) && !s.isAttached(v) && Math.abs(x[3 * v] - xl) < 0.005) {
                hi = Math.max(hi, x[3 * v + 2]);
            }
        }
        assertTrue(Double.isFinite(top) && top <= hi + 0.005 && top > hi - 0.01, top + " against " + hi);
    }
}
