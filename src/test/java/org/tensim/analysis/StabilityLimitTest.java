package org.tensim.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.stability.LinearStability;
import org.tensim.solver.stability.StabilityTheory;

/**
 * The largest stable step measured by bisection through the whole simulation,
 * against linear stability theory (docs/physics.md): 2 / w for symplectic Euler and
 * velocity Verlet, 2 sqrt(2) / w for RK4, on springs whose k/m spans six decades.
 */
class StabilityLimitTest {
    private static final int PERIODS = 50;
    private static final double TOL = 1e-3;

    /** The registered method's own linear stability description. */
    private static LinearStability theory(String integrator) {
        return Integrators.create(integrator).stability();
    }

    @ParameterizedTest(name = "{0} at w = {1} rad/s: w h_crit = {2}")
    @CsvSource({"symplectic-euler, 10, 2", "symplectic-euler, 1000, 2", "verlet, 1, 2", "verlet, 10, 2",
        "rk4, 10, 2.8284271", "rk4, 1000, 2.8284271"})
    void undampedLimitWithinFivePercent(String integrator, double omega, double theory) {
        assertEquals(theory, theory(integrator).undampedLimit(), 1e-6, "theory table");
        double measured = StabilityStudy.criticalOmegaH(integrator, omega, 0, PERIODS, TOL);
        assertEquals(theory, measured, 0.05 * theory, integrator + ": measured critical w h at w = " + omega
                + " rad/s");
    }

    @ParameterizedTest(name = "{0} with damping ratio {1}")
    @CsvSource({"euler, 0.5", "symplectic-euler, 0.2", "rk2, 0.2", "heun, 0.5", "verlet, 0.5", "rk4, 0.5"})
    void dampedLimitWithinFivePercentOfTheory(String integrator, double zeta) {
        double theory = StabilityTheory.criticalOmegaH(theory(integrator), zeta);
        double measured = StabilityStudy.criticalOmegaH(integrator, 10, zeta, PERIODS, TOL);
        assertTrue(theory > 0 && Double.isFinite(theory), "theory " + theory);
        assertEquals(theory, measured, 0.05 * theory, integrator + " at zeta = " + zeta);
    }

    @Test
    void implicitEulerIsStableAtEveryStepTried() {
        assertEquals(Double.POSITIVE_INFINITY, StabilityStudy.criticalOmegaH("implicit-euler", 10, 0, PERIODS, TOL));
        assertEquals(Double.POSITIVE_INFINITY, theory("implicit-euler").undampedLimit());
    }

    @Test
    void undampedEulerAndRk2AreNeverStableInTheory() {
        for (String m : new String[] {"euler", "rk2", "heun"}) {
            assertEquals(0, theory(m).undampedLimit(), m);
            assertTrue(!StabilityTheory.stable(theory(m), 1e-2, 0), m + " must grow on an undamped spring even at w h = 0.01");
        }
    }

    @Test
    void theoryOfSymplecticEulerMatchesItsClosedFormAtTheLimit() {
        // Trace of the undamped step matrix is 2 - (w h)^2: |trace| <= 2 iff w h <= 2.
        assertTrue(StabilityTheory.stable(theory("symplectic-euler"), 1.999, 0));
        assertTrue(!StabilityTheory.stable(theory("symplectic-euler"), 2.001, 0));
        assertTrue(StabilityTheory.stable(theory("rk4"), 2.8284, 0));
        assertTrue(!StabilityTheory.stable(theory("rk4"), 2.8285, 0));
    }
}
