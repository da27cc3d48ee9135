package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.SurfaceSliding.Mode;
import org.tensim.solver.integrators.Integrators;

/**
 * Two bodies in one state coupled by the sliding term, run by the solver: a block resting on a soft plate carries its
 * weight through the term, and a node held on a driven surface that moves sideways and up and down stays on it
 * within F / k and is not dragged along (frictionless).
 */
class SurfaceSlidingBodiesTest {
    private static final double G = 9.81; // m/s^2

    /** The identity mapping of nodes [0, n) of a state of {@code nodes} nodes. */
    private static LinearMapping identity(int n, int nodes) {
        LinearMapping.Builder b = new LinearMapping.Builder(nodes);
        for (int i = 0; i < n; i++) {
            b.add(new int[] {i}, new double[] {1});
        }
        return b.build();
    }

    private static Simulation simulation(Topology t) {
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create("rk2"));
        // Gravity and the driven surface do work on the nodes: the monitor's energy balance does not hold.
        return sim.apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY,
                sim.settings().energyCheckInterval()));
    }

    @Test
    void aBlockRestingOnASoftPlateCarriesItsWeightThroughTheTerm() {
        int g = 9;
        double h = 0.01; // m, plate spacing
        Topology t = new Topology();
        for (int i = 0; i < g; i++) {
            for (int j = 0; j < g; j++) {
                var n = t.addNode(i * h, j * h, 0, 0.001);
                if (i == 0 || j == 0 || i == g - 1 || j == g - 1) {
                    n.fix();
                }
            }
        }
        int[] tris = new int[6 * (g - 1) * (g - 1)];
        int k = 0;
        for (int i = 0; i + 1 < g; i++) {
            for (int j = 0; j + 1 < g; j++) {
                int a = i * g + j, b = (i + 1) * g + j, c = (i + 1) * g + j + 1, d = i * g + j + 1;
                // Pretensioned springs (rest 0.9 of their length) give the plate its out-of-plane stiffness.
                t.addSpring(a, b, 500, 0.9 * h, 0);
                t.addSpring(a, d, 500, 0.9 * h, 0);
                t.addSpring(a, c, 200, 0.9 * h * Math.sqrt(2), 0);
                System.arraycopy(new int[] {a, b, c, a, c, d}, 0, tris, k, 6); // normal +z
                k += 6;
            }
        }
        for (int i = 1; i < g; i++) {
            t.addSpring((g - 1) * g + i - 1, (g - 1) * g + i, 500, 0.9 * h, 0);
            t.addSpring(i * g - 1 + g, (i - 1) * g + g - 1, 500, 0.9 * h, 0);
        }
        // The block: a 12 mm cube of 8 nodes of 5 g each, its bottom face at the plate's middle, 1 mm above it.
        int first = t.nodeCount();
        double side = 0.012;
        double cx = (g - 1) * h / 2 - side / 2 + 0.002;
        for (int c = 0; c < 8; c++) {
            t.addNode(cx + side * (c & 1), cx + side * ((c >> 1) & 1), 0.001 + side * ((c >> 2) & 1), 0.005);
        }
        for (int a = first; a < first + 8; a++) {
            for (int b = a + 1; b < first + 8; b++) {
                t.addSpring(t.node(a), t.node(b), 2000, 0);
            }
        }
        double mass = 8 * 0.005;
        t.setGravity(new Vec3(0, 0, -G));
        t.setViscousDamping(0.2);
        Simulation sim = simulation(t);
        int[] bottom = {first, first + 1, first + 2, first + 3};
        SurfaceSliding term = new SurfaceSliding(bottom, identity(g * g, t.nodeCount()), tris,
                new double[] {1000, 1000, 1000, 1000}, Mode.CONTACT, 0, sim.state().x);
        sim.forces().addTerm(term);
        sim.runUntil(1.5, 1e-4);
        double[] x = sim.state().x;
        double[] f = new double[x.length];
        term.addForces(sim.time(), x, sim.state().v, f);
        double onPlate = 0;
        double onBlock = 0;
        for (int j = 0; j < t.nodeCount(); j++) {
            if (j < g * g) {
                onPlate += f[3 * j + 2];
            } else {
                onBlock += f[3 * j + 2];
            }
        }
        assertEquals(-mass * G, onPlate, 1e-3 * mass * G, "the plate carries the block's weight");
        assertEquals(mass * G, onBlock, 1e-3 * mass * G, "the term holds the block up");
        // The plate sagged under the block (it is soft), and the block rests on it at the penetration F / k.
        double sag = -x[3 * (g * g / 2) + 2];
        assertTrue(sag > 1e-3, "the plate's middle sagged " + sag + " m");
        double perFollower = mass * G / 4 / 1000;
        double pen = term.maxPenetrationM(x);
        assertTrue(pen > 0.5 * perFollower && pen < 2 * perFollower, "penetration " + pen + " m, F / k per follower "
                + perFollower + " m");
    }

    @Test
    void aNodeHeldOnADrivenSurfaceStaysOnItWithinFOverKAndIsNotDraggedAlong() {
        double m = 0.01; // kg
        double k = 100; // N/m: w0 = 100 rad/s, well above the drive's 2 pi rad/s (quasi-static)
        double amp = 0.02; // m, vertical amplitude
        double w = 2 * Math.PI; // rad/s
        double slide = 0.05; // m/s, sideways speed of the surface
        Topology t = new Topology();
        double[][] corners = {{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}};
        for (double[] c : corners) {
            t.addNode(c[0], c[1], 0, 0.001).drive((time, rest, out, o) -> {
                out[o] = rest.x() + slide * time;
                out[o + 1] = rest.y();
                out[o + 2] = rest.z() + amp * Math.sin(w * time);
            });
        }
        t.addNode(0.003, 0.001, -m * G / k, m); // the static position under its weight
        t.setGravity(new Vec3(0, 0, -G));
        Simulation sim = simulation(t);
        sim.state().v[14] = amp * w; // moving up with the surface at t = 0
        SurfaceSliding term = new SurfaceSliding(new int[] {4}, identity(4, 5), new int[] {0, 1, 2, 0, 2, 3},
                new double[] {k}, Mode.SLIDING, 0, sim.state().x);
        sim.forces().addTerm(term);
        // The node's distance d to the plane z_s = amp sin(w t) obeys m d'' + k d = -m g - m z_s'', and it starts
        // at d = -m g / k with d' = 0: d = -m g / k + B (sin(w t) - (w / w0) sin(w0 t)), B = (m amp w^2 / k) / (1 -
        // (w / w0)^2). Its largest normal load F = m g + k B (1 + w / w0) bounds |d| by F / k.
        double w0 = Math.sqrt(k / m);
        double bAmp = m * amp * w * w / k / (1 - (w / w0) * (w / w0));
        double loadMax = m * G + k * bAmp * (1 + w / w0); // N
        double worstD = 0;
        double worstTracking = 0;
        int[] seen = new int[2];
        double dt = 1e-4;
        for (int step = 1; step <= 20000; step++) {
            sim.step(dt);
            double time = sim.time();
            double[] x = sim.state().x;
            double d = x[14] - amp * Math.sin(w * time); // the surface is the plane z = amp sin(w t)
            worstD = Math.max(worstD, Math.abs(d));
            double exact = -m * G / k + bAmp * (Math.sin(w * time) - w / w0 * Math.sin(w0 * time));
            worstTracking = Math.max(worstTracking, Math.abs(d - exact));
            seen[term.pairedTriangle(0)] = 1;
        }
        double[] x = sim.state().x;
        assertTrue(worstD <= loadMax / k, "|d| up to " + worstD + " m, F / k = " + loadMax / k + " m");
        assertTrue(worstTracking < 1e-3 * loadMax / k, "d off the exact solution by " + worstTracking + " m");
        assertEquals(0.003, x[12], 1e-12, "frictionless: the surface slid 0.1 m under the node, which stays");
        assertEquals(0.001, x[13], 1e-12);
        assertEquals(2, seen[0] + seen[1], "the surface slid far enough to pair the node with both triangles");
    }

    /**
     * A free node bouncing on a free-floating plate (4 nodes, 6 springs), no gravity, nothing fixed: the term's
     * forces are internal, so the total momentum stays what it was to round-off, and the total energy (kinetic,
     * springs and the term's) is conserved to the integrator's error (rk4, 20 000 steps a second).
     */
    @Test
    void aFreeNodeOnAFreePlateConservesMomentumAndEnergy() {
        Topology t = new Topology();
        double[][] corners = {{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}};
        for (double[] c : corners) {
            t.addNode(c[0], c[1], 0, 0.01);
        }
        for (int a = 0; a < 4; a++) {
            for (int b = a + 1; b < 4; b++) {
                t.addSpring(t.node(a), t.node(b), 200, 0);
            }
        }
        t.addNode(0.06, 0.03, 0.002, 0.005); // above triangle (0, 1, 2), 2 mm off the plate
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create("rk4"));
        double[] v = sim.state().v;
        v[12] = 0.01; // m/s: sliding slowly along the plate (stays over the same triangle)
        v[14] = -0.05; // and moving into it
        SurfaceSliding term = new SurfaceSliding(new int[] {4}, identity(4, 5), new int[] {0, 1, 2, 0, 2, 3},
                new double[] {50}, Mode.SLIDING, 0.002, sim.state().x);
        sim.forces().addTerm(term);
        double[] p0 = momentum(sim.state());
        double e0 = energy(sim);
        double worstE = 0;
        for (int step = 0; step < 10000; step++) {
            sim.step(5e-5);
            worstE = Math.max(worstE, Math.abs(energy(sim) - e0));
        }
        double[] p1 = momentum(sim.state());
        double scale = 0.005 * 0.05;
        for (int a = 0; a < 3; a++) {
            assertEquals(p0[a], p1[a], 1e-12 * scale, "momentum " + a);
        }
        assertTrue(e0 > 0 && worstE < 1e-6 * e0, "energy drift " + worstE + " J of " + e0 + " J");
        assertTrue(term.maxSeparationM(sim.state().x) + term.maxPenetrationM(sim.state().x) > 1e-4,
                "the node did move against the term");
    }

    private static double[] momentum(SystemState s) {
        double[] p = new double[3];
        for (int j = 0; j < s.nodeCount; j++) {
            for (int a = 0; a < 3; a++) {
                p[a] += s.mass[j] * s.v[3 * j + a];
            }
        }
        return p;
    }

    private static double energy(Simulation sim) {
        SystemState s = sim.state();
        double k = 0;
        for (int j = 0; j < s.nodeCount; j++) {
            for (int a = 0; a < 3; a++) {
                k += 0.5 * s.mass[j] * s.v[3 * j + a] * s.v[3 * j + a];
            }
        }
        return k + sim.forces().elasticEnergy(sim.time(), s.x);
    }
}
