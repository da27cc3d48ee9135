package org.tensim.scene.conditions;

import org.tensim.scene.diaphragm.BreathingCycle;

/**
 * The breathing cycle of the diaphragm ({@link BreathingCycle}) as a time law: {@code amplitude * s(t)}, with s
 * the breathing level (0 at end-expiration, 1 at end-inspiration; period T, inspiration a share {@code 1/(1+r)} of
 * it). Named in a scene's {@code laws:} as {@code {type: breathing, period: 4 s, inspiration: 0.333, pause: 0.25, amplitude: 1}}
 * and used by any condition or motion; the ribs' helical-axis law takes its cycle and amplitude.
 */
public final class BreathingLaw implements TimeLaw {
    private final BreathingCycle cycle;
    private final double amplitude;

    /**
     * Without an end-expiratory pause.
     *
     * @param periodS          breathing period T, s (&gt; 0)
     * @param inspirationShare Ti / T, in (0, 1) (1/3 for I:E = 1:2)
     * @param amplitude        the factor at end-inspiration (dimensionless)
     */
    public BreathingLaw(double periodS, double inspirationShare, double amplitude) {
        this(periodS, inspirationShare, 0, amplitude);
    }

    /**
     * @param periodS          breathing period T, s (&gt; 0)
     * @param inspirationShare Ti / T, in (0, 1) (1/3 for I:E = 1:2)
     * @param pauseShare       the end-expiratory pause, a share of the expiration in [0, 1) ({@link BreathingCycle})
     * @param amplitude        the factor at end-inspiration (dimensionless)
     */
    public BreathingLaw(double periodS, double inspirationShare, double pauseShare, double amplitude) {
        if (!(inspirationShare > 0 && inspirationShare < 1)) {
            throw new IllegalArgumentException("the inspiration's share of the cycle must lie in (0, 1), got "
                    + inspirationShare);
        }
        if (!Double.isFinite(amplitude)) {
            throw new IllegalArgumentException("the amplitude must be a finite number, got " + amplitude);
        }
        // I:E = 1:r with Ti = T / (1 + r): r = (1 - share) / share.
        this.cycle = new BreathingCycle(periodS, (1 - inspirationShare) / inspirationShare, pauseShare);
        this.amplitude = amplitude;
    }

    /** The cycle. */
    public BreathingCycle cycle() {
        return cycle;
    }

    /** The factor at end-inspiration. */
    public double amplitude() {
        return amplitude;
    }

    @Override
    public double value(double tSeconds) {
        return amplitude * cycle.level(tSeconds);
    }
}
