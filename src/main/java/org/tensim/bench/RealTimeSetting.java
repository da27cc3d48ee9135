package org.tensim.bench;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.tensim.solver.Integrator;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The configuration of {@code ./tensim diaphragm --realtime}: the fastest one that the real-time study
 * ({@link RealTimeStudy}) measured within its tolerance ({@link RealTimeStudy#TOLERANCE} relative RMS
 * displacement error against RK2 at the same mesh, at end-inspiration and at the worst moment, and the
 * apex's descent within {@link RealTimeStudy#APEX_TOLERANCE_MM} of RK2's) on the default mesh, with the
 * errors and the speed that study measured (docs/diaphragm.md, "Real time with BDF2").
 *
 * @param integrator        registry name of the integrator
 * @param dtS               time step, s
 * @param krylovIterations  CG iterations per step
 * @param threads           threads the study ran it on
 * @param endError          measured relative RMS error at end-inspiration
 * @param worstError        measured largest relative RMS error over the run (against the motion's amplitude)
 * @param apexDifferenceMm  measured difference of the apex's descent from RK2's at end-inspiration, mm
 * @param realtimeFactor    measured real-time factor (wall, sync included) in the study's run
 * @param measured          when, where and under which load the study measured it
 */
public record RealTimeSetting(String integrator, double dtS, int krylovIterations, int threads, double endError,
        double worstError, double apexDifferenceMm, double realtimeFactor, String measured) {
    /** The default mesh's setting, from the study of {@link #measured()}. */
    public static final RealTimeSetting DEFAULT_MESH = new RealTimeSetting(PrefactoredBdf2.NAME, 0.01,
            PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS, 2, Double.NaN, Double.NaN, Double.NaN, Double.NaN,
            "not yet measured");

    /** A new integrator of this setting. */
    public Integrator newIntegrator() {
        return new PrefactoredBdf2().setKrylovIterations(krylovIterations);
    }

    /** One sentence naming the solver, the step and the measured error bound. */
    public String describe() {
        return String.format(Locale.ROOT, "%s at %.0f ms (%d CG iterations a step, %d threads): the fastest "
                + "configuration the real-time study measured within %.0f %% of RK2 at the default mesh: relative RMS "
                + "error %.1f %% at end-inspiration, %.1f %% at the worst moment, apex within %.2f mm; %.2f of real "
                + "time in that study (%s)", integrator, 1e3 * dtS, krylovIterations, threads,
                100 * RealTimeStudy.TOLERANCE, 100 * endError, 100 * worstError, apexDifferenceMm, realtimeFactor,
                measured);
    }

    /** The setting as summary entries. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("integrator", integrator);
        m.put("dt_s", dtS);
        m.put("cg_iterations_per_step", krylovIterations);
        m.put("measured_error_end_inspiration", endError);
        m.put("measured_error_worst_moment", worstError);
        m.put("measured_apex_difference_mm", apexDifferenceMm);
        m.put("measured_realtime_factor", realtimeFactor);
        m.put("measured", measured);
        return m;
    }
}
