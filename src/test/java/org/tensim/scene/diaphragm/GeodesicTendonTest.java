package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.util.ArrayDeque;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;

/** The tendon grown by geodesic distance from the dome tops ({@link GeodesicTendon}). */
class GeodesicTendonTest {
    private static final double[] SHARES = {0.10, 0.12, 0.15};

    @Test
    void theDoubleDomesTendonHasTheAskedShareAndIsOnePiece() {
        for (int rings : new int[] {14, 28}) {
            TwoSurfaces s = DiaphragmSetup.generatedSurfaces(rings);
            for (double f : SHARES) {
                GeodesicTendon.Region r = GeodesicTendon.grow(s, f);
                checkRegion(s, r, f, rings + " rings");
            }
        }
    }

    @Test
    void theRegionIsTheSameAtTwoResolutions() {
        TwoSurfaces coarse = DiaphragmSetup.generatedSurfaces(14);
        TwoSurfaces fine = DiaphragmSetup.generatedSurfaces(28);
        for (double f : SHARES) {
            GeodesicTendon.Region a = GeodesicTendon.grow(coarse, f);
            GeodesicTendon.Region b = GeodesicTendon.grow(fine, f);
            double gap = Math.sqrt(sq(a.centroid()[0] - b.centroid()[0]) + sq(a.centroid()[1] - b.centroid()[1])
                    + sq(a.centroid()[2] - b.centroid()[2]));
            System.out.printf("GeodesicTendon double dome F=%.2f: share %.4f (14 rings) %.4f (28 rings),"
                    + " radius %.1f / %.1f mm, centroid gap %.2f mm%n", f, a.share(), b.share(),
                    1e3 * a.radiusM(), 1e3 * b.radiusM(), 1e3 * gap);
            assertEquals(a.share(), b.share(), 0.01, "F = " + f + ": the same area share at 14 and 28 rings");
            assertTrue(gap < 0.005, "F = " + f + ": centroids " + 1e3 * gap + " mm apart; expected under 5 mm");
        }
    }

    @Test
    void theBodyParts3dTendonHasTheAskedShareAndIsOnePiece() throws Exception {
        assumeTrue(Files.isRegularFile(BodyPartsDiaphragmTest.MESH), "needs the BodyParts3D diaphragm mesh "
                + BodyPartsDiaphragmTest.MESH.getFileName() + " at " + BodyPartsDiaphragmTest.MESH.toAbsolutePath());
        TriangleMesh mesh = MeshLoader.load(BodyPartsDiaphragmTest.MESH, MeshUnits.MM).mesh();
        TwoSurfaces s = DiaphragmSetup.surfaces(mesh, 0.0025).surfaces();
        for (double f : SHARES) {
            GeodesicTendon.Region r = GeodesicTendon.grow(s, f);
            System.out.printf("GeodesicTendon BodyParts3D F=%.2f: share %.4f, radius %.1f mm, centroid"
                    + " (%.1f, %.1f, %.1f) mm%n", f, r.share(), 1e3 * r.radiusM(), 1e3 * r.centroid()[0],
                    1e3 * r.centroid()[1], 1e3 * r.centroid()[2]);
            checkRegion(s, r, f, "BodyParts3D");
        }
    }

    /**
     * On a flat square the geodesic distance is the straight one, and the triangles' edges (a grid with
     * one diagonal per cell) are at most sqrt(2) longer: the region is between the two discs that bound
     * it, around a given seed.
     */
    @Test
    void aGivenSeedGrowsADiscBoundedByTheEdgeMetric() {
        double l = 0.1;
        int n = 40;
        double h = 2 * l / n;
        TwoSurfaces s = TwoSurfaces.offset(FlatMeshes.square(l, n), 0.0025);
        double sx = 0.013;
        double sy = -0.021;
        GeodesicTendon.Region r = GeodesicTendon.grow(s, new double[][] {{sx, sy}}, 0.1);
        checkRegion(s, r, 0.1, "flat square");
        TriangleMesh m = s.mesh();
        for (int v = 0; v < m.vertexCount(); v++) {
            if (!s.isUpper(v)) {
                continue;
            }
            double d = Math.hypot(m.coord(v, 0) - sx, m.coord(v, 1) - sy);
            if (d > r.radiusM() + 1e-12) {
                assertFalse(r.tendon()[v], "vertex " + v + " at " + d + " m beyond the radius " + r.radiusM());
            }
            // start within a cell's diagonal of the seed, then at most sqrt(2) times the straight way
            if (Math.sqrt(2) * d + Math.sqrt(2) * h < r.radiusM()) {
                assertTrue(r.tendon()[v], "vertex " + v + " at " + d + " m well inside the radius " + r.radiusM());
            }
        }
    }

    /**
     * The level is the signed distance to the tendon's edge: positive on the tendon's upper vertices, negative
     * off it, at most the radius, the partner's on a lower vertex; its zero, interpolated in each upper triangle
     * (where the fibres are clipped), encloses about the share asked for at both resolutions.
     */
    @Test
    void theLevelIsTheSignedDistanceToTheEdgeAndItsZeroEnclosesTheShare() {
        for (int rings : new int[] {14, 28}) {
            TwoSurfaces s = DiaphragmSetup.generatedSurfaces(rings);
            GeodesicTendon.Region r = GeodesicTendon.grow(s, 0.12);
            TriangleMesh m = s.mesh();
            double[] level = r.level();
            for (int v = 0; v < m.vertexCount(); v++) {
                assertTrue(level[v] <= r.radiusM() && level[v] >= -r.radiusM(), rings + " rings, vertex " + v);
                if (!s.isUpper(v)) {
                    assertEquals(s.partner(v) >= 0 ? level[s.partner(v)] : -r.radiusM(), level[v], 0,
                            rings + " rings, lower vertex " + v);
                } else if (level[v] != 0) {
                    assertEquals(level[v] > 0, r.tendon()[v], rings + " rings, vertex " + v + " at level " + level[v]);
                }
            }
            double all = 0;
            double tendon = 0;
            double[] h = new double[3];
            for (int t : s.upperTriangles()) {
                double a = triangleArea(m, t);
                for (int k = 0; k < 3; k++) {
                    h[k] = level[m.corner(t, k)];
                }
                all += a;
                tendon += a * (1 - MuscleFibres.muscleFraction(h));
            }
            System.out.printf("geodesic tendon, %d rings: vertex share %.4f, clipped at the level's zero %.4f%n",
                    rings, r.share(), tendon / all);
            assertEquals(0.12, tendon / all, 0.005, rings + " rings: the clipped tendon's share");
        }
    }

    private static double triangleArea(TriangleMesh m, int t) {
        double[][] p = new double[3][3];
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) {
                p[k][a] = m.coord(m.corner(t, k), a);
            }
        }
        double ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1], uz = p[1][2] - p[0][2];
        double vx = p[2][0] - p[0][0], vy = p[2][1] - p[0][1], vz = p[2][2] - p[0][2];
        return 0.5 * Math.sqrt(Math.pow(uy * vz - uz * vy, 2) + Math.pow(uz * vx - ux * vz, 2)
                + Math.pow(ux * vy - uy * vx, 2));
    }

    @Test
    void badInputIsRefusedNamingTheValue() {
        TwoSurfaces s = DiaphragmSetup.generatedSurfaces(6);
        for (double f : new double[] {0, 1, -0.1, Double.NaN}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> GeodesicTendon.grow(s, f));
            assertTrue(e.getMessage().contains(String.valueOf(f)), e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> GeodesicTendon.grow(s, new double[0][], 0.1));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GeodesicTendon.grow(s, new double[][] {{0, 0}, {0, Double.NaN}}, 0.1));
        assertTrue(e.getMessage().contains("seed 1") && e.getMessage().contains("NaN"), e.getMessage());
    }

    /**
     * The share, counted here from the vertex areas, is within 1 % of F and within half the largest
     * upper vertex's area of it; the region holds one piece of the upper surface; each lower vertex
     * follows its partner.
     */
    private static void checkRegion(TwoSurfaces s, GeodesicTendon.Region r, double f, String what) {
        TriangleMesh m = s.mesh();
        double[] area = SurfaceGeometry.vertexAreas(m);
        double upper = 0;
        double tendon = 0;
        double largest = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            if (s.isUpper(v)) {
                upper += area[v];
                tendon += r.tendon()[v] ? area[v] : 0;
                largest = Math.max(largest, area[v]);
            } else if (s.partner(v) >= 0) {
                assertEquals(r.tendon()[s.partner(v)], r.tendon()[v], what + ": lower vertex " + v);
            }
        }
        assertEquals(tendon / upper, r.share(), 1e-12, what + ": the reported share is the vertices'");
        assertEquals(f, r.share(), 0.01, what + ": share within 1 % of " + f);
        assertEquals(f, r.share(), 0.5 * largest / upper + 1e-12, what + ": within half a vertex of " + f);
        assertEquals(1, upperComponents(s, r.tendon()), what + ", F = " + f + ": one piece");
    }

    /** Connected pieces of the tendon's upper vertices along the upper triangles' edges. */
    static int upperComponents(TwoSurfaces s, boolean[] tendon) {
        TriangleMesh m = s.mesh();
        int[][] adj = GeodesicTendon.adjacency(m, s.upperTriangles());
        boolean[] seen = new boolean[m.vertexCount()];
        int pieces = 0;
        for (int v0 = 0; v0 < m.vertexCount(); v0++) {
            if (!s.isUpper(v0) || !tendon[v0] || seen[v0]) {
                continue;
            }
            pieces++;
            ArrayDeque<Integer> todo = new ArrayDeque<>();
            todo.add(v0);
            seen[v0] = true;
            while (!todo.isEmpty()) {
                for (int w : adj[todo.poll()]) {
                    if (s.isUpper(w) && tendon[w] && !seen[w]) {
                        seen[w] = true;
                        todo.add(w);
                    }
                }
            }
        }
        return pieces;
    }

    private static double sq(double x) {
        return x * x;
    }
}
