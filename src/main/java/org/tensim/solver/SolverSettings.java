package org.tensim.solver;

import java.util.Objects;
import org.tensim.model.Check;

/**
 * The solver's settings in one place (after Box2D's {@code b2WorldDef}): what a
 * {@link Simulation} reports or refuses, how its divergence check, rigid-link
 * projection and implicit solves stop, and on how many threads it runs. Immutable;
 * validated here, where the values enter; change one with a {@code with...} method
 * and hand the result to {@link Simulation#apply(SolverSettings)}.
 *
 * @param stepLimitSeverity         what a step beyond the critical step estimate of an explicit
 *                                  integrator does (default {@link Severity#WARN})
 * @param projectionFailureSeverity what a rigid-link projection that stops above its tolerance does
 *                                  (default {@link Severity#WARN})
 * @param energyGrowthLimit         kinetic + spring energy growth factor (> 1) between two energy checks
 *                                  beyond which the run is stopped as diverged; infinite turns the
 *                                  energy check off, the finiteness check stays (default 100)
 * @param energyCheckInterval       steps between energy checks, >= 1 (default 100)
 * @param projectionTolerance       largest relative rigid-link length error |l - L| / L the projection
 *                                  accepts, dimensionless, > 0 (default 1e-9)
 * @param projectionMaxIterations   cap on Gauss-Seidel sweeps of the projection per step, >= 1 (default 200)
 * @param cgTolerance               relative residual at which an implicit integrator's conjugate-gradient
 *                                  solve stops, > 0 (default 1e-12; 1e-3 is the real-time setting of
 *                                  docs/diaphragm.md)
 * @param cgMaxIterations           cap on CG iterations per step, >= 1 (default 500)
 * @param threads                   threads that share each step, the caller included, >= 1 (default 1; used
 *                                  by {@code parallel.Parallelism.install(Simulation)})
 */
public record SolverSettings(Severity stepLimitSeverity, Severity projectionFailureSeverity, double energyGrowthLimit,
        int energyCheckInterval, double projectionTolerance, int projectionMaxIterations, double cgTolerance,
        int cgMaxIterations, int threads) {
    /** The defaults listed above. */
    public static final SolverSettings DEFAULTS = new SolverSettings(Severity.WARN, Severity.WARN, 100, 100, 1e-9, 200,
            1e-12, 500, 1);

    /** @throws IllegalArgumentException naming the setting, its value and what is expected */
    public SolverSettings {
        Objects.requireNonNull(stepLimitSeverity, "step limit severity");
        Objects.requireNonNull(projectionFailureSeverity, "projection failure severity");
        if (!(energyGrowthLimit > 1)) {
            throw new IllegalArgumentException("energy growth limit must be a factor > 1 (or Infinity to turn the"
                    + " check off), got " + energyGrowthLimit);
        }
        Check.atLeast("energy check interval (steps)", energyCheckInterval, 1);
        Check.positive("rigid link tolerance", "(relative length error)", projectionTolerance);
        Check.atLeast("rigid link iteration cap", projectionMaxIterations, 1);
        Check.positive("CG tolerance", "(relative residual)", cgTolerance);
        Check.atLeast("CG iteration cap", cgMaxIterations, 1);
        Check.atLeast("thread count", threads, 1);
    }

    public SolverSettings withStepLimitSeverity(Severity s) {
        return new SolverSettings(s, projectionFailureSeverity, energyGrowthLimit, energyCheckInterval,
                projectionTolerance, projectionMaxIterations, cgTolerance, cgMaxIterations, threads);
    }

    public SolverSettings withProjectionFailureSeverity(Severity s) {
        return new SolverSettings(stepLimitSeverity, s, energyGrowthLimit, energyCheckInterval,
                projectionTolerance, projectionMaxIterations, cgTolerance, cgMaxIterations, threads);
    }

    /** Energy growth factor and check interval (steps) of the divergence check. */
    public SolverSettings withEnergyCheck(double growthLimit, int intervalSteps) {
        return new SolverSettings(stepLimitSeverity, projectionFailureSeverity, growthLimit, intervalSteps,
                projectionTolerance, projectionMaxIterations, cgTolerance, cgMaxIterations, threads);
    }

    /** Relative length tolerance and sweep cap of the rigid-link projection. */
    public SolverSettings withProjection(double tolerance, int maxIterations) {
        return new SolverSettings(stepLimitSeverity, projectionFailureSeverity, energyGrowthLimit,
                energyCheckInterval, tolerance, maxIterations, cgTolerance, cgMaxIterations, threads);
    }

    /** Relative residual and iteration cap of an implicit integrator's CG. */
    public SolverSettings withCg(double tolerance, int maxIterations) {
        return new SolverSettings(stepLimitSeverity, projectionFailureSeverity, energyGrowthLimit,
                energyCheckInterval, projectionTolerance, projectionMaxIterations, tolerance, maxIterations, threads);
    }

    public SolverSettings withThreads(int n) {
        return new SolverSettings(stepLimitSeverity, projectionFailureSeverity, energyGrowthLimit,
                energyCheckInterval, projectionTolerance, projectionMaxIterations, cgTolerance, cgMaxIterations, n);
    }
}
