package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.tensim.model.Vec3;

class TunableSinusoidTest {
    static double fy(TunableSinusoid s, double t) {
        double[] f = new double[3];
        s.addTo(t, f, 0);
        return f[1];
    }

    @Test
    void matchesTheSinusoidAndKeepsPhaseContinuousOnAFrequencyChange() {
        TunableSinusoid s = new TunableSinusoid(10, 0.5, new Vec3(0, -2, 0));
        assertEquals(-10 * Math.sin(2 * Math.PI * 0.5 * 0.3), fy(s, 0.3), 1e-12);
        double before = fy(s, 1.7);
        s.setFrequency(2, 1.7);
        assertEquals(before, fy(s, 1.7), 1e-12, "no jump at the change");
        // After the change the force runs at the new frequency: one period later it repeats.
        assertEquals(fy(s, 1.9), fy(s, 2.4), 1e-9);
        s.setAmplitude(0);
        assertEquals(0, fy(s, 3.1), 0);
    }
}
