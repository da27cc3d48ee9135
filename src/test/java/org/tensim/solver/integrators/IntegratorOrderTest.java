package org.tensim.solver.integrators;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.analysis.AccuracyScenes;
import org.tensim.analysis.AccuracyStudy;

/**
 * Measured global orders within +/- 0.15 of the declared order, for every
 * integrator of the registry (a new one is measured at once), on one spring with an
 * exact solution (w = 10 rad/s, released from a 0.1 m stretch, 2 s, dt from 0.02 s
 * halved 7 times), undamped and with damping ratio 0.1 (which exercises the
 * velocity-dependent forces of every method, e.g. Verlet's predicted velocity). The
 * declared orders of the methods of the literature are checked against their
 * textbook values too.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class IntegratorOrderTest {
    /** Textbook orders of the methods known when this test was written. */
    private static final Map<String, Integer> TEXTBOOK = Map.of("euler", 1, "symplectic-euler", 1, "rk2", 2,
            "heun", 2, "verlet", 2, "rk4", 4, "implicit-euler", 1, "bdf2", 2);

    private Map<String, Double> undamped;
    private Map<String, Double> damped;

    static List<String> names() {
        return Integrators.names();
    }

    @BeforeAll
    void measure() {
        List<String> all = Integrators.names();
        undamped = AccuracyStudy.run(AccuracyScenes.get("spring"), all, line -> { }).measuredOrder();
        damped = AccuracyStudy.run(AccuracyScenes.get("damped-spring"), all, line -> { }).measuredOrder();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("names")
    void undampedSpringOrder(String name) {
        int declared = Integrators.create(name).order();
        if (TEXTBOOK.containsKey(name)) {
            assertEquals(TEXTBOOK.get(name), declared, "declared order of " + name);
        }
        assertEquals(declared, undamped.get(name), 0.15, "measured order of " + name + " on the undamped spring");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("names")
    void dampedSpringOrder(String name) {
        int declared = Integrators.create(name).order();
        assertEquals(declared, damped.get(name), 0.15, "measured order of " + name + " on the damped spring");
    }

    @org.junit.jupiter.api.Test
    void everyTextbookMethodIsRegistered() {
        assertEquals(true, Integrators.names().containsAll(TEXTBOOK.keySet()), "registry " + Integrators.names());
    }
}
