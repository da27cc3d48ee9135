package org.tensim.app.gui;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;

/**
 * The integrators offered in the GUI: every one in the project's registry
 * ({@link Integrators}), the paper's RK2 midpoint first as the default. The
 * control panel, presets and the runner take whatever this list holds.
 */
public final class IntegratorCatalog {
    /** The default: the paper's integrator. */
    public static final String DEFAULT = "rk2";

    private IntegratorCatalog() {
    }

    /** All choices, the default first, then the registry's order. */
    public static List<IntegratorChoice> available() {
        List<IntegratorChoice> l = new ArrayList<>();
        for (Map.Entry<String, Supplier<Integrator>> e : Integrators.all().entrySet()) {
            Integrator probe = e.getValue().get();
            String label = e.getKey() + ", order " + probe.order() + (e.getKey().equals(DEFAULT) ? " (paper)" : "");
            IntegratorChoice c = new IntegratorChoice(e.getKey(), label, e.getValue());
            if (e.getKey().equals(DEFAULT)) {
                l.add(0, c);
            } else {
                l.add(c);
            }
        }
        return List.copyOf(l);
    }
}
