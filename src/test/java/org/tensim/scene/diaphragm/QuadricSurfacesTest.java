package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Locale;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.MeshEdges;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.testsupport.SharedData;

/**
 * The resolution study's coarse models by quadric-error edge collapse ({@link Decimation#QUADRIC}) on the
 * BodyParts3D diaphragm: what the clustering breaks is kept. The shell stays as closed as it was, each face a
 * consistently wound 2-manifold, the faces' areas and the thickness kept, the triangle count the target, and
 * the rim where the faces meet made of the full mesh's own rim vertices, unmoved; so the coarse muscle's own rim
 * gives the full mesh's active share. Skipped, naming the file, where {@code ../shared} is absent.
 */
class QuadricSurfacesTest {
    private static final Path MESH = SharedData.BODYPARTS3D_DIAPHRAGM;

    private static TwoSurfaces bodyParts() throws Exception {
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        return DiaphragmSetup.loadSurfaces(MESH, MeshUnits.parse("mm"), 0.0025).surfaces();
    }

    /** The triangles with three corners on one face, as a mesh of the shell's vertices. */
    private static TriangleMesh face(TwoSurfaces s, boolean upper) {
        TriangleMesh m = s.mesh();
        int[] t = new int[3 * m.triangleCount()];
        int n = 0;
        for (int i = 0; i < m.triangleCount(); i++) {
            if (s.isUpper(m.corner(i, 0)) == upper && s.isUpper(m.corner(i, 1)) == upper
                    && s.isUpper(m.corner(i, 2)) == upper) {
                for (int k = 0; k < 3; k++) {
                    t[n++] = m.corner(i, k);
                }
            }
        }
        return new TriangleMesh(m.coordinates(), java.util.Arrays.copyOf(t, n));
    }

    @Test
    void aSheetKeepsItsThicknessItsRimAndItsArea() {
        TwoSurfaces sheet = TwoSurfaces.offset(FlatMeshes.square(0.1, 24), 0.003);
        TwoSurfaces coarse = Decimation.QUADRIC.coarsen(sheet, 0.025);
        int target = (int) Math.round(sheet.mesh().totalArea() / (Math.sqrt(3) / 4 * 0.025 * 0.025));
        assertEquals(target, coarse.mesh().triangleCount(), 2, "triangles");
        assertEquals(sheet.thicknessM(), coarse.thicknessM(), 1e-12, "an offset sheet's thickness");
        for (boolean upper : new boolean[] {true, false}) {
            assertEquals(face(sheet, upper).totalArea(), face(coarse, upper).totalArea(), 1e-12, "face area");
            for (int v = 0; v < coarse.mesh().vertexCount(); v++) {
                if (coarse.isUpper(v) == upper) {
                    assertEquals(upper ? 0 : -0.003, coarse.mesh().coord(v, 2), 1e-15, "vertex " + v + " off its face");
                }
            }
        }
        assertTrue(coarse.carriesSourceRim());
    }

    @Test
    void theBodyParts3dShellStaysAsClosedAsItWasWithItsAreaThicknessAndRim() throws Exception {
        TwoSurfaces full = bodyParts();
        int target = full.mesh().triangleCount() / 2;
        TwoSurfaces coarse = Decimation.quadric(full, target);
        int[] fullEdges = MeshEdges.manifold(full.mesh());
        int[] coarseEdges = MeshEdges.manifold(coarse.mesh());
        System.out.printf(Locale.ROOT, "quadric to %d of %d triangles; edges used once %d (full %d)%n",
                coarse.mesh().triangleCount(), full.mesh().triangleCount(), coarseEdges[0], fullEdges[0]);
        assertEquals(target, coarse.mesh().triangleCount(), 2, "triangles");
        assertTrue(coarseEdges[0] <= fullEdges[0], "open edges: " + coarseEdges[0] + " against " + fullEdges[0]);
        for (boolean upper : new boolean[] {true, false}) {
            MeshEdges.manifold(face(coarse, upper));
            double a = face(full, upper).totalArea();
            double c = face(coarse, upper).totalArea();
            System.out.printf(Locale.ROOT, "%s face %.0f of %.0f mm^2%n", upper ? "upper" : "lower", c * 1e6, a * 1e6);
            assertEquals(a, c, 0.02 * a, upper ? "upper face's area" : "lower face's area");
        }
        System.out.printf(Locale.ROOT, "thickness %.3f of %.3f mm%n", coarse.thicknessM() * 1e3,
                full.thicknessM() * 1e3);
        assertEquals(full.thicknessM(), coarse.thicknessM(), 0.03 * full.thicknessM(), "thickness");
        TwoSurfaces own = TwoSurfaces.of(coarse.mesh(), DecimatedSurfacesTest.sides(coarse));
        Set<String> fullRim = new HashSet<>();
        boolean[] fr = full.ownRim();
        for (int v = 0; v < fr.length; v++) {
            if (fr[v]) {
                fullRim.add(key(full.mesh(), v));
            }
        }
        boolean[] cr = own.ownRim();
        for (int v = 0; v < cr.length; v++) {
            assertTrue(!cr[v] || fullRim.contains(key(coarse.mesh(), v)), "coarse rim vertex " + v
                    + " is not one of the full mesh's rim vertices");
        }
        double f = DecimatedSurfacesTest.activeShare(full);
        double c = DecimatedSurfacesTest.activeShare(own);
        System.out.printf(Locale.ROOT, "active share: full %.3f, quadric on its own rim %.3f%n", f, c);
        assertEquals(f, c, 0.03 * f, "the coarse muscle's active share on its own rim");
    }

    private static String key(TriangleMesh m, int v) {
        return m.coord(v, 0) + "," + m.coord(v, 1) + "," + m.coord(v, 2);
    }
}
