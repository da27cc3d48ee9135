package org.tensim.scene.thorax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.tensim.io.ProjectFolder;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.SurfaceDistance;
import org.tensim.io.mesh.TriangleMesh;

class DistanceGridTest {
    private static final Path THORAX = ProjectFolder.resolve("..", "shared", "meshes", "thorax");
    private static final double[] C = {0.01, -0.12, 1.15};
    private static final double R = 0.05;

    @Test
    void aSphereIsItsAnalyticDistanceWithinACell() {
        double h = 2e-3;
        DistanceGrid g = DistanceGrid.build(TestMeshes.icosphere(C, R, 4), h, 20e-3);
        assertEquals(0, g.report().boundaryEdges());
        assertTrue(g.report().windingClosed(), g.report().describe());
        Random rnd = new Random(3);
        double[] grad = new double[4];
        int inside = 0;
        for (int s = 0; s < 4000; s++) {
            // points from the centre to well outside the grid (90 mm from a 50 mm sphere, the grid reaching 70 mm)
            double[] p = new double[3];
            double[] u = randomUnit(rnd);
            double r = rnd.nextDouble() * 0.09;
            for (int a = 0; a < 3; a++) {
                p[a] = C[a] + r * u[a];
            }
            double d = g.distance(p[0], p[1], p[2], grad, 1);
            double exact = r - R;
            inside += exact < 0 ? 1 : 0;
            if (outsideGrid(g, p)) {
                // beyond the grid: a positive lower bound, never more than a cell above the truth
                assertTrue(d > 0 && d <= exact + h, "outside the grid at r = " + r + ": " + d);
                continue;
            }
            assertEquals(exact, d, h, "distance at r = " + r);
            if (r > R / 2) { // away from the centre, where the distance has a kink
                double dot = grad[1] * u[0] + grad[2] * u[1] + grad[3] * u[2];
                assertTrue(dot > 0.99, "gradient along the radius at r = " + r + ": cos = " + dot);
            }
        }
        assertTrue(inside > 500, "the samples reach inside: " + inside);
    }

    @Test
    void aBoxIsItsAnalyticDistanceWithinACellAndItsFaceNormals() {
        double[] lo = {-0.02, 0.10, 0.95};
        double[] hi = {0.02, 0.13, 0.97};
        double h = 1e-3;
        DistanceGrid g = DistanceGrid.build(TestMeshes.box(lo, hi), h, 10e-3);
        assertTrue(g.report().windingClosed(), g.report().describe());
        double[] b = g.boundsM();
        for (int a = 0; a < 3; a++) {
            assertEquals(lo[a], b[a], 1e-15);
            assertEquals(hi[a], b[a + 3], 1e-15);
        }
        Random rnd = new Random(4);
        double[] grad = new double[3];
        int faceChecks = 0;
        for (int s = 0; s < 4000; s++) {
            double[] p = new double[3];
            double[] q = new double[3];
            for (int a = 0; a < 3; a++) {
                p[a] = lo[a] - 8e-3 + rnd.nextDouble() * (hi[a] - lo[a] + 16e-3);
                q[a] = Math.abs(p[a] - (lo[a] + hi[a]) / 2) - (hi[a] - lo[a]) / 2;
            }
            double out = Math.sqrt(sq(Math.max(q[0], 0)) + sq(Math.max(q[1], 0)) + sq(Math.max(q[2], 0)));
            double in = Math.min(Math.max(q[0], Math.max(q[1], q[2])), 0);
            double exact = out + in;
            double d = g.distance(p[0], p[1], p[2], grad, 0);
            assertEquals(exact, d, h, "box distance at " + java.util.Arrays.toString(p));
            // where one face is nearest by more than two cells (inside) or the point is over a face (outside),
            // the gradient is that face's normal
            int face = nearestFace(q, 2 * h);
            if (face >= 0) {
                faceChecks++;
                double sign = p[face] > (lo[face] + hi[face]) / 2 ? 1 : -1;
                assertEquals(sign, grad[face], 1e-3, "gradient along the normal of face " + face + " at "
                        + java.util.Arrays.toString(p) + ": " + java.util.Arrays.toString(grad));
            }
        }
        assertTrue(faceChecks > 1000, "face-normal checks " + faceChecks);
    }

    @Test
    void aSphereWithAHoleKeepsItsSignAwayFromTheHole() {
        double h = 2e-3;
        TriangleMesh open = TestMeshes.without(TestMeshes.icosphere(C, R, 3),
                c -> c[2] - C[2] > 0.97 * R); // a cap of a few triangles around the top pole
        DistanceGrid g = DistanceGrid.build(open, h, 10e-3);
        assertTrue(g.report().boundaryEdges() > 0, g.report().describe());
        assertFalse(g.report().windingClosed(), "the winding number notices the hole: " + g.report().describe());
        Random rnd = new Random(5);
        double[] grad = new double[3];
        for (int s = 0; s < 2000; s++) {
            double[] u = randomUnit(rnd);
            if (u[2] > 0.5) {
                continue; // within 60 degrees of the hole
            }
            double r = R * (rnd.nextBoolean() ? 0.3 + 0.6 * rnd.nextDouble() : 1.1 + 0.3 * rnd.nextDouble());
            double d = g.distance(C[0] + r * u[0], C[1] + r * u[1], C[2] + r * u[2], grad, 0);
            assertEquals(Math.signum(r - R), Math.signum(d), "sign at r = " + r + " (distance " + d + ")");
            assertEquals(r - R, d, h + 0.002 * R, "distance at r = " + r);
        }
        assertTrue(g.distance(C[0], C[1], C[2], grad, 0) < -0.9 * R, "the centre is deep inside");
    }

    @Test
    void refusesAnUnreasonableGrid() {
        TriangleMesh box = TestMeshes.box(new double[] {0, 0, 0}, new double[] {1, 1, 1});
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DistanceGrid.build(box, 1e-3, 0));
        assertTrue(e.getMessage().contains("coarser"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> DistanceGrid.build(box, -1, 0));
        assertThrows(IllegalArgumentException.class, () -> DistanceGrid.build(box, 0.1, Double.NaN));
    }

    @Test
    void aSharedRibTwoMillimetresOffItsSurface() throws IOException, MeshFormatException {
        Path file = THORAX.resolve("rib-r7.obj");
        Assumptions.assumeTrue(Files.isRegularFile(file), file + " not found");
        TriangleMesh rib = MeshLoader.load(file, MeshUnits.MM, MeshCleaner.Options.defaults().keepingAllComponents())
                .mesh();
        DistanceGrid g = DistanceGrid.build(rib);
        System.out.println("rib-r7: " + g.report().describe());
        double h = g.report().cellM();
        double[] n = TestMeshes.vertexNormals(rib);
        SurfaceDistance exact = new SurfaceDistance(rib.coordinates(), rib.triangles());
        double[] grad = new double[3];
        int nv = rib.vertexCount();
        int[] clear = new int[2];
        int[] off = new int[2];
        int wrongSign = 0;
        double worstVsExact = 0;
        for (int v = 0; v < nv; v++) {
            for (int side = 0; side < 2; side++) {
                double s = side == 0 ? 2e-3 : -2e-3;
                double x = rib.coord(v, 0) + s * n[3 * v];
                double y = rib.coord(v, 1) + s * n[3 * v + 1];
                double z = rib.coord(v, 2) + s * n[3 * v + 2];
                double d = g.distance(x, y, z, grad, 0);
                double u = exact.distance(x, y, z);
                // the grid's own error, whatever the rib's shape there
                worstVsExact = Math.max(worstVsExact, Math.abs(Math.abs(d) - u));
                // where the rib is thin or sharply curved, a point 2 mm along the normal is nearer another part
                // of the surface: +-2 mm is expected only where the exact distance says so
                if (Math.abs(u - 2e-3) < 0.1e-3) {
                    clear[side]++;
                    off[side] += Math.abs(d - s) > 1e-3 ? 1 : 0;
                    wrongSign += Math.signum(d) != Math.signum(s) ? 1 : 0;
                }
            }
        }
        System.out.printf("rib-r7: %d vertices; 2 mm clear of the rest of the surface: %d outside, %d inside;"
                + " of these off by > 1 mm: %d, %d, wrong sign %d; worst |grid| - exact %.3f mm%n", nv, clear[0],
                clear[1], off[0], off[1], wrongSign, worstVsExact * 1e3);
        assertTrue(clear[0] > 0.9 * nv && clear[1] > 0.5 * nv, "most offsets are clear of the rest of the rib");
        assertEquals(0, off[0] + off[1], "+-2 mm points within 1 mm of +-2 mm");
        assertEquals(0, wrongSign, "signs");
        assertTrue(worstVsExact < h, "worst deviation from the exact distance " + worstVsExact + " m, cell " + h);
    }

    /** The axis of the only face region the point is in with a clearance of {@code gap}, or -1. */
    private static int nearestFace(double[] q, double gap) {
        int best = 0;
        for (int a = 1; a < 3; a++) {
            if (q[a] > q[best]) {
                best = a;
            }
        }
        for (int a = 0; a < 3; a++) {
            if (a != best && q[a] > q[best] - gap) {
                return -1;
            }
            if (a != best && q[best] > 0 && q[a] > -gap) {
                return -1; // outside, but beyond an edge of the face
            }
        }
        return best;
    }

    private static boolean outsideGrid(DistanceGrid g, double[] p) {
        double[] b = g.gridBoundsM();
        for (int a = 0; a < 3; a++) {
            if (p[a] < b[a] || p[a] > b[a + 3]) {
                return true;
            }
        }
        return false;
    }

    private static double[] randomUnit(Random r) {
        double[] u = {r.nextGaussian(), r.nextGaussian(), r.nextGaussian()};
        double l = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        return new double[] {u[0] / l, u[1] / l, u[2] / l};
    }

    private static double sq(double x) {
        return x * x;
    }
}
