package org.tensim.scene.diaphragm;

import org.tensim.model.Check;

/**
 * A quiet breathing cycle: period T, inspiration:expiration ratio 1:r, and an end-expiratory pause, a share p of
 * the expiration spent at rest. The breathing level {@code s(t)} goes from 0 (end of expiration, the rest shape) to
 * 1 (end of inspiration) and back, smoothly (continuous velocity):
 * <pre>
 *   Ti = T / (1 + r),  Te = T - Ti,  Tx = (1 - p) Te,  tau = t mod T
 *   s = (1 - cos(pi tau / Ti)) / 2              for tau in [0, Ti]          (inspiration)
 *   s = (1 + cos(pi (tau - Ti) / Tx)) / 2       for tau in [Ti, Ti + Tx]    (expiration)
 *   s = 0                                       for tau in [Ti + Tx, T]     (the end-expiratory pause)
 * </pre>
 * Quiet breathing: 12-15 breaths per minute (T = 4-5 s), I:E about 1:2.
 *
 * <p><b>Why a pause.</b> In quiet breathing the expiration is passive: the flow is largest early and has stopped well
 * before the next inspiration, so the organs dwell at end-exhale. Lujan et al. (Med Phys 26:715-720, 1999) model
 * organ motion over a breath as {@code cos^(2n)}, flat at exhale, for this reason, and Seppenwoolde et al. (Int J
 * Radiat Oncol Biol Phys 53:822-834, 2002) measured lung tumours spending longer near exhale than inhale. The
 * default share {@link #QUIET_PAUSE_SHARE} comes from the five DIR-Lab 4D-CT cases' time course (docs/lungs.md,
 * "The time course and the breathing law"): their landmarks' shares of the end-inhale displacement at 10-40 % of
 * the cycle after end-inhale (mean 0.82, 0.47, 0.25, 0.10) are those of an expiration over half the cycle, 2 s of
 * the 2.67 s expiration at 4 s and I:E 1:2 (a raised cosine over 2 s gives 0.90, 0.65, 0.35, 0.10), and not those
 * of a raised cosine over the whole 2.67 s (0.95, 0.79, 0.58, 0.35).
 */
public final class BreathingCycle {
    /** The quiet law's end-expiratory pause, a share of the expiration: 0.25 (0.67 s of 2.67 s at 4 s, I:E 1:2). */
    public static final double QUIET_PAUSE_SHARE = 0.25;

    private final double periodS;
    private final double expirationRatio;
    private final double pauseShare;
    private final double inspirationS;
    private final double exhalingS;

    /** Without an end-expiratory pause: the expiration's raised cosine takes all of Te. */
    public BreathingCycle(double periodS, double expirationRatio) {
        this(periodS, expirationRatio, 0);
    }

    /**
     * @param periodS         breathing period, s (&gt; 0; default 4 s = 15 breaths/min)
     * @param expirationRatio r in I:E = 1:r (&gt; 0; default 2)
     * @param pauseShare      p, the share of the expiration spent at rest at its end, in [0, 1) (default
     *                        {@link #QUIET_PAUSE_SHARE}; 0: the expiration's cosine takes all of it)
     */
    public BreathingCycle(double periodS, double expirationRatio, double pauseShare) {
        this.periodS = Check.positive("breathing period", "s", periodS);
        this.expirationRatio = Check.positive("expiration ratio r in I:E = 1:r", "", expirationRatio);
        if (!(pauseShare >= 0 && pauseShare < 1)) {
            throw new IllegalArgumentException("end-expiratory pause must be a share of the expiration in [0, 1), got "
                    + pauseShare);
        }
        this.pauseShare = pauseShare;
        this.inspirationS = periodS / (1 + expirationRatio);
        this.exhalingS = (1 - pauseShare) * (periodS - inspirationS);
    }

    /** 15 breaths per minute, I:E = 1:2, the end-expiratory pause {@link #QUIET_PAUSE_SHARE}. */
    public static BreathingCycle quiet() {
        return new BreathingCycle(4, 2, QUIET_PAUSE_SHARE);
    }

    public double periodS() {
        return periodS;
    }

    public double expirationRatio() {
        return expirationRatio;
    }

    /** The end-expiratory pause, a share of the expiration in [0, 1). */
    public double pauseShare() {
        return pauseShare;
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
        double e = tau - inspirationS;
        return e >= exhalingS ? 0 : 0.5 * (1 + Math.cos(Math.PI * e / exhalingS));
    }

    @Override
    public String toString() {
        return "BreathingCycle[period " + periodS + " s, I:E 1:" + expirationRatio + ", pause " + pauseShare + "]";
    }
}
