package org.tensim.app;

import org.tensim.cli.IntegratorOption;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.TimeStepOption;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/**
 * The diaphragm's integrator and step, shared by {@code tensim diaphragm} and its resolution study (a picocli
 * mixin): {@code --integrator}, {@code --dt} and the iterative solvers' settings.
 */
public final class DiaphragmSolverOptions {
    @Mixin
    IntegratorOption integrator = new IntegratorOption();

    @Mixin
    TimeStepOption dt = TimeStepOption.chosenByScene("the step the time-step policy recommends for the integrator"
            + " on this scene; summary.json's dt_rule says how it was chosen");

    @Option(names = "--cg-tolerance", paramLabel = "R",
            description = "implicit-euler only: relative residual at which each step's CG solve stops"
                    + " (default: 1e-12).")
    Double cgTolerance;

    @Option(names = "--newton", paramLabel = "N",
            description = "bdf2 only: Newton iterations per step (default: "
                    + PrefactoredBdf2.DEFAULT_NEWTON_ITERATIONS + "; with --thorax: "
                    + PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS + ", docs/thorax.md).")
    Integer newton;

    @Option(names = "--cg-iterations", paramLabel = "N",
            description = "bdf2 only: cap on CG iterations per Newton iteration (default: "
                    + PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS + "; with --thorax: "
                    + PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS + ").")
    Integer cgIterations;

    /**
     * The step the organs' runs take by default, s: bdf2 at 2.5 ms is the integrator and step of every run with the
     * lungs and the liver in docs/lungs.md (three cycles on the full mesh, breaths the same to 0.19 %). RK2 at the
     * thorax's recommended step (about 1.3e-5 s) needs some 200 times the steps: about 3 hours a breath on the full
     * mesh on two cores.
     */
    public static final double ORGANS_DT_S = 0.0025;

    private double checkedDt;

    /**
     * With the organs: {@code bdf2} at {@link #ORGANS_DT_S} when neither {@code --integrator} nor {@code --dt} was
     * given. Returns what it chose, for the summary, or null when the user's choice stands.
     */
    String defaultForOrgans(CommandSpec spec) {
        if (integrator.given(spec) || dt.given(spec)) {
            return null;
        }
        integrator.defaultTo(spec, PrefactoredBdf2.NAME);
        dt.defaultTo(spec, ORGANS_DT_S);
        return "with --lungs and neither --integrator nor --dt: " + PrefactoredBdf2.NAME + " at " + ORGANS_DT_S
                + " s, the organs' runs' step (docs/lungs.md)";
    }

    /**
     * Checks the options against the scene (each setting applies to its own integrator; the step is at most one
     * breathing period and fits {@code seconds}) and returns the integrator they configure.
     */
    void check(CommandSpec spec, DiaphragmSpec scene, double seconds) {
        Integrator chosen = integrator.create(spec);
        if (cgTolerance != null && !(chosen instanceof ImplicitEuler)) {
            throw new ParameterException(spec.commandLine(), "--cg-tolerance applies to --integrator implicit-euler"
                    + " only, not " + integrator.name());
        }
        if ((newton != null || cgIterations != null) && !(chosen instanceof PrefactoredBdf2)) {
            throw new ParameterException(spec.commandLine(), "--newton and --cg-iterations apply to --integrator"
                    + " bdf2 only, not " + integrator.name());
        }
        try {
            configured(chosen, scene);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        double period = scene.breathing().periodS();
        double dt = this.dt.seconds(spec);
        checkedDt = dt;
        if (dt > period) {
            throw new ParameterException(spec.commandLine(), "--dt must be > 0 s (or 0 for the recommended step) and"
                    + " at most one breathing period (--period " + period + " s), got " + dt + " s");
        }
        if (dt != 0) {
            OptionChecks.stepFits(spec, "--dt", dt, "--seconds", seconds);
        }
    }

    /** A new integrator as the options configure it, for a scene of this spec. */
    Integrator create(DiaphragmSpec scene) {
        return configured(Integrators.create(integrator.name()), scene);
    }

    /** The step asked for, s, 0 for the recommended one (known after {@link #check}). */
    double dt() {
        return checkedDt;
    }

    /** The integrator's name as given. */
    String integratorName() {
        return integrator.name();
    }

    /**
     * Gives a plain {@code bdf2} ({@code name}) in a thorax with contact that thorax's converged iterations
     * ({@link PrefactoredBdf2#CONTACT_NEWTON_ITERATIONS}; a named setup keeps its own), as every diaphragm run does.
     */
    static Integrator contactDefaults(Integrator i, String name, DiaphragmSpec s) {
        if (i instanceof PrefactoredBdf2 b && s.cage().boneSurfaces() && s.cage().contact()
                && name.equals(PrefactoredBdf2.NAME)) {
            b.setNewtonIterations(PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS);
            b.setKrylovIterations(PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS);
        }
        return i;
    }

    /**
     * The integrator as the options configure it (the run's, and every model's of a study): a thorax's converged
     * {@code bdf2} step for plain {@code bdf2} (a named setup keeps its own iterations; docs/thorax.md), then
     * {@code --newton}, {@code --cg-iterations} and {@code --cg-tolerance}.
     */
    private Integrator configured(Integrator i, DiaphragmSpec s) {
        contactDefaults(i, integrator.name(), s);
        if (i instanceof PrefactoredBdf2 b) {
            if (newton != null) {
                b.setNewtonIterations(newton);
            }
            if (cgIterations != null) {
                b.setKrylovIterations(cgIterations);
            }
        }
        if (cgTolerance != null && i instanceof ImplicitEuler ie) {
            ie.setTolerance(cgTolerance);
        }
        return i;
    }
}
