package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.tensim.scene.thorax.TestMeshes;

/**
 * Quadric-error edge collapse as geometry: a plane decimates onto itself (every quadric's error is zero there),
 * its border stays on the border, a closed sphere stays a closed, consistently wound 2-manifold near its
 * sphere, and vertices of two groups never merge.
 */
class QuadricDecimationTest {
    @Test
    void aPlaneDecimatesExactlyOntoItselfAndKeepsItsBorder() {
        double l = 0.1;
        TriangleMesh square = FlatMeshes.square(l, 24);
        QuadricDecimation.Result r = QuadricDecimation.simplify(square, new int[square.vertexCount()], 200);
        TriangleMesh m = r.mesh();
        assertTrue(m.triangleCount() >= 200 && m.triangleCount() <= 202, m.triangleCount() + " triangles");
        for (int v = 0; v < m.vertexCount(); v++) {
            assertEquals(0.0, m.coord(v, 2), 0.0, "vertex " + v + " off the plane");
        }
        MeshEdges.manifold(m);
        assertEquals(4 * l * l, m.totalArea(), 1e-12 * l * l, "the square's area");
        boolean[] border = MeshCleaner.boundaryVertices(m);
        double[] n = new double[3];
        for (int t = 0; t < m.triangleCount(); t++) {
            m.normal(t, n);
            assertTrue(n[2] > 0, "triangle " + t + " turned over");
        }
        for (int v = 0; v < m.vertexCount(); v++) {
            if (border[v]) {
                double edge = Math.max(Math.abs(m.coord(v, 0)), Math.abs(m.coord(v, 1)));
                assertEquals(l, edge, 1e-15, "border vertex " + v + " left the square's border");
            }
        }
    }

    @Test
    void aClosedSphereStaysClosedOnItsSphere() {
        double r = 0.05;
        TriangleMesh sphere = TestMeshes.icosphere(new double[] {0.01, -0.02, 0.3}, r, 4);
        QuadricDecimation.Result d = QuadricDecimation.simplify(sphere, new int[sphere.vertexCount()], 800);
        TriangleMesh m = d.mesh();
        assertEquals(800, m.triangleCount(), 2, "triangles");
        int[] edges = MeshEdges.manifold(m);
        assertEquals(0, edges[0], "edges used by one triangle: the sphere opened");
        assertEquals(2, m.vertexCount() - edges[1] + m.triangleCount(), "Euler characteristic of a sphere");
        for (int v = 0; v < m.vertexCount(); v++) {
            double dx = m.coord(v, 0) - 0.01;
            double dy = m.coord(v, 1) + 0.02;
            double dz = m.coord(v, 2) - 0.3;
            assertEquals(r, Math.sqrt(dx * dx + dy * dy + dz * dz), 0.01 * r, "vertex " + v + " off the sphere");
        }
        assertEquals(sphere.totalArea(), m.totalArea(), 0.02 * sphere.totalArea(), "area");
    }

    @Test
    void groupsNeverMergeAndTheirBorderStaysPut() {
        TriangleMesh sphere = TestMeshes.icosphere(new double[] {0, 0, 0}, 0.05, 4);
        int[] groups = new int[sphere.vertexCount()];
        for (int v = 0; v < groups.length; v++) {
            groups[v] = sphere.coord(v, 2) > 0.01 ? 1 : 0;
        }
        QuadricDecimation.Result d = QuadricDecimation.simplify(sphere, groups, 600);
        TriangleMesh m = d.mesh();
        assertEquals(0, MeshEdges.manifold(m)[0], "the sphere opened");
        int[] mixed = new int[2];
        for (TriangleMesh mesh : new TriangleMesh[] {sphere, m}) {
            int[] g = mesh == sphere ? groups : d.groups();
            for (int t = 0; t < mesh.triangleCount(); t++) {
                int s = g[mesh.corner(t, 0)] + g[mesh.corner(t, 1)] + g[mesh.corner(t, 2)];
                if (s == 1 || s == 2) {
                    for (int k = 0; k < 3; k++) {
                        int v = mesh.corner(t, k);
                        mixed[mesh == sphere ? 0 : 1]++;
                        if (mesh == m) {
                            assertTrue(isVertexOf(sphere, m, v), "border vertex " + v + " moved");
                        }
                    }
                }
            }
        }
        assertTrue(mixed[1] > 0 && mixed[1] < mixed[0], "the band between the groups, coarsened along itself: "
                + Arrays.toString(mixed));
        for (int v = 0; v < m.vertexCount(); v++) {
            assertEquals(d.groups()[v] == 1, m.coord(v, 2) > 0.01 - 1e-12, "vertex " + v + " crossed groups");
        }
    }

    private static boolean isVertexOf(TriangleMesh source, TriangleMesh m, int v) {
        for (int w = 0; w < source.vertexCount(); w++) {
            if (source.coord(w, 0) == m.coord(v, 0) && source.coord(w, 1) == m.coord(v, 1)
                    && source.coord(w, 2) == m.coord(v, 2)) {
                return true;
            }
        }
        return false;
    }

    @Test
    void badInputIsRefusedNamingTheValue() {
        TriangleMesh square = FlatMeshes.square(0.1, 4);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> QuadricDecimation.simplify(square, new int[3], 10));
        assertTrue(e.getMessage().contains("3 groups"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> QuadricDecimation.simplify(square, new int[square.vertexCount()], 2));
        assertTrue(e.getMessage().contains("2"), e.getMessage());
    }
}
