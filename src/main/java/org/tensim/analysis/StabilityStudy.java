package org.tensim.analysis;

import org.tensim.model.Check;
import org.tensim.model.Topology;
import org.tensim.scene.SpringScene;
import org.tensim.solver.Severity;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * Measures the largest stable time step of an integrator by bisection, running
 * the whole {@link Simulation} (with its divergence checks' energy limit off, so
 * that the method itself is measured).
 *
 * <p>Stable means bounded and finite over a fixed number of periods: the run
 * covers {@code periods} periods of the oscillation (2 pi / w each, at least
 * {@link #MIN_STEPS} steps), every position stays finite, no displacement from
 * the initial positions exceeds {@link #ESCAPE_FACTOR} times the initial amplitude,
 * and the largest displacement over the last quarter of the steps is at most
 * {@link #GROWTH_FACTOR} times the largest over the first quarter. A method
 * bounded but not contractive (symplectic Euler, Verlet below their limit) keeps
 * the ratio near 1; one beyond its limit grows geometrically and exceeds it within
 * a few periods. The escape bound matters: the scene must stay in its linear
 * range (a spring's mass that overshoots its anchor moves in a bounded, chaotic
 * double well and would otherwise look stable), so the initial amplitude is tiny
 * ({@link #SPRING_STRETCH_M} on a 1 m spring). Methods that grow slowly at every step (forward Euler, undamped
 * RK2) get a measured limit that shrinks as the number of periods grows: the
 * bisection finds where their growth over that many periods reaches the factor.
 */
public final class StabilityStudy {
    /** Largest allowed growth of the displacement from the first to the last quarter of the run. */
    public static final double GROWTH_FACTOR = 2;
    /** A displacement this many times the initial amplitude counts as unstable (and ends the trial). */
    public static final double ESCAPE_FACTOR = 1e4;
    /** Initial stretch of the test spring, m (rest length 1 m): small, so that the escape bound stays linear. */
    public static final double SPRING_STRETCH_M = 1e-6;
    /** Fewest steps of a run. */
    public static final int MIN_STEPS = 40;
    /** Lower end of the w h bracket: below it a method is reported as never stable (0). */
    public static final double OMEGA_H_MIN = 1e-3;
    /** Upper end of the w h bracket: stable there means reported as always stable (infinite). */
    public static final double OMEGA_H_MAX = 100;

    private StabilityStudy() {
    }

    /**
     * Measured critical w h (dimensionless) of an integrator on one spring of
     * natural frequency omega (rad/s) and damping ratio zeta.
     *
     * @param periods   periods of the oscillation per trial run (>= 1)
     * @param relativeTolerance bisection stops when the bracket's ratio is below 1 + this
     */
    public static double criticalOmegaH(String integrator, double omega, double zeta, int periods,
            double relativeTolerance) {
        Check.atLeast("stability periods", periods, 1);
        Check.positive("bisection tolerance", "", relativeTolerance);
        Topology t = SpringScene.build(omega, zeta, SPRING_STRETCH_M);
        return criticalOmegaH(t, integrator, omega, 2 * Math.PI / omega * periods, SPRING_STRETCH_M,
                relativeTolerance);
    }

    /**
     * Measured critical w h on any scene: bisection (geometric) on h in
     * [{@link #OMEGA_H_MIN}, {@link #OMEGA_H_MAX}] / omega, each trial a run of
     * {@code durationS}.
     *
     * @param omega the frequency that scales the steps (the scene's highest), rad/s
     * @param amplitudeM the initial displacement amplitude of the scene, m (see {@link #ESCAPE_FACTOR})
     * @return the critical w h: 0 when unstable at the lower end, infinite when stable at the upper end
     */
    public static double criticalOmegaH(Topology t, String integrator, double omega, double durationS,
            double amplitudeM, double relativeTolerance) {
        return criticalOmegaH(t, integrator, omega, durationS, amplitudeM, relativeTolerance, OMEGA_H_MIN,
                OMEGA_H_MAX);
    }

    /**
     * As above, with the w h bracket given: trials at small w h take many steps, so a
     * caller that knows roughly where the limit lies saves most of the time.
     *
     * @param omegaHMin lower end of the bracket (0 is returned when unstable there)
     * @param omegaHMax upper end of the bracket (infinity is returned when stable there)
     */
    public static double criticalOmegaH(Topology t, String integrator, double omega, double durationS,
            double amplitudeM, double relativeTolerance, double omegaHMin, double omegaHMax) {
        Check.positive("lower end of the w h bracket", "", omegaHMin);
        if (!(omegaHMax > omegaHMin)) {
            throw new IllegalArgumentException("upper end of the w h bracket must exceed the lower end " + omegaHMin
                    + ", got " + omegaHMax);
        }
        double lo = omegaHMin;
        double hi = omegaHMax;
        if (!stable(t, integrator, lo / omega, durationS, amplitudeM)) {
            return 0;
        }
        if (stable(t, integrator, hi / omega, durationS, amplitudeM)) {
            return Double.POSITIVE_INFINITY;
        }
        while (hi / lo > 1 + relativeTolerance) {
            double mid = Math.sqrt(lo * hi);
            if (stable(t, integrator, mid / omega, durationS, amplitudeM)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return Math.sqrt(lo * hi);
    }

    /**
     * Whether a run of the scene with step h (s) over durationS (s) stays bounded and finite.
     *
     * @param amplitudeM initial displacement amplitude, m
     */
    public static boolean stable(Topology t, String integrator, double h, double durationS, double amplitudeM) {
        SystemState s = SystemState.compile(t);
        Simulation sim = new Simulation(s, Integrators.create(integrator));
        sim.apply(sim.settings().withStepLimitSeverity(Severity.IGNORE)
                .withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval())
                .withProjectionFailureSeverity(Severity.IGNORE));
        long steps = Math.max(MIN_STEPS, (long) Math.ceil(durationS / h));
        long quarter = steps / 4;
        double first = 0;
        double last = 0;
        try {
            for (long i = 0; i < steps; i++) {
                sim.step(h);
                double d = largestDisplacement(s);
                if (i < quarter) {
                    first = Math.max(first, d);
                } else if (i >= steps - quarter) {
                    last = Math.max(last, d);
                }
                if (d > ESCAPE_FACTOR * amplitudeM) {
                    return false;
                }
            }
        } catch (SimulationDivergedException e) {
            return false;
        }
        return last <= GROWTH_FACTOR * first;
    }

    private static double largestDisplacement(SystemState s) {
        double worst = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            double dx = s.x[3 * i] - s.x0[3 * i];
            double dy = s.x[3 * i + 1] - s.x0[3 * i + 1];
            double dz = s.x[3 * i + 2] - s.x0[3 * i + 2];
            double d = dx * dx + dy * dy + dz * dz;
            if (!(d <= worst)) {
                worst = d;
            }
        }
        return Math.sqrt(worst);
    }
}
