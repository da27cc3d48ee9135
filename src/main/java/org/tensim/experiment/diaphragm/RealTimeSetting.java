package org.tensim.experiment.diaphragm;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * What {@code ./tensim diaphragm --realtime} runs, by muscle load: a setup of the integrator catalogue
 * ({@link Integrators}) and its time step. The real-time study ({@link RealTimeStudy},
 * {@code diaphragm realtime-study}) chose each as the fastest configuration it measured within
 * {@link RealTimeStudy#TOLERANCE} relative RMS displacement error against RK2 at the same mesh (at
 * end-inspiration and at the worst moment) and with the apex's descent within
 * {@link RealTimeStudy#APEX_TOLERANCE_MM} of RK2's, on the default mesh. The figures themselves are that
 * study's output (realtime.json, docs/diaphragm.md), not constants here: a run's summary carries its own
 * provenance. With the geodesic tendon at 19 kPa the fibres' setting at 4 CG iterations, as first chosen, measured
 * 2.7 % at end-inspiration but 5.2 % at the worst moment; with 5, {@code bdf2}'s default cap since, 2.0 / 4.8 %
 * (docs/diaphragm.md, "Real time").
 *
 * @param integrator name of a setup in {@link Integrators}
 * @param dtS        time step, s (0: the scene's stable step for that integrator)
 */
public record RealTimeSetting(String integrator, double dtS) {
    /**
     * With the muscle's active fibre tension ({@code --muscle-load fibres}, the default load): the catalogue's
     * real-time setup, {@link Integrators#REAL_TIME} at {@link Integrators#REAL_TIME_STEP_S}.
     */
    public static final RealTimeSetting FIBRES = new RealTimeSetting(Integrators.REAL_TIME,
            Integrators.REAL_TIME_STEP_S);

    /**
     * With a pressure load ({@code --muscle-load pressure} or {@code paper-nodes}): no large-step configuration
     * stayed within the tolerance at the worst moment of the inspiration, where the compressed muscle moves
     * fast, so the fastest configuration within it is the reference itself, RK2 at the scene's stable step.
     */
    public static final RealTimeSetting PRESSURE = new RealTimeSetting(Integrators.DEFAULT, 0);

    /**
     * In a thorax (bone surfaces; contact on or off) with the fibres' load: {@link Integrators#CONTACT_REAL_TIME}
     * at {@link Integrators#REAL_TIME_STEP_S}, chosen by the thorax's real-time study
     * ({@link ThoraxRealTimeStudy}: within {@link RealTimeStudy#TOLERANCE} of the converged contact step at 5 ms on
     * the BodyParts3D diaphragm in the shared thorax; docs/thorax.md, "Real time in the thorax").
     */
    public static final RealTimeSetting THORAX = new RealTimeSetting(Integrators.CONTACT_REAL_TIME,
            Integrators.REAL_TIME_STEP_S);

    /** The setting must name a setup of the catalogue and a step of 0 or more. */
    public RealTimeSetting {
        Integrators.choice(integrator);
        if (!(dtS >= 0) || !Double.isFinite(dtS)) {
            throw new IllegalArgumentException("dtS must be a finite step >= 0 s (0: the stable step), got " + dtS);
        }
    }

    /** The setting for a muscle-load model: {@link #FIBRES} for the fibres, {@link #PRESSURE} for the others. */
    public static RealTimeSetting forMuscleLoad(BoundaryConditions.MuscleLoad model) {
        return model == BoundaryConditions.MuscleLoad.FIBRES ? FIBRES : PRESSURE;
    }

    /**
     * The setting for a scene: {@link #THORAX} in a thorax (with or without contact: the diaphragm is held at its
     * origins only either way) with the fibres' load, else {@link #forMuscleLoad}.
     *
     * @throws IllegalArgumentException in a thorax with another load (no setting was measured there)
     */
    public static RealTimeSetting forScene(BoundaryConditions.MuscleLoad model, boolean thorax) {
        if (!thorax) {
            return forMuscleLoad(model);
        }
        if (model != BoundaryConditions.MuscleLoad.FIBRES) {
            throw new IllegalArgumentException("no real-time setting was measured in a thorax with the "
                    + BoundaryConditions.name(model) + " load; use --muscle-load fibres");
        }
        return THORAX;
    }

    /** A new integrator of this setting. */
    public Integrator newIntegrator() {
        return Integrators.create(integrator);
    }

    /** One sentence naming the solver, the step and how it was chosen. */
    public String describe() {
        Integrator in = newIntegrator();
        String what = dtS == 0 ? integrator + " at the scene's stable step"
                : in instanceof PrefactoredBdf2 b
                        ? String.format(Locale.ROOT, "%s at %.0f ms (%d Newton x %d CG iterations a step)", integrator,
                                1e3 * dtS, b.newtonIterations(), b.krylovIterations())
                        : String.format(Locale.ROOT, "%s at %.0f ms", integrator, 1e3 * dtS);
        if (this.equals(THORAX)) {
            return String.format(Locale.ROOT, "%s, links tied in the preconditioner: the thorax's real-time study's"
                    + " (diaphragm realtime-study --thorax) setting, chosen within %.0f %% of the converged contact"
                    + " step at 5 ms (its measured error: docs/thorax.md)", what, 100 * RealTimeStudy.TOLERANCE);
        }
        return String.format(Locale.ROOT, "%s: the real-time study's (diaphragm realtime-study) setting for the"
                + " default mesh, chosen within %.0f %% of RK2 (its measured error: docs/performance.md)", what,
                100 * RealTimeStudy.TOLERANCE);
    }

    /** The setting as summary entries: the setup, the step and the solver's iterations where it has them. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("integrator", integrator);
        m.put("dt_s", dtS);
        if (newIntegrator() instanceof PrefactoredBdf2 b) {
            m.put("newton_iterations_per_step", b.newtonIterations());
            m.put("cg_iterations_per_newton_iteration", b.krylovIterations());
            m.put("link_coupling", b.linkCoupling());
        }
        if (this.equals(THORAX)) {
            m.put("tolerance_against_converged_contact_step", RealTimeStudy.TOLERANCE);
        } else {
            m.put("tolerance_against_rk2", RealTimeStudy.TOLERANCE);
        }
        return m;
    }
}
