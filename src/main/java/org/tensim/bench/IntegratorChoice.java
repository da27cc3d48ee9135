package org.tensim.bench;

import java.util.List;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;

/** The integrators the benchmark can run, by command-line name. */
final class IntegratorChoice {
    private IntegratorChoice() {
    }

    /** Names accepted by {@link #create(String)}. */
    static List<String> names() {
        return List.of("rk2");
    }

    /** A new integrator by name; an exception lists the names known. */
    static Integrator create(String name) {
        if ("rk2".equals(name)) {
            return new MidpointRK2();
        }
        throw new IllegalArgumentException("--integrator " + name + ": unknown; expected one of " + names());
    }
}
