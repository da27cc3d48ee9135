package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.model.ForceLaw;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

class SimulationTest {
    @Test
    void freeFallUnderGravityIsExactForRK2() {
        Topology t = new Topology();
        t.addNode(0, 10, 0, 2);
        t.setGravity(new Vec3(0, -9.81, 0));
        Simulation sim = Simulation.of(t);
        sim.runUntil(1.0, 0.01);
        // Constant acceleration: midpoint RK2 is exact up to rounding.
        assertEquals(10 - 0.5 * 9.81, sim.state().x[1], 1e-10);
        assertEquals(-9.81, sim.state().v[1], 1e-10);
        assertEquals(1.0, sim.time(), 1e-12);
        assertEquals(100, sim.steps());
    }

    @Test
    void constantForceAndSinusoidAddUp() {
        Topology t = new Topology();
        Node n = t.addNode(0, 0, 0, 1);
        t.applyForce(n, ForceLaw.constant(new Vec3(2, 0, 0)));
        t.applyForce(n, ForceLaw.sinusoid(3, 0.5, Math.PI / 2, new Vec3(0, 0, 5)));
        SystemState s = SystemState.compile(t);
        double[] f = new double[3];
        new ForceModel(s).computeForces(1.0, s.x, s.v, f);
        assertEquals(2, f[0], 1e-12);
        assertEquals(0, f[1], 1e-12);
        // 3 sin(2 pi 0.5 * 1 + pi/2) = 3 cos(pi) = -3, along +z
        assertEquals(-3, f[2], 1e-12);
    }

    @Test
    void viscousDampingDissipatesEnergyMonotonically() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1).fix();
        t.addNode(1.2, 0, 0, 1);
        t.addSpring(a.id(), 1, 100, 1, 0);
        t.setViscousDamping(2 * Math.sqrt(100 * 1) * 0.1);
        Simulation sim = Simulation.of(t);
        double e = sim.forces().totalEnergy();
        for (int i = 0; i < 500; i++) {
            sim.step(1e-3);
            double e2 = sim.forces().totalEnergy();
            assertTrue(e2 < e, "energy must fall at step " + i);
            e = e2;
        }
    }

    @Test
    void listenersAreNotifiedAfterEveryStepInOrder() {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        Simulation sim = Simulation.of(t);
        List<Double> times = new ArrayList<>();
        sim.addListener(s -> times.add(s.time()));
        for (int i = 0; i < 5; i++) {
            sim.step(0.1);
        }
        assertEquals(5, times.size());
        assertEquals(0.5, times.get(4), 1e-12);
        assertEquals(5, sim.profile().steps());
        assertTrue(sim.profile().totalNanos(Stage.INTEGRATE) > 0);
    }

    @Test
    void aRemovedListenerIsNoLongerNotifiedAndTheOthersStay() {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        Simulation sim = Simulation.of(t);
        List<String> calls = new ArrayList<>();
        StepListener a = s -> calls.add("a");
        StepListener b = s -> calls.add("b");
        sim.addListener(a);
        sim.addListener(b);
        sim.step(0.1);
        sim.removeListener(a);
        sim.step(0.1);
        sim.removeListener(a); // removing twice changes nothing
        sim.step(0.1);
        assertEquals(List.of("a", "b", "b", "b"), calls);
    }

    @Test
    void drivenNodesFollowTheirMotionAndPullTheirNeighbours() {
        Topology t = new Topology();
        Node d = t.addNode(0, 0, 0, 1).drive((time, rest, out, o) -> {
            out[o] = rest.x() + 0.1 * time;
            out[o + 1] = rest.y();
            out[o + 2] = rest.z();
        });
        t.addNode(1, 0, 0, 1);
        t.addSpring(d, t.node(1), 1000, 5);
        Simulation sim = Simulation.of(t);
        sim.runUntil(2, 1e-3);
        assertEquals(0.2, sim.state().x[0], 1e-12, "driven node at its prescribed position");
        assertEquals(0.1, sim.state().v[0], 1e-6, "driven node velocity from its motion");
        assertTrue(sim.state().x[3] > 1.1, "the spring pulls the free node along: " + sim.state().x[3]);
    }

    @Test
    void divergenceStopsWithStepAndNode() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1).fix();
        t.addNode(1.5, 0, 0, 1e-3);
        t.addSpring(a.id(), 1, 1e6, 1, 0);
        Simulation sim = Simulation.of(t);
        SimulationDivergedException e = assertThrows(SimulationDivergedException.class, () -> {
            for (int i = 0; i < 10000; i++) {
                sim.step(0.1);
            }
        });
        assertEquals(1, e.node());
        assertTrue(e.step() > 0 && e.step() < 10000);
        assertTrue(e.getMessage().contains("step " + e.step()), e.getMessage());
        assertTrue(e.getMessage().contains("node 1"), e.getMessage());
    }
}
