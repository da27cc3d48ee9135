package org.tensim.solver.integrators;

import java.util.function.Supplier;
import org.tensim.solver.Integrator;

/**
 * One named setup of an integrator: a method with its settings (for example {@code bdf2-newton2}, BDF2 with
 * 2 Newton iterations of up to 8 CG iterations a step), a label for menus, and a factory. The setups are
 * declared in one place, {@link Integrators}; command lines, the GUI, presets, sweep and calibration specs
 * name them by {@link #name()}. Each call of {@link #create()} makes a new integrator (integrators keep
 * scratch arrays sized for one state), so every body gets its own.
 */
public final class IntegratorChoice {
    private final String name;
    private final String label;
    private final Supplier<Integrator> factory;

    IntegratorChoice(String name, String label, Supplier<Integrator> factory) {
        this.name = name;
        this.label = label;
        this.factory = factory;
    }

    /**
     * The setup's name, as on command lines and in presets. For a method with its default settings it is the
     * method's {@link Integrator#name()}; a variant's name differs from the method's (the integrator it makes
     * still reports the method's name).
     */
    public String name() {
        return name;
    }

    /** A label for menus: the name, the order and what the setup is for. */
    public String label() {
        return label;
    }

    /** A new integrator of this setup. */
    public Integrator create() {
        return factory.get();
    }

    @Override
    public String toString() {
        return label;
    }
}
