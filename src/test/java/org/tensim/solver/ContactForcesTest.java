package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tensim.testsupport.FiniteDifferences.maxAbs;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.RigidMotion;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.testsupport.AllocationCounter;
import org.tensim.testsupport.FiniteDifferences;

/**
 * The contact forces ({@link ContactForces}) as physics: minus the gradient of the penalty energy
 * {@code k max(0, g - d)^2 / 2} against a plane and a sphere that move and turn, the tangent equal to
 * the forces' derivative on a plane, the read-outs, the critical step counting the contacts, and a
 * force pass that allocates nothing.
 */
class ContactForcesTest {
    private static final double TIME = 0.7;

    /** 40 nodes in the unit box, each paired with a tilted plane and a sphere, both moving and turning. */
    private static SystemState scene(Random rnd) {
        Topology t = new Topology();
        RigidMotion m = ContactShapes.moving(new Vec3(0.1, -0.2, 0.05), new Vec3(0.3, 0.2, -0.1), 0.8);
        int plane = t.addContactBody(ContactShapes.body("plane", ContactShapes.plane(0.3, 1, -0.2, 0.05), m));
        int ball = t.addContactBody(ContactShapes.body("ball", ContactShapes.sphere(0.2, 0.1, 0, 0.5),
                ContactShapes.moving(Vec3.ZERO, new Vec3(0, 0.1, 0), -1.3)));
        for (int i = 0; i < 40; i++) {
            t.addNode(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1, 0.01);
            t.addContact(i, plane, 100 + 900 * rnd.nextDouble(), 0.02 * rnd.nextDouble());
            t.addContact(i, ball, 100 + 900 * rnd.nextDouble(), 0.02 * rnd.nextDouble());
        }
        return SystemState.compile(t);
    }

    @Test
    void forcesAreMinusTheEnergyGradientOnMovingPlaneAndSphere() {
        SystemState s = scene(new Random(7));
        double[] x = s.x.clone();
        double[] f = new double[x.length];
        s.contacts.forces(TIME, x, f);
        int active = s.contacts.activeCount(TIME, x);
        assertTrue(active > 10 && active < 70, "some pairs in contact, some not: " + active);
        double scale = maxAbs(f);
        double[] g = FiniteDifferences.gradient(y -> s.contacts.energy(TIME, y), x, 1e-7);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-g[k], f[k], 1e-6 * scale, "component " + k);
        }
    }

    @Test
    void theTangentIsTheForcesDerivativeOnAPlane() {
        Topology t = new Topology();
        RigidMotion m = ContactShapes.moving(new Vec3(0, 0.1, 0), new Vec3(0.2, 0.5, 0), 0.6);
        int plane = t.addContactBody(ContactShapes.body("plane", ContactShapes.plane(0.2, 1, 0.4, 0), m));
        Random rnd = new Random(11);
        for (int i = 0; i < 30; i++) {
            t.addNode(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1, 0.01);
            t.addContact(i, plane, 1e3 * (1 + rnd.nextDouble()), 0.01);
        }
        SystemState s = SystemState.compile(t);
        double[] x = s.x.clone();
        double[] z = new double[x.length];
        for (int k = 0; k < z.length; k++) {
            z[k] = rnd.nextGaussian();
        }
        s.contacts.linearise(TIME, x);
        double[] kz = new double[x.length];
        s.contacts.multiplyAdd(z, kz, null, 1);
        // -df/dx z by central differences; exact for a plane up to rounding (no node crosses the surface).
        double eps = 1e-7;
        double[] df = FiniteDifferences.directional((y, f) -> s.contacts.forces(TIME, y, f), x, z, eps);
        int active = s.contacts.activeCount(TIME, x);
        assertTrue(active > 5 && active < 25, "some nodes in contact, some not: " + active);
        double[] xp = x.clone();
        for (int k = 0; k < x.length; k++) {
            xp[k] += eps * z[k];
        }
        assertEquals(active, s.contacts.activeCount(TIME, xp), "no node crossed the surface");
        double scale = maxAbs(kz);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-df[k], kz[k], 1e-6 * scale, "component " + k);
        }
        // On a compact numbering that leaves node 0 out: the same rows, node 0's neither read nor written.
        int[] offset = new int[s.nodeCount];
        double[] zc = new double[z.length - 3];
        for (int i = 0; i < s.nodeCount; i++) {
            offset[i] = i == 0 ? -1 : 3 * (i - 1);
            for (int c = 0; c < 3 && i > 0; c++) {
                zc[3 * (i - 1) + c] = z[3 * i + c];
            }
        }
        double[] yc = new double[zc.length];
        s.contacts.multiplyAdd(zc, yc, offset, 2);
        for (int k = 3; k < x.length; k++) {
            assertEquals(2 * kz[k], yc[k - 3], 1e-12 * scale, "compact component " + k);
        }
        double[] diag = new double[x.length];
        s.contacts.addDiagonal(diag, 1);
        for (int k = 0; k < x.length; k++) {
            double[] e = new double[x.length];
            e[k] = 1;
            double[] ke = new double[x.length];
            s.contacts.multiplyAdd(e, ke, null, 1);
            assertEquals(ke[k], diag[k], 1e-12 * scale, "diagonal " + k);
        }
    }

    /** Three nodes over the plane y = 0: one above its gap, one within it, one 2 mm inside the body. */
    @Test
    void readOutsCountDepthAndReaction() {
        Topology t = new Topology();
        int plane = t.addContactBody(ContactShapes.body("floor", ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED));
        t.addNode(0, 0.01, 0, 1);
        t.addNode(0.2, 0.0005, 0, 1);
        t.addNode(0.4, -0.002, 0, 1);
        for (int i = 0; i < 3; i++) {
            t.addContact(i, plane, 1e4, 0.001);
        }
        SystemState s = SystemState.compile(t);
        ContactForces c = s.contacts;
        assertEquals(2, c.activeCount(0, s.x));
        assertEquals(0.002, c.maxPenetrationM(0, s.x), 1e-15, "depth below the surface, not below the gap");
        double expected = 1e4 * (0.0005 + 0.003);
        assertArrayEquals(new double[] {0, expected, 0}, c.totalForceN(0, s.x), 1e-12);
        assertEquals(expected, c.totalNormalForceN(0, s.x), 1e-12);
        boolean[] in = c.nodesInContact(0, s.x);
        assertTrue(!in[0] && in[1] && in[2], "nodes 1 and 2 touch");
        assertEquals(0.5 * 1e4 * (0.0005 * 0.0005 + 0.003 * 0.003), c.energy(0, s.x), 1e-15);
        assertEquals(c.energy(0, s.x), new ForceModel(s).elasticEnergy(0, s.x), 1e-15, "in the model's energy");
    }

    /** A node of mass m on one contact of stiffness k: w_max = sqrt(k / m), as if touching. */
    @Test
    void theCriticalStepCountsEveryContactAsTouching() {
        Topology t = new Topology();
        int plane = t.addContactBody(ContactShapes.body("floor", ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED));
        t.addNode(0, 1, 0, 0.01);
        t.addContact(0, plane, 400, 0);
        var c = SystemState.compile(t).criticalTimeStep();
        assertEquals(200, c.omegaMaxPower(), 1e-6, "sqrt(400 / 0.01)");
        assertTrue(c.omegaMaxGershgorin() >= 200 - 1e-9, "the bound is a bound: " + c.omegaMaxGershgorin());
    }

    @Test
    void theForcePassAndTangentAllocateNothing() {
        SystemState s = scene(new Random(3));
        ForceModel model = new ForceModel(s);
        double[] f = new double[s.x.length];
        double[] y = new double[s.x.length];
        long bytes = AllocationCounter.currentThread().bytesAllocatedBy(() -> {
            for (int i = 0; i < 2000; i++) {
                double time = 1e-3 * i;
                model.computeForces(time, s.x, s.v, f);
                s.contacts.linearise(time, s.x);
                s.contacts.multiplyAdd(f, y, null, 1e-6);
                s.contacts.addDiagonal(y, 1e-6);
            }
        }, 3);
        assertTrue(maxAbs(f) > 0, "contact forces were exerted");
        assertEquals(0, bytes, "bytes allocated by 2000 force passes with contacts");
    }
    /** Steps of rk2, implicit Euler and BDF2 with nodes on a rising floor allocate nothing (after warm-up). */
    @Test
    void stepsWithContactsAllocateNothing() {
        for (String name : new String[] {"rk2", "implicit-euler", "bdf2"}) {
            Topology t = new Topology();
            int floor = t.addContactBody(ContactShapes.body("floor", ContactShapes.plane(0, 1, 0, 0),
                    ContactShapes.translating(new Vec3(0, 0.05, 0))));
            for (int i = 0; i < 10; i++) {
                t.addNode(0.1 * i, -0.01 * 9.81 / 1e4, 0, 0.01); // resting: p = m g / k
                t.addContact(i, floor, 1e4, 0);
                if (i > 0) {
                    t.addSpring(t.node(i - 1), t.node(i), 100, 0.1);
                }
            }
            t.setGravity(new Vec3(0, -9.81, 0));
            t.setViscousDamping(5); // zeta = 0.25: the nodes ride the floor instead of bouncing off it
            Simulation sim = new Simulation(SystemState.compile(t),
                    org.tensim.solver.integrators.Integrators.create(name));
            sim.apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
            double h = sim.integrator().explicit() ? 0.1 / sim.criticalTimeStep().omegaMaxPower() : 1e-3;
            for (int i = 0; i < 300; i++) {
                sim.step(h);
            }
            long bytes = AllocationCounter.currentThread().bytesAllocatedBy(() -> {
                for (int i = 0; i < 300; i++) {
                    sim.step(h);
                }
            }, 3);
            assertEquals(10, sim.state().contacts.activeCount(sim.time(), sim.state().x), name + ": all on the floor");
            assertEquals(0, bytes, name + ": bytes allocated by 300 steps with contacts");
        }
    }
    /**
     * Each node's distance to its nearest hard body, for reports: the signed distance to the body in its pose at
     * that time, the smaller over the node's pairs, a compliant body left out, NaN without a pair.
     */
    @Test
    void nearestHardDistancesAreTheSignedDistancesToTheBodiesPosedAtThatTime() {
        Topology t = new Topology();
        for (int i = 0; i < 4; i++) {
            t.addNode(0, 0, 0, 1);
        }
        // Turned by pi/4 rad/s about z and moved along y at 0.25 m/s: at t = 2 s the plane x0 = 0 of its rest frame
        // is the world plane y = 0.5, its outside towards +y (ContactShapes.moving: x = R x0 + c).
        int plane = t.addContactBody(new org.tensim.model.ContactBody("rib", ContactShapes.plane(1, 0, 0, 0),
                ContactShapes.moving(Vec3.ZERO, new Vec3(0, 0.25, 0), Math.PI / 4), ContactShapes.BOUNDS, true));
        int ball = t.addContactBody(new org.tensim.model.ContactBody("sternum", ContactShapes.sphere(0, 0, 0, 0.1),
                RigidMotion.FIXED, ContactShapes.BOUNDS, true));
        int liver = t.addContactBody(ContactShapes.body("liver", ContactShapes.plane(1, 0, 0, 0), RigidMotion.FIXED));
        t.addContact(0, plane, 1, 0);
        t.addContact(1, plane, 1, 0);
        t.addContact(1, ball, 1, 0);
        t.addContact(2, liver, 1, 0);
        ContactForces c = SystemState.compile(t).contacts;
        double[] x = {
            3, 0.8, 1, // 0.3 m outside the plane
            0, 0.05, 0, // 0.45 m inside the plane, 0.05 m inside the ball: the plane's is the smaller
            -2, 0, 0, // only the liver, a compliant support: no hard body
            1, 1, 1}; // no pair
        double[] d = c.nearestHardDistances(2, x, 4);
        assertEquals(0.3, d[0], 1e-12);
        assertEquals(-0.45, d[1], 1e-12);
        assertTrue(Double.isNaN(d[2]), "the liver is not a hard body");
        assertTrue(Double.isNaN(d[3]), "a node without a pair has no distance");

        // At rest the plane is the world plane x = 0: node 0 is 3 m outside it, node 1 0.05 m inside the ball.
        double[] rest = c.nearestHardDistances(0, x, 4);
        assertEquals(3, rest[0], 1e-12);
        assertEquals(-0.05, rest[1], 1e-12);
        // Only the first nodes asked for are reported on.
        assertEquals(1, c.nearestHardDistances(2, x, 1).length);
    }
}
