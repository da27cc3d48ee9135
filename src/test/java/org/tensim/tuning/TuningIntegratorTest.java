package org.tensim.tuning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.integrators.Integrators;

/** The integrator chosen in a tuning session is the one every body runs. */
class TuningIntegratorTest {
    @Test
    void choosingAnotherIntegratorChangesTheRun() {
        ViewScene a = CubeViewScene.create();
        ViewScene b = CubeViewScene.create();
        Tuning t = new Tuning(b.name(), b.parameters(), b.defaultTimeStep(), false, Integrators.choices());
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
