package org.tensim.scene.tunable;

import org.tensim.model.ForceLaw;
import org.tensim.model.Vec3;

/**
 * The sinusoidal force of {@link ForceLaw#sinusoid} with an amplitude and a
 * frequency that can change while the simulation runs:
 * {@code F(t) = A sin(2 pi f t + phi) d}. A change of frequency at time t keeps
 * the phase continuous (phi is adjusted), so the force does not jump. Set only on
 * the simulation thread, between steps.
 */
public final class TunableSinusoid implements ForceLaw {
    private final double dx;
    private final double dy;
    private final double dz;
    private double amplitude;
    private double omega;
    private double phase;

    /**
     * @param amplitudeN  peak force, N
     * @param frequencyHz frequency, Hz
     * @param direction   direction of the force (normalised here)
     */
    public TunableSinusoid(double amplitudeN, double frequencyHz, Vec3 direction) {
        Vec3 d = direction.normalized();
        dx = d.x();
        dy = d.y();
        dz = d.z();
        setAmplitude(amplitudeN);
        omega = 2 * Math.PI * frequencyHz;
    }

    /** Peak force, N (>= 0). */
    public void setAmplitude(double n) {
        if (!(n >= 0) || !Double.isFinite(n)) {
            throw new IllegalArgumentException("force amplitude must be a finite number >= 0 N, got " + n);
        }
        amplitude = n;
    }

    /** New frequency (Hz, >= 0) from time tSeconds on, with the phase continuous at that time. */
    public void setFrequency(double hz, double tSeconds) {
        if (!(hz >= 0) || !Double.isFinite(hz)) {
            throw new IllegalArgumentException("force frequency must be a finite number >= 0 Hz, got " + hz);
        }
        double w = 2 * Math.PI * hz;
        phase += (omega - w) * tSeconds;
        omega = w;
    }

    public double amplitude() {
        return amplitude;
    }

    @Override
    public void addTo(double t, double[] f, int o) {
        double s = amplitude * Math.sin(omega * t + phase);
        f[o] += dx * s;
        f[o + 1] += dy * s;
        f[o + 2] += dz * s;
    }
}
