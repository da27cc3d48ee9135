package org.tensim.app.gui;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The integrators offered in the GUI: every one in the project's registry
 * ({@link Integrators}), the paper's RK2 midpoint first as the default. The
 * control panel, presets and the runner take whatever this list holds.
 */
public final class IntegratorCatalog {
    /** The default: the paper's integrator. */
    public static final String DEFAULT = Integrators.DEFAULT;
    /**
     * Implicit Euler with its CG stopped at a relative residual of 1e-3: the setting of the real-time
     * study (docs/diaphragm.md), with which a 14-ring diaphragm at a 10 ms step runs 2.9 times real
     * time headless within 6.4 % of RK2; the registry's implicit Euler solves to 1e-12, for accuracy
     * studies.
     */
    public static final String REAL_TIME_IMPLICIT = "implicit-euler-cg1e-3";
    /** CG tolerance of {@link #REAL_TIME_IMPLICIT}. */
    public static final double REAL_TIME_CG_TOLERANCE = 1e-3;
    /**
     * The choice for tuning at about real time: the large-step solver ({@link PrefactoredBdf2}: BDF2,
     * Newton-CG preconditioned by a prefactored sparse Cholesky, refactored in the background after a
     * change). The diaphragm opens with it at {@link #REAL_TIME_STEP_S} (docs/gui.md).
     */
    public static final String REAL_TIME = PrefactoredBdf2.NAME;
    /**
     * {@link #REAL_TIME} with 2 Newton iterations of up to 8 CG iterations a step: with the muscle pressure
     * one Newton iteration is not enough from 10 ms on the default mesh (20.6 % from RK2 at end-inspiration),
     * two end within 2 % of it at 10 and 20 ms; with the fibres (the default load) 0.3 % at end-inspiration
     * and 1.9 % at the worst moment at 20 ms, against 3.7 % and 4.5 % with one (docs/diaphragm.md, real-time
     * study); about three times the cost of a step.
     */
    public static final String LARGE_STEP_ACCURATE = "bdf2-newton2";
    /** Newton iterations per step of {@link #LARGE_STEP_ACCURATE}. */
    public static final int LARGE_STEP_ACCURATE_NEWTON = 2;
    /** CG iterations per Newton iteration of {@link #LARGE_STEP_ACCURATE}. */
    public static final int LARGE_STEP_ACCURATE_KRYLOV = 8;
    /**
     * Time step of {@link #REAL_TIME}, s: 25 ms, the step of {@code diaphragm --realtime}, which the real-time
     * study measured within 5 % of RK2 on the default mesh with the fibres (docs/diaphragm.md).
     */
    public static final double REAL_TIME_STEP_S = 0.025;

    private IntegratorCatalog() {
    }

    /** All choices, the default first, then the registry's order. */
    public static List<IntegratorChoice> available() {
        List<IntegratorChoice> l = new ArrayList<>();
        for (Map.Entry<String, Supplier<Integrator>> e : Integrators.all().entrySet()) {
            Integrator probe = e.getValue().get();
            String label = e.getKey() + ", order " + probe.order() + (e.getKey().equals(DEFAULT) ? " (paper)"
                    : e.getKey().equals(REAL_TIME) ? " (large steps, real time)" : "");
            IntegratorChoice c = new IntegratorChoice(e.getKey(), label, e.getValue());
            if (e.getKey().equals(DEFAULT)) {
                l.add(0, c);
            } else {
                l.add(c);
            }
        }
        l.add(new IntegratorChoice(REAL_TIME_IMPLICIT, "implicit-euler, CG to 1e-3 (real time on coarse models)",
                () -> new ImplicitEuler().setTolerance(REAL_TIME_CG_TOLERANCE)));
        l.add(new IntegratorChoice(LARGE_STEP_ACCURATE, "bdf2, 2 Newton x 8 CG (large steps, within 2 % of RK2)",
                () -> new PrefactoredBdf2().setNewtonIterations(LARGE_STEP_ACCURATE_NEWTON)
                        .setKrylovIterations(LARGE_STEP_ACCURATE_KRYLOV)));
        return List.copyOf(l);
    }
}
