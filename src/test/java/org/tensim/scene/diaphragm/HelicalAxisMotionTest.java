package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Vec3;

/** The finite helical axis law: a rigid screw motion about a given axis. */
class HelicalAxisMotionTest {
    private static final BreathingCycle CYCLE = new BreathingCycle(4, 2);

    private static Vec3 at(HelicalAxisMotion m, double t, Vec3 p) {
        double[] out = new double[3];
        m.position(t, p, out, 0);
        return new Vec3(out[0], out[1], out[2]);
    }

    @Test
    void isARigidScrewAboutItsAxis() {
        DiaphragmControls k = new DiaphragmControls(1, 0);
        Vec3 axis = new Vec3(0.3, -0.8, 0.2).normalized();
        Vec3 point = new Vec3(0.01, -0.02, 1.1);
        double angle = 0.2;
        double slide = 0.003;
        HelicalAxisMotion m = new HelicalAxisMotion(axis, point, angle, slide, CYCLE, k);
        double ti = CYCLE.inspirationS();
        Random rnd = new Random(7);
        Vec3[] p = new Vec3[6];
        Vec3[] q = new Vec3[6];
        for (int i = 0; i < p.length; i++) {
            p[i] = point.plus(new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).times(0.05));
            q[i] = at(m, ti, p[i]);
        }
        for (int i = 0; i < p.length; i++) {
            for (int j = i + 1; j < p.length; j++) {
                assertEquals(p[i].distance(p[j]), q[i].distance(q[j]), 1e-12, "distances are kept");
            }
            // The component along the axis moves by the slide only; the perpendicular part turns by the angle.
            Vec3 r0 = p[i].minus(point);
            Vec3 r1 = q[i].minus(point);
            assertEquals(r0.dot(axis) + slide, r1.dot(axis), 1e-12);
            Vec3 a0 = r0.minus(axis.times(r0.dot(axis)));
            Vec3 a1 = r1.minus(axis.times(r1.dot(axis)));
            assertEquals(angle, Math.acos(a0.dot(a1) / (a0.norm() * a1.norm())), 1e-9);
        }
        // A point on the axis only slides.
        Vec3 onAxis = point.plus(axis.times(0.04));
        assertEquals(0, at(m, ti, onAxis).distance(onAxis.plus(axis.times(slide))), 1e-12);
        // At end-expiration the rib is at rest.
        assertEquals(0, at(m, 0, p[0]).distance(p[0]), 1e-15);
    }

    @Test
    void followsTheRibAmplitudeWhileRunning() {
        DiaphragmControls k = new DiaphragmControls(1, 0);
        HelicalAxisMotion m = new HelicalAxisMotion(new Vec3(1, 0, 0), Vec3.ZERO, 0.1, 0, CYCLE, k);
        Vec3 p = new Vec3(0, -0.1, 0);
        double ti = CYCLE.inspirationS();
        double d1 = at(m, ti, p).distance(p);
        k.setRibAmplitude(2);
        double d2 = at(m, ti, p).distance(p);
        k.setRibAmplitude(0);
        double d0 = at(m, ti, p).distance(p);
        assertEquals(2 * 0.1 * Math.sin(0.05), d1, 1e-12);
        assertEquals(2 * 0.1 * Math.sin(0.1), d2, 1e-12);
        assertEquals(0, d0, 0);
    }

    @Test
    void controlsRefuseOutOfRangeValues() {
        DiaphragmControls k = new DiaphragmControls(1, 1000);
        assertThrows(IllegalArgumentException.class, () -> k.setRibAmplitude(-0.1));
        assertThrows(IllegalArgumentException.class, () -> k.setRibAmplitude(3.5));
        assertThrows(IllegalArgumentException.class, () -> k.setMuscleAmplitudePa(Double.NaN));
        String m = assertThrows(IllegalArgumentException.class, () -> k.setMuscleAmplitudePa(65_000)).getMessage();
        assertTrue(m.contains("60000.0 Pa") && m.contains("65000.0"), m);
        k.setMuscleAmplitudePa(45_000); // within the fibres' range (an active stress up to 60 kPa)
        k.setMuscleAmplitudePa(1000);
        assertEquals(1, k.ribAmplitude());
        assertEquals(1000, k.muscleAmplitudePa());
    }
}
