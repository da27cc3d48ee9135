package org.tensim.scene.thorax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Vec3;

/** A tube swept along a polyline is a closed, outward surface of the section's size, inside negative. */
public class TubeSweepTest {
    /**
     * Every edge is used by exactly two triangles, once in each direction: closed and consistently wound. Returns
     * the enclosed volume by the divergence theorem (positive when the normals point out), m^3.
     */
    public static double closedVolume(TriangleMesh m) {
        Map<Long, Integer> directed = new HashMap<>();
        double volume = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                long key = (long) m.corner(t, k) << 32 | m.corner(t, (k + 1) % 3);
                assertEquals(null, directed.put(key, t), "edge " + m.corner(t, k) + "-" + m.corner(t, (k + 1) % 3)
                        + " used twice in the same direction (triangle " + t + ")");
            }
            double[][] p = new double[3][3];
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++) {
                    p[k][a] = m.coord(m.corner(t, k), a);
                }
            }
            volume += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2]
                    - p[1][2] * p[2][0]) + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6;
        }
        for (long key : directed.keySet()) {
            long reverse = (key & 0xffffffffL) << 32 | key >>> 32;
            assertTrue(directed.containsKey(reverse), "edge " + (key >>> 32) + "-" + (key & 0xffffffffL)
                    + " has no triangle on its other side: the surface is open");
        }
        return volume;
    }

    @Test
    void aStraightTubeIsClosedOutwardAndHoldsItsPolygonalSectionTimesItsLength() {
        Vec3[] line = {new Vec3(0, 0, 0), new Vec3(0.03, 0, 0), new Vec3(0.08, 0, 0)};
        int around = 12;
        double a = 0.006;
        double b = 0.003;
        TriangleMesh m = TubeSweep.sweep(line, new Vec3(0, 0, 1), a, b, around);
        assertEquals(3 * around + 2, m.vertexCount());
        double section = around / 2.0 * a * b * Math.sin(2 * Math.PI / around); // the inscribed polygon's area
        assertEquals(section * 0.08, closedVolume(m), 1e-12, "volume, m^3");
        // The first axis is along the reference: the section is 2a high (z) and 2b thick (y).
        double[] box = m.bounds();
        assertEquals(2 * a, box[5] - box[2], 1e-12);
        assertEquals(2 * b, box[4] - box[1], 1e-12); // around is a multiple of 4: vertices at +/- b
        assertEquals(2, TubeSweep.sourcePoint(2 * around + 5, 3, around));
        assertEquals(0, TubeSweep.sourcePoint(3 * around, 3, around));
        assertEquals(2, TubeSweep.sourcePoint(3 * around + 1, 3, around));
    }

    @Test
    void aBentTubesSignedDistanceIsNegativeOnItsLineAndPositiveOutside() {
        // A quarter circle of radius 0.1 m in 10 points, a rib-sized section.
        int n = 10;
        Vec3[] line = new Vec3[n];
        for (int i = 0; i < n; i++) {
            double phi = 0.5 * Math.PI * i / (n - 1);
            line[i] = new Vec3(0.1 * Math.cos(phi), 0.1 * Math.sin(phi), 0);
        }
        double a = 0.006;
        double b = 0.003;
        TriangleMesh m = TubeSweep.sweep(line, new Vec3(0, 0, 1), a, b, 16);
        assertTrue(closedVolume(m) > 0, "outward");
        DistanceGrid g = DistanceGrid.build(m);
        System.out.println("bent rib-sized tube: " + g.report().describe());
        assertTrue(g.report().windingClosed(), g.report().describe());
        double[] grad = new double[3];
        for (int i = 1; i < n - 1; i++) {
            Vec3 p = line[i];
            double inside = g.distance(p.x(), p.y(), p.z(), grad, 0);
            // at the line: the nearest wall is the thin side, b away (within a cell of the grid)
            assertEquals(-b, inside, DistanceGrid.DEFAULT_CELL_M, "on the line at point " + i);
            Vec3 out = p.times(1.1); // 10 mm outside, radially
            assertEquals(0.01 - b, g.distance(out.x(), out.y(), out.z(), grad, 0), 0.5e-3, "10 mm out at " + i);
            assertTrue(grad[0] * p.x() + grad[1] * p.y() > 0, "the normal points out, away from the line");
        }
    }

    @Test
    void aBadTubeIsRefusedNamingTheValue() {
        Vec3[] line = {new Vec3(0, 0, 0), new Vec3(0, 0, 0.05)};
        IllegalArgumentException parallel = assertThrows(IllegalArgumentException.class,
                () -> TubeSweep.sweep(line, new Vec3(0, 0, 1), 0.01, 0.01, 8));
        assertTrue(parallel.getMessage().contains("parallel"), parallel.getMessage());
        IllegalArgumentException axes = assertThrows(IllegalArgumentException.class,
                () -> TubeSweep.sweep(line, new Vec3(1, 0, 0), -0.01, 0.01, 8));
        assertTrue(axes.getMessage().contains("-0.01"), axes.getMessage());
        assertThrows(IllegalArgumentException.class, () -> TubeSweep.sweep(new Vec3[] {line[0]}, new Vec3(1, 0, 0),
                0.01, 0.01, 8));
    }
}
