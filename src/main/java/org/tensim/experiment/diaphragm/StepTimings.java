package org.tensim.experiment.diaphragm;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.tensim.solver.Simulation;
import org.tensim.solver.Stage;
import org.tensim.solver.prefactored.Bdf2Part;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * Where a run's steps spent their wall time, for the summary: the mean per step of each stage of
 * the simulation's {@link org.tensim.solver.StepProfile} (ms), and, for {@code bdf2}, of each part of
 * its Newton-Krylov solve ({@link Bdf2Part}, ms; inside the INTEGRATE stage). Means over the whole
 * run, the first step's factorisation included.
 */
final class StepTimings {
    private StepTimings() {
    }

    /** {@code {"integrate": ms, ..., "bdf2": {"links": ms, ...}}}, rounded to microseconds. */
    static Map<String, Object> of(Simulation sim) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (Stage s : Stage.values()) {
            m.put(s.name().toLowerCase(Locale.ROOT), DiaphragmReport.round(sim.profile().meanMillis(s), 3));
        }
        if (sim.integrator() instanceof PrefactoredBdf2 b) {
            Map<String, Object> parts = new LinkedHashMap<>();
            for (Bdf2Part p : Bdf2Part.values()) {
                parts.put(p.name().toLowerCase(Locale.ROOT), DiaphragmReport.round(b.partMillisPerStep(p), 3));
            }
            m.put("bdf2", parts);
        }
        return m;
    }
}
