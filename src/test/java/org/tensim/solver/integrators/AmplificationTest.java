package org.tensim.solver.integrators;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.tensim.scene.SpringScene;
import org.tensim.solver.Severity;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * Per-step amplitude of undamped springs against the amplification factors of
 * theory. On x'' = -w^2 x the amplitude A = sqrt(x^2 + (v / w)^2) is |q + i p| of
 * the complex form q' = -i w q, so a Runge-Kutta method multiplies it by exactly
 * |R(-i w h)| per step.
 */
class AmplificationTest {
    private static final double STRETCH_M = 1e-4; // small, far inside the linear range

    /** Runs n steps; returns {first amplitude, last amplitude} and checks monotonicity as asked. */
    private static double[] amplitudes(String integrator, double omega, double h, int n, int monotone) {
        return amplitudes(integrator, omega, h, n, monotone, STRETCH_M);
    }

    private static double[] amplitudes(String integrator, double omega, double h, int n, int monotone,
            double stretch) {
        SystemState s = SystemState.compile(SpringScene.build(omega, 0, stretch));
        Simulation sim = new Simulation(s, Integrators.create(integrator));
        sim.apply(sim.settings().withStepLimitSeverity(Severity.IGNORE).withEnergyCheck(Double.POSITIVE_INFINITY,
                sim.settings().energyCheckInterval()));
        double a0 = amplitude(s, omega);
        double prev = a0;
        for (int i = 0; i < n; i++) {
            sim.step(h);
            double a = amplitude(s, omega);
            if (monotone > 0) {
                assertTrue(a > prev, integrator + " at w h = " + omega * h + ": amplitude must grow at step " + (i + 1)
                        + ", went from " + prev + " to " + a);
            } else if (monotone < 0) {
                assertTrue(a < prev, integrator + " at w h = " + omega * h + ": amplitude must decay at step "
                        + (i + 1) + ", went from " + prev + " to " + a);
            }
            prev = a;
        }
        return new double[] {a0, prev};
    }

    /** Steps (at most 200) that keep the total growth under 1000 times: the spring stays linear. */
    private static int steps(double logGrowthPerStep) {
        return (int) Math.max(5, Math.min(200, Math.log(1000) / logGrowthPerStep));
    }

    private static double amplitude(SystemState s, double omega) {
        double x = s.x[3] - SpringScene.REST_LENGTH_M;
        double v = s.v[3] / omega;
        return Math.sqrt(x * x + v * v);
    }

    @ParameterizedTest(name = "{0} at w h = {1}")
    @CsvSource({"rk2, 0.1", "rk2, 0.2", "rk2, 0.5", "rk2, 1.0", "heun, 0.2", "heun, 1.0"})
    void rk2GrowsAsTheoryPredicts(String integrator, double omegaH) {
        double omega = 10;
        double theory = 0.5 * Math.log(1 + Math.pow(omegaH, 4) / 4); // ln |R(i w h)|
        int n = steps(theory);
        double[] a = amplitudes(integrator, omega, omegaH / omega, n, +1);
        double measured = Math.log(a[1] / a[0]) / n;
        assertEquals(theory, measured, 0.01 * theory, integrator + ": log growth per step at w h = " + omegaH
                + " (theory (1 + (w h)^4/4)^(1/2) = " + Math.exp(theory) + ", measured " + Math.exp(measured) + ")");
    }

    @ParameterizedTest(name = "forward Euler grows at w = {0} rad/s, h = {1} s")
    @CsvSource({"1, 0.001", "10, 0.0001", "10, 0.01", "10, 0.2", "1000, 0.001", "0.1, 0.5"})
    void forwardEulerGrowsOnEveryUndampedSpring(double omega, double h) {
        double theory = Math.sqrt(1 + omega * h * omega * h);
        int n = steps(Math.log(theory));
        double[] a = amplitudes("euler", omega, h, n, +1);
        double perStep = Math.pow(a[1] / a[0], 1.0 / n);
        assertEquals(theory, perStep, 1e-9 * theory, "forward Euler's growth per step |1 + i w h|");
    }

    @ParameterizedTest(name = "implicit Euler decays at w h = {0}")
    @CsvSource({"0.01", "0.5", "2", "10", "1000"})
    void implicitEulerDecays(double omegaH) {
        double omega = 10;
        double theory = 1 / Math.sqrt(1 + omegaH * omegaH); // |1 / (1 - i w h)|
        // Decays at most 1e6 times in all: below that, the position's round-off (about 1e-16 m) would show.
        int n = (int) Math.max(1, Math.min(50, Math.log(1e6) / -Math.log(theory)));
        double[] a = amplitudes("implicit-euler", omega, omegaH / omega, n, -1, 0.1);
        double perStep = Math.pow(a[1] / a[0], 1.0 / n);
        assertEquals(theory, perStep, 1e-6 * theory, "implicit Euler's decay per step over " + n + " steps");
    }

    /**
     * Below their limit w h = 2 the symplectic methods neither grow nor decay: they keep a quadratic invariant
     * of the map exactly, so the point (x, v / w) runs round a fixed ellipse and the amplitude A = |(x, v / w)|
     * stays between that ellipse's semi-axes. With a = w h and a start at rest (A0 = the stretch):
     * symplectic Euler (v += -w^2 x h, then x += v h) keeps x^2 + p^2 - a x p, p = v / w, so
     * A / A0 lies in [1 / sqrt(1 + a / 2), 1 / sqrt(1 - a / 2)] (0.716 .. 4.472 at a = 1.9); velocity Verlet
     * keeps (1 - a^2 / 4) x^2 + p^2, so A / A0 lies in [sqrt(1 - a^2 / 4), 1] (0.312 .. 1). Each step turns
     * the point by acos(1 - a^2 / 2) (2.51 and 1.42 rad, not a fraction of a turn), so over 2000 steps both
     * extremes are reached to 1e-6; the band 1e-4 leaves margin for that sampling, and a drift of 1e-4 over
     * the run (5e-8 per step) falls outside it, where the old bound allowed growth by 20 times.
     */
    @ParameterizedTest(name = "{0} keeps an undamped spring on its ellipse at w h = {1}")
    @CsvSource({"symplectic-euler, 1.9, 0.7161148740394329, 4.472135954999580",
            "symplectic-euler, 1.3, 0.778498944161523, 1.690308509457033",
            "verlet, 1.9, 0.3122498999199199, 1.0", "verlet, 1.3, 0.7599342076785331, 1.0"})
    void boundedBelowTheLimit(String integrator, double omegaH, double minRatio, double maxRatio) {
        double omega = 10;
        SystemState s = SystemState.compile(SpringScene.build(omega, 0, STRETCH_M));
        Simulation sim = new Simulation(s, Integrators.create(integrator));
        sim.apply(sim.settings().withStepLimitSeverity(Severity.IGNORE).withEnergyCheck(Double.POSITIVE_INFINITY,
                sim.settings().energyCheckInterval()));
        double a0 = amplitude(s, omega);
        double lo = 1;
        double hi = 1;
        for (int i = 0; i < 2000; i++) {
            sim.step(omegaH / omega);
            lo = Math.min(lo, amplitude(s, omega) / a0);
            hi = Math.max(hi, amplitude(s, omega) / a0);
        }
        String what = integrator + " at w h = " + omegaH + ": A / A0 in [" + lo + ", " + hi + "]";
        assertEquals(minRatio, lo, 1e-4 * minRatio, what);
        assertEquals(maxRatio, hi, 1e-4 * maxRatio, what);
    }

    /** RK4 below its limit 2.83 decays by exactly |R(i w h)| per step, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24. */
    @ParameterizedTest(name = "rk4 decays at w h = {0}")
    @CsvSource({"1.0", "2.0", "2.8"})
    void rk4DecaysAsTheoryPredicts(double omegaH) {
        double y = omegaH;
        double theory = Math.hypot(1 - y * y / 2 + Math.pow(y, 4) / 24, y - Math.pow(y, 3) / 6);
        // A decay of at most 1e6 from a 0.1 m stretch (the spring is linear along its axis at any stretch):
        // from 1e-4 m the end amplitude, 1e-10 m, would show the position's round-off (2e-8 per step).
        int n = (int) Math.max(5, Math.min(200, Math.log(1e6) / -Math.log(theory)));
        double[] a = amplitudes("rk4", 10, omegaH / 10, n, -1, 0.1);
        double perStep = Math.pow(a[1] / a[0], 1.0 / n);
        assertEquals(theory, perStep, 1e-9, "rk4's decay per step over " + n + " steps");
    }
}
