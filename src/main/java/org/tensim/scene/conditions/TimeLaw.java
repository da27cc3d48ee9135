package org.tensim.scene.conditions;

import java.util.Arrays;

/**
 * A dimensionless factor of time that scales a load or a motion (FEBio's load curve): a condition's value at
 * time t is its nominal value times {@code value(t)}. Laws are named once in a scene and reused.
 * Implementations must not allocate: they are evaluated at every force pass.
 */
@FunctionalInterface
public interface TimeLaw {
    /** The factor at {@code tSeconds} (s). */
    double value(double tSeconds);

    /** What a table does outside its first and last times. */
    enum Extension {
        /** The first value before the first time, the last after the last. */
        CONSTANT,
        /** The line through the first (last) two points, continued. */
        EXTRAPOLATE
    }

    /** 1 at every time. */
    static TimeLaw one() {
        return t -> 1;
    }

    /**
     * {@code amplitude * sin(2 pi frequency t + phase)}; written as {@link org.tensim.model.ForceLaw#sinusoid}
     * writes it, so that a force of this law is the same to the last bit.
     *
     * @param frequencyHz Hz (>= 0)
     * @param phaseRad    phase at t = 0, rad
     */
    static TimeLaw sine(double amplitude, double frequencyHz, double phaseRad) {
        double w = 2 * Math.PI * frequencyHz;
        return t -> amplitude * Math.sin(w * t + phaseRad);
    }

    /**
     * {@code from} until {@code startS}, then linear to {@code to} at {@code startS + durationS}, then {@code to}.
     *
     * @param durationS s (> 0)
     */
    static TimeLaw ramp(double startS, double durationS, double from, double to) {
        if (!(durationS > 0)) {
            throw new IllegalArgumentException("a ramp's duration must be > 0 s, got " + durationS);
        }
        return t -> t <= startS ? from : t >= startS + durationS ? to : from + (to - from) * (t - startS) / durationS;
    }

    /**
     * Linear interpolation between points (times[i], values[i]), times strictly increasing (at least one point);
     * outside them as {@code extension} says.
     *
     * @throws IllegalArgumentException naming the first time that is not after the one before it
     */
    static TimeLaw table(double[] times, double[] values, Extension extension) {
        if (times.length == 0 || times.length != values.length) {
            throw new IllegalArgumentException("a table needs at least one point and as many values as times");
        }
        for (int i = 1; i < times.length; i++) {
            if (!(times[i] > times[i - 1])) {
                throw new IllegalArgumentException("the times must increase: point " + i + " is at " + times[i]
                        + " s, not after point " + (i - 1) + " at " + times[i - 1] + " s");
            }
        }
        double[] ts = times.clone();
        double[] vs = values.clone();
        int n = ts.length;
        return t -> {
            if (n == 1) {
                return vs[0];
            }
            int i;
            if (t <= ts[0]) {
                if (extension == Extension.CONSTANT) {
                    return vs[0];
                }
                i = 0;
            } else if (t >= ts[n - 1]) {
                if (extension == Extension.CONSTANT) {
                    return vs[n - 1];
                }
                i = n - 2;
            } else {
                int k = Arrays.binarySearch(ts, t);
                if (k >= 0) {
                    return vs[k];
                }
                i = -k - 2;
            }
            return vs[i] + (vs[i + 1] - vs[i]) * (t - ts[i]) / (ts[i + 1] - ts[i]);
        };
    }
}
