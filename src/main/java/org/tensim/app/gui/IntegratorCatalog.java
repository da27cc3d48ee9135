package org.tensim.app.gui;

import java.util.List;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;

/**
 * The integrators offered in the GUI, the paper's first. This is the one place
 * to extend when more {@link Integrator} implementations exist: the control
 * panel, presets and the runner take whatever this list holds.
 */
public final class IntegratorCatalog {
    private IntegratorCatalog() {
    }

    /** All choices, the default (the paper's RK2 midpoint) first. */
    public static List<IntegratorChoice> available() {
        return List.of(new IntegratorChoice(new MidpointRK2().name(), "RK2 midpoint (paper)", MidpointRK2::new));
    }
}
