package org.tensim.solver.stability;

/**
 * A time step and how it was chosen.
 *
 * @param seconds the step, s (finite, > 0)
 * @param reason  how it was chosen, for reports and logs (e.g. {@code "given (--dt)"})
 */
public record TimeStep(double seconds, String reason) {
    /** @throws IllegalArgumentException naming the value when it is not finite and > 0 */
    public TimeStep {
        if (!(seconds > 0) || !Double.isFinite(seconds)) {
            throw new IllegalArgumentException("time step must be a finite number > 0 s, got " + seconds + " ("
                    + reason + ")");
        }
    }
}
