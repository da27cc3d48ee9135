package org.tensim.bench;

import java.util.List;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;

/** The integrators the benchmark can run, by command-line name (the project's registry). */
final class IntegratorChoice {
    private IntegratorChoice() {
    }

    /** Names accepted by {@link #create(String)}. */
    static List<String> names() {
        return Integrators.names();
    }

    /** A new integrator by name; an exception lists the names known. */
    static Integrator create(String name) {
        try {
            return Integrators.create(name);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--integrator " + name + ": " + e.getMessage(), e);
        }
    }
}
