package org.tensim.app.gui;

import java.util.function.Supplier;
import org.tensim.solver.Integrator;

/**
 * An integrator the user can pick: its short name (as {@link Integrator#name()},
 * used in presets), a label, and a factory. Each body gets its own instance
 * (integrators keep scratch arrays).
 */
public record IntegratorChoice(String name, String label, Supplier<Integrator> factory) {
    public Integrator create() {
        return factory.get();
    }

    @Override
    public String toString() {
        return label;
    }
}
