package org.tensim.scene.diaphragm;

import org.tensim.model.Check;

/**
 * A quiet breathing cycle: period T and inspiration:expiration ratio 1:r. The
 * breathing level {@code s(t)} goes from 0 (end of expiration, the rest shape) to
 * 1 (end of inspiration) and back, smoothly (continuous velocity):
 * <pre>
 *   Ti = T / (1 + r),  Te = T - Ti,  tau = t mod T
 *   s = (1 - cos(pi tau / Ti)) / 2              for tau in [0, Ti]   (inspiration)
 *   s = (1 + cos(pi (tau - Ti) / Te)) / 2       for tau in [Ti, T]   (expiration)
 * </pre>
 * Quiet breathing: 12-15 breaths per minute (T = 4-5 s), I:E about 1:2.
 */
public final class BreathingCycle {
    private final double periodS;
    private final double expirationRatio;
    private final double inspirationS;

    /**
     * @param periodS         breathing period, s (> 0; default 4 s = 15 breaths/min)
     * @param expirationRatio r in I:E = 1:r (> 0; default 2)
     */
    public BreathingCycle(double periodS, double expirationRatio) {
        this.periodS = Check.positive("breathing period", "s", periodS);
        this.expirationRatio = Check.positive("expiration ratio r in I:E = 1:r", "", expirationRatio);
        this.inspirationS = periodS / (1 + expirationRatio);
    }

    /** 15 breaths per minute, I:E = 1:2. */
    public static BreathingCycle quiet() {
        return new BreathingCycle(4, 2);
    }

    public double periodS() {
        return periodS;
    }

    public double expirationRatio() {
        return expirationRatio;
    }

    /** Duration of inspiration Ti, s. */
    public double inspirationS() {
        return inspirationS;
    }

    /** The breathing level s(t) in [0, 1]: 0 at end-expiration, 1 at end-inspiration. Allocation-free. */
    public double level(double tSeconds) {
        double tau = tSeconds - periodS * Math.floor(tSeconds / periodS);
        if (tau <= inspirationS) {
            return 0.5 * (1 - Math.cos(Math.PI * tau / inspirationS));
        }
        return 0.5 * (1 + Math.cos(Math.PI * (tau - inspirationS) / (periodS - inspirationS)));
    }
}
