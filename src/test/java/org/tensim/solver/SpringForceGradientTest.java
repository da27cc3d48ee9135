package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.RepeatedTest;
import org.junit.jupiter.api.RepetitionInfo;
import org.tensim.model.Topology;
import org.tensim.testsupport.FiniteDifferences;

/** Spring forces are minus the gradient of the spring energy (central finite differences). */
class SpringForceGradientTest {
    @RepeatedTest(5)
    void forcesAreMinusTheEnergyGradient(RepetitionInfo info) {
        Random rnd = new Random(1234 + info.getCurrentRepetition());
        Topology t = new Topology();
        int n = 8;
        for (int i = 0; i < n; i++) {
            t.addNode(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), 0.5 + rnd.nextDouble());
        }
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                if (rnd.nextDouble() < 0.6) {
                    t.addSpring(i, j, 1 + 100 * rnd.nextDouble(), 0.2 + rnd.nextDouble(), 0);
                }
            }
        }
        SystemState s = SystemState.compile(t);
        ForceModel fm = new ForceModel(s);
        double[] x = s.x.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.3 * rnd.nextGaussian();
        }
        double[] f = new double[x.length];
        fm.springs(x, f);
        double[] grad = FiniteDifferences.gradient(fm::springEnergy, x, 1e-6);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-grad[k], f[k], 1e-5 * Math.max(1, Math.abs(grad[k])), "coordinate " + k);
        }
    }

    @RepeatedTest(3)
    void dampedLoopWithZeroVelocityEqualsUndampedLoop(RepetitionInfo info) {
        Random rnd = new Random(99 + info.getCurrentRepetition());
        Topology t = new Topology();
        for (int i = 0; i < 6; i++) {
            t.addNode(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), 1);
        }
        for (int i = 0; i < 5; i++) {
            t.addSpring(i, i + 1, 10 + rnd.nextDouble(), 0.5, 3);
        }
        SystemState s = SystemState.compile(t);
        ForceModel fm = new ForceModel(s);
        double[] a = new double[s.x.length];
        double[] b = new double[s.x.length];
        fm.springs(s.x, a);
        fm.springsDamped(s.x, new double[s.x.length], b);
        for (int k = 0; k < a.length; k++) {
            assertEquals(a[k], b[k], 1e-12);
        }
    }

    @RepeatedTest(3)
    void axialDampingOpposesRelativeAxialVelocityAndIgnoresSliding(RepetitionInfo info) {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(1, 0, 0, 1);
        double c = 2 + info.getCurrentRepetition();
        t.addSpring(0, 1, 0, 1, c);
        SystemState s = SystemState.compile(t);
        ForceModel fm = new ForceModel(s);
        double[] f = new double[6];
        double[] v = {0, 0, 0, 0.5, 0.7, -0.2}; // node 1 separates along x at 0.5 m/s, slides in y, z
        fm.springsDamped(s.x, v, f);
        assertEquals(c * 0.5, f[0], 1e-12, "node 0 pulled towards node 1");
        assertEquals(-c * 0.5, f[3], 1e-12, "node 1 pulled back");
        assertEquals(0, f[4], 1e-12, "sliding across the axis is not damped");
        assertEquals(0, f[5], 1e-12);
    }
}
