package org.tensim.solver.integrators;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.tensim.analysis.AccuracyScenes;
import org.tensim.analysis.AccuracyStudy;

/**
 * Measured global orders within +/- 0.15 of theory, on one spring with an exact
 * solution (w = 10 rad/s, released from a 0.1 m stretch, 2 s, dt from 0.02 s
 * halved 7 times), undamped and with damping ratio 0.1 (which exercises the
 * velocity-dependent forces of every method, e.g. Verlet's predicted velocity).
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class IntegratorOrderTest {
    private Map<String, Double> undamped;
    private Map<String, Double> damped;

    @BeforeAll
    void measure() {
        List<String> all = Integrators.names();
        undamped = AccuracyStudy.run(AccuracyScenes.get("spring"), all, line -> { }).measuredOrder();
        damped = AccuracyStudy.run(AccuracyScenes.get("damped-spring"), all, line -> { }).measuredOrder();
    }

    @ParameterizedTest(name = "{0}: order {1}")
    @CsvSource({"euler, 1", "symplectic-euler, 1", "rk2, 2", "heun, 2", "verlet, 2", "rk4, 4", "implicit-euler, 1", "bdf2, 2"})
    void undampedSpringOrder(String name, int expected) {
        assertEquals(expected, Integrators.create(name).order(), "declared order of " + name);
        assertEquals(expected, undamped.get(name), 0.15, "measured order of " + name + " on the undamped spring");
    }

    @ParameterizedTest(name = "{0}: order {1}")
    @CsvSource({"euler, 1", "symplectic-euler, 1", "rk2, 2", "heun, 2", "verlet, 2", "rk4, 4", "implicit-euler, 1", "bdf2, 2"})
    void dampedSpringOrder(String name, int expected) {
        assertEquals(expected, damped.get(name), 0.15, "measured order of " + name + " on the damped spring");
    }
}
