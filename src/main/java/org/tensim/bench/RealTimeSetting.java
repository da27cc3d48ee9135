package org.tensim.bench;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The configuration of {@code ./tensim diaphragm --realtime}: the fastest one that the real-time study
 * ({@link RealTimeStudy}) measured within its tolerance ({@link RealTimeStudy#TOLERANCE} relative RMS
 * displacement error against RK2 at the same mesh, at end-inspiration and at the worst moment, and the
 * apex's descent within {@link RealTimeStudy#APEX_TOLERANCE_MM} of RK2's) on the default mesh, with the
 * errors and the speed that study measured (docs/diaphragm.md, "Real time with BDF2").
 *
 * @param integrator        registry name of the integrator
 * @param dtS               time step, s (0: the scene's stable RK2 step)
 * @param newtonIterations  Newton iterations per step (BDF2 only)
 * @param krylovIterations  CG iterations per Newton iteration (BDF2 only)
 * @param threads           threads the study ran it on
 * @param endError          measured relative RMS error at end-inspiration
 * @param worstError        measured largest relative RMS error over the run (against the motion's amplitude)
 * @param apexDifferenceMm  measured difference of the apex's descent from RK2's at end-inspiration, mm
 * @param realtimeFactor    measured real-time factor (wall, sync included) in the study's run
 * @param measured          when, where and under which load the study measured it
 */
public record RealTimeSetting(String integrator, double dtS, int newtonIterations, int krylovIterations, int threads,
        double endError,
        double worstError, double apexDifferenceMm, double realtimeFactor, String measured) {
    /**
     * The default mesh's setting, from the study of {@link #measured()}: after the rigid links entered BDF2's
     * step, one large-step configuration stayed within the tolerance (BDF2 at 5 ms with 6 Newton x 8 CG
     * iterations: 0.8 % at end-inspiration, 3.2 % at its worst moment, apex within 0.01 mm), at about twice
     * RK2's speed per CPU second (0.027 against 0.013) but not faster by the wall clock in that run (0.006
     * against 0.008, under a load of 13-19); so the fastest one within it by the study's rule (wall clock) is
     * still the reference itself, RK2 at the scene's stable step on two threads.
     */
    public static final RealTimeSetting DEFAULT_MESH = new RealTimeSetting("rk2", 0, 1, 1, 2, 0, 0, 0, 0.008,
            "2026-11-23 14:39-14:57 UTC, load average 13-19 on 2 cores; 0.013 of real time per CPU second");

    /** A new integrator of this setting. */
    public Integrator newIntegrator() {
        Integrator in = Integrators.create(integrator);
        if (in instanceof PrefactoredBdf2 b) {
            b.setNewtonIterations(newtonIterations).setKrylovIterations(krylovIterations);
        }
        return in;
    }

    /** One sentence naming the solver, the step and the measured error bound. */
    public String describe() {
        String what = dtS == 0 ? integrator + " at the scene's stable step"
                : String.format(Locale.ROOT, "%s at %.0f ms (%d Newton x %d CG iterations a step)", integrator, 1e3 * dtS,
                        newtonIterations, krylovIterations);
        return String.format(Locale.ROOT, "%s, %d threads: the fastest configuration the real-time study measured"
                + " within %.0f %% of RK2 at the default mesh (relative RMS error %.1f %% at end-inspiration, %.1f %% at"
                + " the worst moment, apex within %.2f mm; %.4f of real time, wall, in that study: %s)", what, threads,
                100 * RealTimeStudy.TOLERANCE, 100 * endError, 100 * worstError, apexDifferenceMm, realtimeFactor,
                measured);
    }

    /** The setting as summary entries. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("integrator", integrator);
        m.put("dt_s", dtS);
        m.put("newton_iterations_per_step", newtonIterations);
        m.put("cg_iterations_per_newton_iteration", krylovIterations);
        m.put("measured_error_end_inspiration", endError);
        m.put("measured_error_worst_moment", worstError);
        m.put("measured_apex_difference_mm", apexDifferenceMm);
        m.put("measured_realtime_factor", realtimeFactor);
        m.put("measured", measured);
        return m;
    }
}
