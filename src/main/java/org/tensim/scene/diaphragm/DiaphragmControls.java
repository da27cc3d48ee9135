package org.tensim.scene.diaphragm;

import org.tensim.model.Check;

/**
 * The two independent control parameters of the diaphragm (the paper's claim:
 * "at least two independent parameters"), read by the rib motions and the muscle
 * action at every force pass, so that they can be changed while a simulation runs
 * (from a GUI thread: the fields are volatile; a change takes effect at the next
 * force evaluation).
 */
public final class DiaphragmControls {
    /** Largest accepted rib amplitude factor: 3 times the physiological quiet-breathing rotation. */
    public static final double MAX_RIB_AMPLITUDE = 3;
    /**
     * Largest accepted muscle action amplitude, Pa: covers both readings of the amplitude, a pressure (a forced
     * inspiration reaches about 10 kPa) and an active fibre stress (19 kPa at quiet breathing on the default
     * mesh, 30 kPa in the thorax with the lungs' recoil to carry, about twice that for a deep breath; the human
     * diaphragm's maximal active stress is of the order of 200 kPa).
     */
    public static final double MAX_MUSCLE_PA = 60_000;

    private volatile double ribAmplitude;
    private volatile double musclePa;

    /**
     * @param ribAmplitude factor on the physiological rib rotations (1 = quiet breathing, 0 = ribs still)
     * @param musclePa     peak muscle action, Pa: active fibre stress or force per unit area of the diaphragm,
     *                     as the scene's muscle load reads it
     */
    public DiaphragmControls(double ribAmplitude, double musclePa) {
        setRibAmplitude(ribAmplitude);
        setMuscleAmplitudePa(musclePa);
    }

    /** Factor on the physiological rib rotation angles and translations (dimensionless, 0..3). */
    public double ribAmplitude() {
        return ribAmplitude;
    }

    /** Sets the rib amplitude factor; refuses values outside [0, 3]. */
    public void setRibAmplitude(double factor) {
        Check.nonNegative("rib amplitude", "(factor on the physiological rib rotation)", factor);
        if (factor > MAX_RIB_AMPLITUDE) {
            throw new IllegalArgumentException("rib amplitude must be at most " + MAX_RIB_AMPLITUDE
                    + " (times the physiological rotation), got " + factor);
        }
        ribAmplitude = factor;
    }

    /** Peak muscle action at end-inspiration, Pa (an active fibre stress or a pressure, as the muscle load reads it). */
    public double muscleAmplitudePa() {
        return musclePa;
    }

    /** Sets the peak muscle action, Pa; refuses values outside [0, 30 kPa]. */
    public void setMuscleAmplitudePa(double pa) {
        Check.nonNegative("muscle action amplitude", "Pa", pa);
        if (pa > MAX_MUSCLE_PA) {
            throw new IllegalArgumentException("muscle action amplitude must be at most " + MAX_MUSCLE_PA
                    + " Pa (an active fibre stress or a pressure), got " + pa);
        }
        musclePa = pa;
    }
}
