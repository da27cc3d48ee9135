package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.testsupport.SharedData;

/**
 * The coarse models of the resolution study ({@link TwoSurfaces#decimated}): the faces' area and the thickness
 * kept, and the muscle's active share the full mesh's, because the coarse model carries the full mesh's free rim
 * instead of the holes and folds the clustering opens. The BodyParts3D cases are skipped, naming the file, where
 * {@code ../shared} is absent.
 */
class DecimatedSurfacesTest {
    private static final Path MESH = SharedData.BODYPARTS3D_DIAPHRAGM;
    /** The study's coarsest cell on the BodyParts3D diaphragm in the thorax (docs/thorax.md). */
    private static final double CELL_M = 0.006;

    private static TwoSurfaces bodyParts() throws Exception {
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        return DiaphragmSetup.loadSurfaces(MESH, MeshUnits.parse("mm"), 0.0025).surfaces();
    }

    /** Area of the triangles with three corners on the given face, m^2. */
    private static double faceArea(TwoSurfaces s, boolean upper) {
        TriangleMesh m = s.mesh();
        double a = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            boolean all = true;
            for (int k = 0; k < 3; k++) {
                all &= s.isUpper(m.corner(t, k)) == upper;
            }
            a += all ? m.area(t) : 0;
        }
        return a;
    }

    /** The area-weighted mean of the fibres' activation over the insertion at the rim (origins left out). */
    static double activeShare(TwoSurfaces s) {
        double[] a = FibreInsertion.activation(s.mesh(), s, null, FibreInsertion.DEFAULT_LENGTH_M);
        double[] area = SurfaceGeometry.vertexAreas(s.mesh());
        double sum = 0;
        double total = 0;
        for (int v = 0; v < a.length; v++) {
            sum += area[v] * a[v];
            total += area[v];
        }
        return sum / total;
    }

    static boolean[] sides(TwoSurfaces s) {
        boolean[] up = new boolean[s.mesh().vertexCount()];
        for (int v = 0; v < up.length; v++) {
            up[v] = s.isUpper(v);
        }
        return up;
    }

    @Test
    void aDecimatedSheetCarriesItsSourcesRimAndKeepsItsShape() {
        TwoSurfaces sheet = TwoSurfaces.offset(FlatMeshes.square(0.1, 24), 0.003);
        TwoSurfaces coarse = sheet.decimated(0.025);
        assertTrue(coarse.mesh().triangleCount() < sheet.mesh().triangleCount() / 4, "decimated to "
                + coarse.mesh().triangleCount() + " of " + sheet.mesh().triangleCount() + " triangles");
        assertTrue(coarse.carriesSourceRim() && !sheet.carriesSourceRim());
        assertArrayEquals(sheet.rimPoints(), coarse.rimPoints(), "the source's rim, point by point");
        assertEquals(sheet.thicknessM(), coarse.thicknessM(), 1e-9, "an offset sheet's thickness");
        assertEquals(coarse.upperCount(), coarse.lowerCount(), "one vertex of each face per cell");
    }

    @Test
    void theStudysCoarseModelKeepsTheFacesAreaAndTheThickness() throws Exception {
        TwoSurfaces full = bodyParts();
        TwoSurfaces coarse = full.decimated(CELL_M);
        System.out.printf(java.util.Locale.ROOT, "decimated at %.1f mm: %d of %d triangles; upper face %.0f of %.0f"
                + " mm^2, lower %.0f of %.0f mm^2, thickness %.2f of %.2f mm%n", CELL_M * 1e3,
                coarse.mesh().triangleCount(), full.mesh().triangleCount(), faceArea(coarse, true) * 1e6,
                faceArea(full, true) * 1e6, faceArea(coarse, false) * 1e6, faceArea(full, false) * 1e6,
                coarse.thicknessM() * 1e3, full.thicknessM() * 1e3);
        assertTrue(coarse.mesh().triangleCount() < 0.5 * full.mesh().triangleCount());
        for (boolean upper : new boolean[] {true, false}) {
            assertEquals(faceArea(full, upper), faceArea(coarse, upper), 0.02 * faceArea(full, upper),
                    upper ? "upper face's area" : "lower face's area");
        }
        assertEquals(full.thicknessM(), coarse.thicknessM(), 0.05 * full.thicknessM(), "thickness");
    }

    /**
     * What made the study's coarse models too stiff in the thorax: clustered at 6 mm, the BodyParts3D diaphragm's
     * own rim (the holes and folds the clustering opens, and its faces meeting inside the sheet) took the active
     * fibre tension off a third of the muscle that the full mesh keeps (area-weighted activation 0.49 against 0.73),
     * and the apex descended 6.0 mm against 11.1. Carrying the full mesh's rim keeps the full mesh's share.
     */
    @Test
    void theCoarseMusclesActiveShareIsTheFullMeshs() throws Exception {
        TwoSurfaces full = bodyParts();
        TwoSurfaces coarse = full.decimated(CELL_M);
        TwoSurfaces ownRim = TwoSurfaces.of(coarse.mesh(), sides(coarse));
        double f = activeShare(full);
        double c = activeShare(coarse);
        double own = activeShare(ownRim);
        System.out.printf(java.util.Locale.ROOT, "active share: full %.3f, decimated %.3f, decimated on its own rim"
                + " %.3f%n", f, c, own);
        assertEquals(f, c, 0.02 * f, "the decimated muscle's active share");
        assertTrue(own < 0.8 * f, "the clustering's own rim should cost the muscle its tension here (the case this"
                + " guards against): " + own + " against " + f);
    }
}
