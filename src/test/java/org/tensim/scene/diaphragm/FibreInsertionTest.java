package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.Simulation;

/**
 * The fibres' insertion ({@link FibreInsertion}): the active stress rises smoothly from 0 at the
 * fibres' ends, the rim is found on closed shells and open sheets, and on the dome the free rim is
 * no longer pulled up by the fibres' tension.
 */
class FibreInsertionTest {
    private static final double L = FibreInsertion.DEFAULT_LENGTH_M;

    @Test
    void theActiveStressRisesSmoothlyFromZeroAtTheEndsToItsFullValue() {
        assertEquals(0, FibreInsertion.ramp(0, L));
        assertEquals(0.5, FibreInsertion.ramp(L / 2, L), 1e-15);
        assertEquals(1, FibreInsertion.ramp(L, L));
        assertEquals(1, FibreInsertion.ramp(3 * L, L));
        double h = 1e-7;
        double slopeBelow = (FibreInsertion.ramp(L, L) - FibreInsertion.ramp(L - h, L)) / h;
        assertEquals(0, slopeBelow, 1e-4 / L, "no kink where the full stress is reached");
        for (int i = 0; i < 50; i++) {
            assertTrue(FibreInsertion.ramp((i + 1) * L / 50, L) > FibreInsertion.ramp(i * L / 50, L), "rises");
        }
        TwoSurfaces sheet = TwoSurfaces.offset(FlatMeshes.square(0.1, 2), 0.0025);
        assertThrows(IllegalArgumentException.class, () -> FibreInsertion.activation(sheet.mesh(), sheet, null,
                -0.01));
    }

    @Test
    void theRimIsAnOpenSheetsBoundaryAndWhereAClosedShellsFacesMeet() {
        // an open sheet made a shell by an offset copy: each face's boundary is rim
        TwoSurfaces open = TwoSurfaces.offset(FlatMeshes.square(0.1, 6), 0.0025);
        TriangleMesh sheet = open.mesh();
        boolean[] rim = FibreInsertion.rim(sheet, open);
        for (int v = 0; v < rim.length; v++) {
            double x = sheet.coord(v, 0);
            double y = sheet.coord(v, 1);
            double[] b = sheet.bounds();
            boolean edge = Math.abs(x - b[0]) < 1e-9 || Math.abs(y - b[1]) < 1e-9 || Math.abs(x - b[3]) < 1e-9
                    || Math.abs(y - b[4]) < 1e-9;
            assertEquals(edge, rim[v], "vertex " + v + " at (" + x + ", " + y + ")");
        }
        TwoSurfaces shell = TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult()
                .withRings(14)));
        boolean[] shellRim = FibreInsertion.rim(shell.mesh(), shell);
        int upper = 0;
        int lower = 0;
        int top = 0;
        for (int v = 0; v < shellRim.length; v++) {
            if (shellRim[v]) {
                upper += shell.isUpper(v) ? 1 : 0;
                lower += shell.isUpper(v) ? 0 : 1;
            }
            top = shell.mesh().coord(v, 2) > shell.mesh().coord(top, 2) ? v : top;
        }
        assertTrue(upper > 0 && lower > 0, "the rim has vertices of both faces: " + upper + ", " + lower);
        assertTrue(upper + lower < shellRim.length / 5, "the rim is an edge, not the sheet: " + (upper + lower) + " of "
                + shellRim.length);
        assertTrue(!shellRim[top], "the dome's top is not on the rim");
        double[] d = FibreInsertion.distanceTo(shell.mesh(), shellRim);
        assertTrue(d[top] > 0.05, "the top lies far from the rim: " + d[top] + " m");
    }

    /**
     * With the ribs still, the fibres pull the dome down; the rim below the attachment band (the
     * lateral skirt of the double dome, beyond every cage segment's reach) is free. With the full
     * active stress up to the edge, the fibres ending there pulled it up (15.6 mm on average at
     * end-inspiration on the 43-ring mesh, docs/diaphragm.md); inserted, it hangs.
     */
    @Test
    void theFibresNoLongerPullTheFreeRimUp() throws Exception {
        BoundaryConditions bc = BoundaryConditions.defaults().withMuscleLoad(BoundaryConditions.MuscleLoad.FIBRES);
        DiaphragmScene scene = SceneFixture.coarse(14, 0, DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, bc);
        TwoSurfaces s = scene.surfaces();
        boolean[] rim = FibreInsertion.rim(s.mesh(), s);
        Simulation sim = scene.newSimulation();
        sim.runUntil(scene.cycle().inspirationS(), scene.recommendedTimeStep());
        int free = 0;
        double rise = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < scene.diaphragmNodes(); v++) {
            if (rim[v] && !scene.isAttached(v)) {
                free++;
                rise = Math.max(rise, sim.state().x[3 * v + 2] - sim.state().x0[3 * v + 2]);
            }
        }
        int apex = scene.apexNode();
        double descent = sim.state().x0[3 * apex + 2] - sim.state().x[3 * apex + 2];
        assertTrue(free > 0, "the double dome has a free rim below the band");
        assertTrue(descent > 0.010, "the fibres pull the dome down: " + descent + " m");
        assertTrue(rise < 0.004, "the free rim is not pulled up: it rose " + rise * 1e3 + " mm");
    }
}
