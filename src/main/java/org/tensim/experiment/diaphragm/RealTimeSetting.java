package org.tensim.experiment.diaphragm;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.tensim.scene.diaphragm.BoundaryConditions;
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
     * The default mesh's setting with the pressure load ({@code --muscle-load pressure} or {@code paper-nodes}),
     * from the study of {@link #measured()} (membrane triangles, damped transverse
     * shear elements, the shear's sliding modes in BDF2's prefactored matrix): every large-step configuration
     * measured ends the inspiration close to RK2 (BDF2 at 5 ms: 2.0 %; at 5 ms with 2 Newton x 8 CG: 0.06 %; at
     * 10 or 20 ms with 2 Newton x 8 CG: 1.7-2.0 %), but none stays within the tolerance at the worst moment:
     * 7.9-14 % at 1.05 s, where the compressed muscle moves fast and RK2 at its step resolves it (RK2 at its step
     * is within 0.5 % of RK2 at half of it there, a throw-away probe of the same afternoon). So the fastest
     * configuration within the tolerance is still the reference itself, RK2 at the scene's stable step on two
     * threads.
     */
    public static final RealTimeSetting DEFAULT_MESH = new RealTimeSetting("rk2", 0, 1, 1, 2, 0, 0, 0, 0.005,
            "2026-11-23 18:00-18:15 UTC, load average 10-12 on 2 cores; 0.014 of real time per CPU second");

    /**
     * The default mesh's setting with the muscle's active fibre tension ({@code --muscle-load fibres}, the default
     * load, with its insertion and the force-length relation), from the study of {@link #measured()}: BDF2 at 25 ms
     * with its default iterations is within the tolerance (2.7 % at end-inspiration, 4.9 % at the worst moment,
     * 1.1 s; apex 0.01 mm from RK2's) at 1.45 of real time by the wall clock, scene-graph sync included; at 20 ms
     * 2.5 % / 4.4 % at 1.09, at 5 ms 0.2 % / 0.5 % at 0.28; at 33 ms 4.6 % / 5.3 %, outside (docs/diaphragm.md,
     * "Real time with the fibres").
     */
    public static final RealTimeSetting DEFAULT_MESH_FIBRES = new RealTimeSetting("bdf2", 0.025,
            PrefactoredBdf2.DEFAULT_NEWTON_ITERATIONS, PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS, 2, 0.0268, 0.0487,
            0.01, 1.45, "2026-11-24 00:23-00:24 UTC, load average 0.9-1.5 on 2 cores; 1.27 of real time per CPU"
                    + " second");

    /**
     * The setting measured for a muscle-load model as on the command line: the fibres' for {@code fibres} or null
     * (the default load, {@link BoundaryConditions#defaults()}), the pressure's for the others.
     */
    public static RealTimeSetting forMuscleLoad(String model) {
        String m = model == null ? BoundaryConditions.DEFAULT_MUSCLE_LOAD : model;
        return m.equals(BoundaryConditions.name(BoundaryConditions.MuscleLoad.FIBRES)) ? DEFAULT_MESH_FIBRES
                : DEFAULT_MESH;
    }

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
