package org.tensim.scene.lungs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.EnumSet;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.testsupport.SharedData;

/** The outer surface of merged lobes: the sheets where two lobes lie on each other are dropped, the rest kept. */
class LungOuterSurfaceTest {
    /** Corners of the unit cube, vertex i at (i &amp; 1, i &gt;&gt; 1 &amp; 1, i &gt;&gt; 2 &amp; 1). */
    private static final int[] CUBE = {
        0, 2, 3, 0, 3, 1, // z = 0, normal -z
        4, 5, 7, 4, 7, 6, // z = 1, +z
        0, 1, 5, 0, 5, 4, // y = 0, -y
        2, 6, 7, 2, 7, 3, // y = 1, +y
        0, 4, 6, 0, 6, 2, // x = 0, -x
        1, 3, 7, 1, 7, 5, // x = 1, +x
    };

    /** Cubes of edge {@code size} (m), the k-th with its low corner at (x0[k], 0, 0), each its own vertices. */
    private static TriangleMesh cubes(double size, double... x0) {
        double[] xyz = new double[24 * x0.length];
        int[] tri = new int[CUBE.length * x0.length];
        for (int k = 0; k < x0.length; k++) {
            for (int i = 0; i < 8; i++) {
                xyz[24 * k + 3 * i] = x0[k] + size * (i & 1);
                xyz[24 * k + 3 * i + 1] = size * (i >> 1 & 1);
                xyz[24 * k + 3 * i + 2] = size * (i >> 2 & 1);
            }
            for (int i = 0; i < CUBE.length; i++) {
                tri[CUBE.length * k + i] = CUBE[i] + 8 * k;
            }
        }
        return new TriangleMesh(xyz, tri);
    }

    @Test
    void twoCubesSharingAFaceLoseExactlyTheCoincidentFaces() {
        TriangleMesh merged = cubes(1, 0, 1);
        assertTrue(merged.signedVolume() > 0, "outward cubes");
        LungOuterSurface s = LungOuterSurface.of(merged, LungOuterSurface.DEFAULT_FISSURE_M);
        assertEquals(2, s.components());
        assertEquals(4, s.droppedTriangles(), "the two coincident faces, two triangles each");
        TriangleMesh o = s.outer();
        assertEquals(20, o.triangleCount());
        assertEquals(10, o.totalArea(), 1e-12, "the 2 x 1 x 1 box's outer area");
        for (int t = 0; t < o.triangleCount(); t++) {
            double xMin = Double.POSITIVE_INFINITY, xMax = Double.NEGATIVE_INFINITY;
            for (int c = 0; c < 3; c++) {
                xMin = Math.min(xMin, o.coord(o.corner(t, c), 0));
                xMax = Math.max(xMax, o.coord(o.corner(t, c), 0));
            }
            assertTrue(xMin < 1 || xMax > 1, "triangle " + t + " lies in the shared plane x = 1");
        }
        assertEquals(16, o.vertexCount(), "every corner of both cubes is still used");
        assertEquals(8, o.boundaryEdgeCount(), "the two open squares' rims, four edges each");
        int[] map = s.mergedVertex();
        assertEquals(o.vertexCount(), map.length);
        for (int v = 0; v < map.length; v++) {
            assertTrue(v == 0 || map[v] > map[v - 1], "increasing merged ids");
            for (int a = 0; a < 3; a++) {
                assertEquals(merged.coord(map[v], a), o.coord(v, a), 0, "outer vertex " + v + " axis " + a);
            }
        }
    }

    @Test
    void separatedCubesAndASingleMeshKeepEverything() {
        TriangleMesh apart = cubes(0.1, 0, 0.105); // 5 mm gap against a 2 mm fissure distance
        LungOuterSurface s = LungOuterSurface.of(apart, 0.002);
        assertEquals(2, s.components());
        assertEquals(0, s.droppedTriangles());
        assertEquals(apart.totalArea(), s.outer().totalArea(), 1e-15);
        assertEquals(24, s.outer().triangleCount());
        // the same gap is a fissure at a 6 mm distance: the facing faces go
        assertEquals(4, LungOuterSurface.of(apart, 0.006).droppedTriangles());
        TriangleMesh one = cubes(0.1, 0);
        LungOuterSurface single = LungOuterSurface.of(one, 1.0); // a distance larger than the cube: nothing else
        assertEquals(1, single.components());
        assertEquals(0, single.droppedTriangles());
        assertEquals(12, single.outer().triangleCount());
    }

    @Test
    void aCubeInsideAnotherIsDroppedWhole() {
        // a 0.1 m cube with a 0.02 m cube in its middle: every inner vertex is inside the outer component
        TriangleMesh big = cubes(0.1, 0);
        double[] xyz = new double[48];
        System.arraycopy(big.coordinates(), 0, xyz, 0, 24);
        for (int i = 0; i < 8; i++) {
            for (int a = 0; a < 3; a++) {
                xyz[24 + 3 * i + a] = 0.04 + 0.02 * (a == 0 ? i & 1 : a == 1 ? i >> 1 & 1 : i >> 2 & 1);
            }
        }
        int[] tri = new int[72];
        for (int i = 0; i < 36; i++) {
            tri[i] = CUBE[i];
            tri[36 + i] = CUBE[i] + 8;
        }
        LungOuterSurface s = LungOuterSurface.of(new TriangleMesh(xyz, tri), 0.002);
        assertEquals(12, s.droppedTriangles(), "the inner cube");
        assertEquals(big.totalArea(), s.outer().totalArea(), 1e-15);
    }

    @Test
    void theSharedLungsLoseTheirFissureSheetsButKeepMostOfTheirSurface() throws Exception {
        for (String f : new String[] {"parts.json", "lung-right-superior.obj", "lung-left-inferior.obj"}) {
            Assumptions.assumeTrue(Files.isRegularFile(SharedData.THORAX.resolve(f)),
                    SharedData.THORAX.resolve(f).toAbsolutePath() + " not found");
        }
        List<TriangleMesh> lungs = LungVolumes.surfaces(ThoraxLoader.load(SharedData.THORAX, EnumSet.of(Group.LUNG)));
        int[] lobes = {3, 2};
        for (int i = 0; i < 2; i++) {
            TriangleMesh merged = lungs.get(i);
            LungOuterSurface s = LungOuterSurface.of(merged, LungOuterSurface.DEFAULT_FISSURE_M);
            String lung = i == 0 ? "right lung" : "left lung";
            assertEquals(lobes[i], s.components(), lung + " lobes");
            double share = s.droppedTriangles() / (double) merged.triangleCount();
            assertTrue(share > 0.10 && share < 0.50, lung + " dropped share " + share);
            double kept = s.outer().totalArea() / merged.totalArea();
            assertTrue(kept > 0.5 && kept < 0.95, lung + " kept area share " + kept);
            assertEquals(merged.triangleCount() - s.droppedTriangles(), s.outer().triangleCount());
        }
    }

    @Test
    void badInputIsRefusedNamingTheValue() {
        TriangleMesh m = cubes(1, 0, 1);
        for (double bad : new double[] {0, -0.001, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> LungOuterSurface.of(m, bad));
            assertTrue(e.getMessage().contains(String.valueOf(bad)), e.getMessage());
        }
        // two coincident cubes lie wholly on each other: nothing is outer
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> LungOuterSurface.of(cubes(1, 0, 0), 0.002));
        assertTrue(e.getMessage().contains("0.002"), e.getMessage());
    }
}
