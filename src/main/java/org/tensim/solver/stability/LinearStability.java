package org.tensim.solver.stability;

/**
 * How an integrator behaves on the linear test oscillator {@code x'' = -w^2 x - 2 zeta w x'}
 * (one spring, natural frequency w = sqrt(k/m) rad/s, damping ratio zeta): the
 * description that {@link StabilityTheory} and {@link TimeStepPolicy} need, given once
 * by each integrator (explicit Runge-Kutta methods derive it from their Butcher
 * tableau, the others write their step's formula on two scalars).
 */
public interface LinearStability {
    /**
     * One step of the method on {@code x'' = -x - 2 zeta x'} (w = 1, so the step h is
     * the dimensionless w h) from (x, v); returns {x1, v1}. Linear in (x, v): its
     * columns at (1, 0) and (0, 1) are the amplification matrix.
     */
    double[] oscillatorStep(double h, double zeta, double x, double v);

    /**
     * The largest w h (dimensionless) for which an undamped spring stays bounded: 0
     * when the method grows at every step size, {@link Double#POSITIVE_INFINITY} when it
     * is unconditionally stable.
     */
    double undampedLimit();

    /**
     * The growth factor per step (spectral radius of the amplification matrix) of a
     * mode of frequency w (rad/s) and damping ratio zeta at the step h (s); at most 1
     * (+ round-off) where the method is stable.
     */
    default double modeAmplification(double h, double w, double zeta) {
        return StabilityTheory.spectralRadius(StabilityTheory.amplification(this, h * w, zeta));
    }

    /** A step formula on the test oscillator (see {@link #oscillatorStep}). */
    @FunctionalInterface
    interface StepFormula {
        double[] step(double h, double zeta, double x, double v);
    }

    /**
     * A method that is not a Runge-Kutta tableau, described by its step formula and
     * its undamped limit (derived by hand in its javadoc and checked against the
     * formula's amplification matrix by the tests).
     */
    static LinearStability declared(double undampedLimit, StepFormula formula) {
        return new LinearStability() {
            @Override
            public double[] oscillatorStep(double h, double zeta, double x, double v) {
                return formula.step(h, zeta, x, v);
            }

            @Override
            public double undampedLimit() {
                return undampedLimit;
            }
        };
    }
}
