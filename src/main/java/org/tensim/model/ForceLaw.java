package org.tensim.model;

/**
 * A time-dependent external force on one node, in newtons. Factories give the
 * paper's sinusoid and a constant; any function of time can be given as a lambda.
 * Implementations must not allocate: they are evaluated at every force pass.
 */
@FunctionalInterface
public interface ForceLaw {
    /**
     * Adds the force at time {@code tSeconds} to {@code f[offset..offset+2]} (N).
     */
    void addTo(double tSeconds, double[] f, int offset);

    /**
     * {@code F(t) = amplitude * sin(2 pi frequency t + phase) * d}, with d the unit
     * vector along {@code direction}.
     *
     * @param amplitudeN  peak force, N (>= 0)
     * @param frequencyHz frequency, Hz (>= 0)
     * @param phaseRad    phase at t = 0, rad
     * @param direction   direction of the force (normalised here; not zero)
     */
    static ForceLaw sinusoid(double amplitudeN, double frequencyHz, double phaseRad, Vec3 direction) {
        Check.nonNegative("sinusoidal force amplitude", "N", amplitudeN);
        Check.nonNegative("sinusoidal force frequency", "Hz", frequencyHz);
        Check.finite("sinusoidal force phase", "rad", phaseRad);
        Vec3 d = direction.normalized();
        double w = 2 * Math.PI * frequencyHz;
        double dx = d.x() * amplitudeN;
        double dy = d.y() * amplitudeN;
        double dz = d.z() * amplitudeN;
        return (t, f, o) -> {
            double s = Math.sin(w * t + phaseRad);
            f[o] += dx * s;
            f[o + 1] += dy * s;
            f[o + 2] += dz * s;
        };
    }

    /** A constant force, N. */
    static ForceLaw constant(Vec3 forceN) {
        double fx = forceN.x();
        double fy = forceN.y();
        double fz = forceN.z();
        return (t, f, o) -> {
            f[o] += fx;
            f[o + 1] += fy;
            f[o + 2] += fz;
        };
    }
}
