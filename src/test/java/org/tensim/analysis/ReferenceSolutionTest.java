package org.tensim.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.scene.SpringScene;

/** The Hipparchus Dormand-Prince 8(5,3) adapter against an exact solution. */
class ReferenceSolutionTest {
    @Test
    void matchesTheDampedSpringExactly() {
        double w = 10;
        double zeta = 0.1;
        double x0 = 0.1;
        double t = 2;
        double[] x = ReferenceSolution.solve(SpringScene.build(w, zeta, x0), t, 1e-12);
        double exact = SpringScene.REST_LENGTH_M + SpringScene.exactStretch(w, zeta, x0, t);
        assertEquals(exact, x[3], 1e-10);
        assertEquals(0, x[0], 0, "the anchor is fixed");
        assertEquals(0, x[4], 1e-15, "motion stays on the axis");
    }

    @Test
    void refusesScenesWithRigidLinks() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ReferenceSolution.solve(CubeScene.tensegrity(CubeParameters.paper()).topology, 1, 1e-10));
        assertTrue(e.getMessage().contains("6"), "names the link count: " + e.getMessage());
    }

    @Test
    void sceneRegistryNamesTheKnownScenesOnError() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> AccuracyScenes.get("liver"));
        assertTrue(e.getMessage().contains("liver") && e.getMessage().contains("cube-ts"), e.getMessage());
    }
}
