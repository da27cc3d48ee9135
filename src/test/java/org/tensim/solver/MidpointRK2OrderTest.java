package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;

/** The paper's RK2 converges at order 2 on one mass on an anchored spring, x(t) = x0 cos(w t). */
class MidpointRK2OrderTest {
    static final double K = 40; // N/m
    static final double M = 0.5; // kg
    static final double L = 1; // m
    static final double X0 = 0.1; // m, initial stretch
    static final double T_END = 3; // s

    static double errorAt(double dt) {
        Topology t = new Topology();
        Node anchor = t.addNode(0, 0, 0, 1).fix();
        Node mass = t.addNode(L + X0, 0, 0, M);
        t.addSpring(anchor.id(), mass.id(), K, L, 0);
        Simulation sim = Simulation.of(t);
        int steps = (int) Math.round(T_END / dt);
        for (int i = 0; i < steps; i++) {
            sim.step(dt);
        }
        double w = Math.sqrt(K / M);
        double exact = L + X0 * Math.cos(w * steps * dt);
        return Math.abs(sim.state().x[3] - exact);
    }

    @Test
    void globalErrorFallsAtOrderTwo() {
        double[] dts = {0.02, 0.01, 0.005, 0.0025, 0.00125};
        double[] lx = new double[dts.length];
        double[] ly = new double[dts.length];
        for (int i = 0; i < dts.length; i++) {
            lx[i] = Math.log(dts[i]);
            ly[i] = Math.log(errorAt(dts[i]));
        }
        double slope = fitSlope(lx, ly);
        assertEquals(2.0, slope, 0.15, "fitted order of RK2 (log error against log dt)");
        // Halving dt divides the error by about 4.
        double ratio = errorAt(0.005) / errorAt(0.0025);
        assertTrue(ratio > 3.5 && ratio < 4.5, "error ratio on halving dt: " + ratio);
    }

    static double fitSlope(double[] x, double[] y) {
        double mx = 0;
        double my = 0;
        for (int i = 0; i < x.length; i++) {
            mx += x[i] / x.length;
            my += y[i] / y.length;
        }
        double sxy = 0;
        double sxx = 0;
        for (int i = 0; i < x.length; i++) {
            sxy += (x[i] - mx) * (y[i] - my);
            sxx += (x[i] - mx) * (x[i] - mx);
        }
        return sxy / sxx;
    }

    @Test
    void undampedAmplitudeGrowsAsTheAmplificationFactorPredicts() {
        // |R(i w h)|^2 = 1 + (w h)^4 / 4: RK2 gains energy on an undamped spring (docs/physics.md).
        double w = Math.sqrt(K / M);
        double h = 0.2 / w;
        Topology t = new Topology();
        Node anchor = t.addNode(0, 0, 0, 1).fix();
        t.addNode(L + X0, 0, 0, M);
        t.addSpring(anchor.id(), 1, K, L, 0);
        Simulation sim = Simulation.of(t);
        int steps = 2000;
        for (int i = 0; i < steps; i++) {
            sim.step(h);
        }
        double u = sim.state().x[3] - L;
        double vel = sim.state().v[3];
        double amplitude = Math.sqrt(u * u + (vel / w) * (vel / w));
        double predicted = X0 * Math.pow(1 + Math.pow(w * h, 4) / 4, steps / 2.0);
        assertEquals(predicted, amplitude, 0.01 * predicted);
        assertTrue(amplitude > X0 * 1.3, "amplitude must grow: " + amplitude);
    }
}
