package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.ViewScene;

class IntegratorCatalogTest {
    @Test
    void offersEveryRegisteredIntegratorThePapersFirst() {
        var l = IntegratorCatalog.available();
        assertEquals("rk2", l.get(0).name());
        assertEquals(Integrators.names().size() + 2, l.size(),
                "the registry's, the real-time implicit Euler and BDF2 with two Newton iterations");
        for (IntegratorChoice c : l) {
            if (c.name().equals(IntegratorCatalog.REAL_TIME_IMPLICIT)) {
                ImplicitEuler ie = (ImplicitEuler) c.create();
                assertEquals("implicit-euler", ie.name());
                // It stops its CG at 1e-3: on a stiff system it needs fewer products than the registry's.
                assertEquals(IntegratorCatalog.REAL_TIME_CG_TOLERANCE, ie.tolerance());
            } else if (c.name().equals(IntegratorCatalog.LARGE_STEP_ACCURATE)) {
                PrefactoredBdf2 b = (PrefactoredBdf2) c.create();
                assertEquals("bdf2", b.name());
                assertEquals(2, b.newtonIterations());
                assertEquals(8, b.krylovIterations());
            } else {
                assertEquals(c.name(), c.create().name());
            }
            assertNotSame(c.create(), c.create(), "a new instance for every body");
        }
    }

    @Test
    void choosingAnotherIntegratorChangesTheRun() {
        ViewScene a = CubeViewScene.create();
        ViewScene b = CubeViewScene.create();
        Tuning t = new Tuning(b.name(), b.parameters(), b.defaultTimeStep(), false, IntegratorCatalog.available());
        t.bind(new ParameterBindingTest.DirectTarget(b));
        t.setIntegrator("rk4");
        for (Body body : b.bodies()) {
            assertEquals("rk4", body.simulation().integrator().name());
        }
        double[] x = ParameterBindingTest.run(a, a.defaultTimeStep(), 200);
        double[] y = ParameterBindingTest.run(b, b.defaultTimeStep(), 200);
        assertNotEquals(Arrays.toString(x), Arrays.toString(y));
    }
}
