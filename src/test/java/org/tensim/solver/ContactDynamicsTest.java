package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.tensim.model.ForceLaw;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.integrators.Integrators;

/**
 * Contact with rigid bodies in every integrator: a loaded node settles at the penetration F / k with
 * the reaction equal to the load, it slides without friction, a dropped node stays within the penalty's
 * dynamic penetration, and a moving plane carries a resting node along.
 */
class ContactDynamicsTest {
    private static final double M = 0.01; // kg
    private static final double K = 1e4; // N/m: w = sqrt(K / M) = 1000 rad/s

    static List<String> allIntegrators() {
        return Integrators.names();
    }

    /** Every integrator but forward Euler, which amplifies every undamped oscillation. */
    static List<String> integratorsStableUndamped() {
        return Integrators.names().stream().filter(n -> !n.equals("euler")).toList();
    }

    /** One free node of mass M at p, in contact (stiffness k, gap 0) with body sdf moved by motion. */
    private static Topology oneNode(Vec3 p, double k, SignedDistance sdf, RigidMotion motion) {
        Topology t = new Topology();
        int b = t.addContactBody(ContactShapes.body("body", sdf, motion));
        t.addNode(p, M);
        t.addContact(0, b, k, 0);
        return t;
    }

    private static Simulation simulation(Topology t, String integrator) {
        return simulation(t, Integrators.create(integrator));
    }

    /** A simulation of t without the energy check (the contact tests' bodies do work on the nodes). */
    static Simulation simulation(Topology t, Integrator integrator) {
        Simulation sim = new Simulation(SystemState.compile(t), integrator);
        // A body that pushes a node from rest gives it energy from nothing in the monitor's view.
        sim.apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
        return sim;
    }

    /** A tenth of 1 / w_max for explicit methods (as if in contact), the given step for implicit ones. */
    static double step(Simulation sim, double implicitStep) {
        return sim.integrator().explicit() ? 0.1 / sim.criticalTimeStep().omegaMaxPower() : implicitStep;
    }

    /** F = 0.1 N pushes a node onto the floor y = 0; damped, it settles at p = F / k, the floor holding F. */
    @ParameterizedTest
    @MethodSource("allIntegrators")
    void aLoadedNodeSettlesAtPenetrationFOverK(String integrator) {
        Topology t = oneNode(new Vec3(0, 0, 0), K, ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED);
        double load = 0.1;
        t.applyForce(t.node(0), ForceLaw.constant(new Vec3(0, -load, 0)));
        t.setViscousDamping(5); // zeta = c / (2 sqrt(k m)) = 0.25
        Simulation sim = simulation(t, integrator);
        sim.runUntil(0.2, step(sim, 1e-3));
        SystemState s = sim.state();
        assertEquals(-load / K, s.x[1], 1e-6 * load / K, integrator + ": y = -F / k");
        assertEquals(load / K, s.contacts.maxPenetrationM(sim.time(), s.x), 1e-6 * load / K);
        assertArrayEquals(new double[] {0, load, 0}, s.contacts.totalForceN(sim.time(), s.x), 1e-6 * load,
                integrator + ": the reaction is minus the load");
        assertEquals(1, s.contacts.activeCount(sim.time(), s.x));
    }

    /** The stiffer the contact, the smaller the penetration: F / k down to 1e-8 m (implicit Euler, 1 ms steps). */
    @ParameterizedTest
    @ValueSource(doubles = {1e3, 1e5, 1e7})
    void stifferContactPenetratesLess(double k) {
        Topology t = oneNode(new Vec3(0, 0, 0), k, ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED);
        t.setGravity(new Vec3(0, -9.81, 0));
        t.setViscousDamping(2 * Math.sqrt(k * M));
        Simulation sim = simulation(t, "implicit-euler");
        sim.runUntil(0.5, 1e-3);
        double expected = M * 9.81 / k;
        assertEquals(expected, sim.state().contacts.maxPenetrationM(sim.time(), sim.state().x), 1e-6 * expected);
    }

    /**
     * Undamped, a node touching the floor under gravity with a tangential velocity keeps it exactly (no
     * friction), while it oscillates on the penalty spring between p = 0 and 2 m g / k (5 % allowed for the
     * explicit methods at w h = 0.1, 10 % for the implicit ones at w h = 1: BDF2's one Newton iteration per
     * step overshoots by 5 %). Forward Euler left out: it amplifies every undamped oscillation
     * ({@code |R| > 1} on the imaginary axis).
     */
    @ParameterizedTest
    @MethodSource("integratorsStableUndamped")
    void aSlidingNodeKeepsItsTangentialMomentum(String integrator) {
        Topology t = oneNode(new Vec3(0, 0, 0), K, ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED);
        t.setGravity(new Vec3(0, -9.81, 0));
        Simulation sim = simulation(t, integrator);
        SystemState s = sim.state();
        s.v[0] = 0.3;
        s.v[2] = -0.2;
        double h = step(sim, 1e-3);
        double deepest = 0;
        while (sim.time() < 0.1) {
            sim.step(h);
            deepest = Math.max(deepest, s.contacts.maxPenetrationM(sim.time(), s.x));
        }
        assertEquals(0.3, s.v[0], 1e-12, integrator + ": tangential velocity x");
        assertEquals(-0.2, s.v[2], 1e-12, integrator + ": tangential velocity z");
        assertEquals(0.3 * sim.time(), s.x[0], 1e-9, integrator);
        double bound = 2 * M * 9.81 / K;
        double allowed = sim.integrator().explicit() ? 1.05 : 1.1;
        assertTrue(deepest > 0.4 * bound && deepest <= allowed * bound, integrator + ": deepest " + deepest
                + " m against 2 m g / k = " + bound + " m");
    }

    /** A node resting on the floor, pushed along it by 0.02 N, accelerates at F / m unimpeded. */
    @ParameterizedTest
    @MethodSource("allIntegrators")
    void aNodePushedAlongTheFloorAcceleratesAsFOverM(String integrator) {
        double weight = M * 9.81;
        Topology t = oneNode(new Vec3(0, -weight / K, 0), K, ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED);
        t.setGravity(new Vec3(0, -9.81, 0));
        t.applyForce(t.node(0), ForceLaw.constant(new Vec3(0, 0, 0.02)));
        Simulation sim = simulation(t, integrator);
        sim.runUntil(0.1, step(sim, 1e-3));
        double a = 0.02 / M;
        assertEquals(a * sim.time(), sim.state().v[2], 1e-9, integrator + ": v = F t / m");
        // Position: exact for the second-order methods; the first-order ones are off by a t h / 2.
        assertEquals(0.5 * a * sim.time() * sim.time(), sim.state().x[2], 0.6 * a * sim.time() * 1e-3,
                integrator + ": x = F t^2 / (2 m)");
        assertEquals(1, sim.state().contacts.activeCount(sim.time(), sim.state().x), integrator + ": on the floor");
    }

    /**
     * Dropped from 5 cm onto a ball of radius 0.1 m (slightly off its top), a node of 1 g on a 100 N/m
     * contact (w = 316 rad/s) hits it at v = 0.99 m/s and sinks in at most {@code p_e + sqrt(p_e^2 + (v / w)^2)}
     * (the undamped penalty spring about its static penetration p_e = m g / k: 3.2 mm), 2 % allowed for the
     * integrators' error, plus for an implicit 1 ms step one step of free flight into the ball (v h: the
     * contact is linearised at the start of the step). It bounces off no faster than it came.
     */
    @ParameterizedTest
    @ValueSource(strings = {"rk2", "verlet", "rk4", "implicit-euler", "bdf2"})
    void aNodeDroppedOnASphereStaysWithinTheDynamicBound(String integrator) {
        double m = 1e-3;
        double k = 100;
        double g = 9.81;
        Topology t = new Topology();
        int b = t.addContactBody(ContactShapes.body("ball", ContactShapes.sphere(0, 0, 0, 0.1), RigidMotion.FIXED));
        t.addNode(0.01, 0.15, 0, m);
        t.addContact(0, b, k, 0);
        t.setGravity(new Vec3(0, -g, 0));
        Simulation sim = simulation(t, integrator);
        SystemState s = sim.state();
        double h = step(sim, 1e-3);
        double deepest = 0;
        double speed = 0;
        // Impact at 0.10 s, contact for about pi / w = 10 ms; the bounce is still on its way up at 0.15 s.
        while (sim.time() < 0.15) {
            sim.step(h);
            deepest = Math.max(deepest, s.contacts.maxPenetrationM(sim.time(), s.x));
            speed = Math.max(speed, Math.hypot(s.v[0], s.v[1]));
        }
        double v = Math.sqrt(2 * g * (Math.hypot(0.01, 0.15) - 0.1));
        double pe = m * g / k;
        double bound = 1.02 * (pe + Math.hypot(pe, v * Math.sqrt(m / k))) + (sim.integrator().explicit() ? 0 : v * h);
        assertTrue(deepest > 0.5 * v * Math.sqrt(m / k), integrator + ": it hit the ball: " + deepest + " m");
        assertTrue(deepest <= bound, integrator + ": sank " + deepest + " m into the ball, bound " + bound + " m");
        assertTrue(speed < 1.02 * v, integrator + ": no energy gained at the impact: " + speed + " m/s, v = " + v);
        assertTrue(s.v[1] > 0, integrator + ": it bounced");
    }

    /**
     * A floor rising at 0.1 m/s from under a node resting on it carries the node along: after 0.2 s the
     * node moves with the floor, at most u / w (its start-up oscillation on the penalty spring) plus
     * m g / k below the floor's surface, never deeper.
     */
    @ParameterizedTest
    @ValueSource(strings = {"rk2", "verlet", "implicit-euler", "bdf2"})
    void aRisingFloorCarriesARestingNode(String integrator) {
        double u = 0.1;
        double g = 9.81;
        Topology t = oneNode(new Vec3(0, -M * g / K, 0), K, ContactShapes.plane(0, 1, 0, 0),
                ContactShapes.translating(new Vec3(0, u, 0)));
        t.setGravity(new Vec3(0, -g, 0));
        t.setViscousDamping(2); // zeta = 0.1: the start-up oscillation dies out within the run
        Simulation sim = simulation(t, integrator);
        SystemState s = sim.state();
        double h = step(sim, 1e-3);
        double deepest = 0;
        while (sim.time() < 0.2) {
            sim.step(h);
            deepest = Math.max(deepest, s.contacts.maxPenetrationM(sim.time(), s.x));
        }
        double w = Math.sqrt(K / M);
        // At steady rise the contact carries the weight and the damping: p = (m g + c u) / k.
        double p = (M * g + 2 * u) / K;
        assertEquals(u * sim.time() - p, s.x[1], 0.02 * p, integrator + ": with the floor, p below it");
        assertEquals(u, s.v[1], 0.02 * u, integrator + ": at the floor's speed");
        assertTrue(deepest <= p + u / w, integrator + ": deepest " + deepest + " m");
    }

    /**
     * A compliant foundation (the liver's support): a square plate of 3 x 3 nodes resting 5 mm above the plane
     * y = 0, each node's pair of stiffness K_f A_i with the gap at its rest distance (in contact from rest, one-sided),
     * pressed by a total load F shared by area. Damped, the plate sinks by F / (K_f A) from rest, not to the plane,
     * and the plane holds F; a load that lifts it meets no pull.
     */
    @ParameterizedTest
    @MethodSource("allIntegrators")
    void aPlateOnACompliantFoundationSinksByLoadOverStiffness(String integrator) {
        double kf = 5e4; // Pa/m
        double side = 0.1; // m, plate 10 cm square
        double rest = 0.005; // m above the plane
        double[] share = {0.25, 0.5, 0.25}; // each node's share of a side (the trapezoid rule)
        Topology t = new Topology();
        int b = t.addContactBody(ContactShapes.body("liver", ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED));
        double load = 5; // N over 0.01 m^2: 500 Pa
        int id = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double area = share[i] * share[j] * side * side; // sums to side^2
                t.addNode(new Vec3(0.05 * i, rest, 0.05 * j), M);
                t.addContact(id, b, kf * area, rest);
                t.applyForce(t.node(id), ForceLaw.constant(new Vec3(0, -load * area / (side * side), 0)));
                id++;
            }
        }
        t.setViscousDamping(1.4 * Math.sqrt(kf * side * side / 16 * M)); // damping ratio 0.7 for the corner nodes
        Simulation sim = simulation(t, integrator);
        sim.runUntil(1, step(sim, 1e-3));
        SystemState s = sim.state();
        double sink = load / (kf * side * side); // 10 mm
        for (int n = 0; n < 9; n++) {
            assertEquals(rest - sink, s.x[3 * n + 1], 1e-4 * sink, integrator + ": node " + n + " sinks by F / (K A)");
        }
        assertArrayEquals(new double[] {0, load, 0}, s.contacts.totalForceN(sim.time(), s.x), 1e-4 * load,
                integrator + ": the foundation holds the load");
        assertEquals(sink - rest, s.contacts.maxPenetrationM(sim.time(), s.x), 1e-4 * sink,
                integrator + ": below the plane by the sink less the rest gap");
        // Lift it: the foundation lets go (one-sided), the plate leaves at the load's acceleration.
        for (int n = 0; n < 9; n++) {
            t.applyForce(t.node(n), ForceLaw.constant(new Vec3(0, 2 * load, 0)));
        }
        Simulation up = simulation(t, integrator);
        up.runUntil(0.05, step(up, 1e-3));
        assertEquals(0, up.state().contacts.activeCount(up.time(), up.state().x), integrator + ": no pull");
        assertTrue(up.state().x[1] > rest, integrator + ": the plate rises above its rest height");
    }
}
