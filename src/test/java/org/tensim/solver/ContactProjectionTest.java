package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.ContactBody;
import org.tensim.model.ContactPair;
import org.tensim.model.ForceLaw;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.thorax.DistanceGrid;
import org.tensim.scene.thorax.TestMeshes;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The contact's projection stage on hard bodies ({@link ContactBody#hard()}, a bone): after every step no node is
 * deeper than its gap, whatever the integrator, the step or how inexact the implicit solve; the correction is along
 * the normal only (frictionless), takes away the velocity that carried the node in, and leaves the rigid links
 * their lengths. A body that is not hard keeps the penalty's penetration F / k (ContactDynamicsTest).
 */
class ContactProjectionTest {
    private static final double M = 0.01; // kg
    private static final double K = 1e4; // N/m
    private static final double G = 9.81; // m/s^2

    static List<String> allIntegrators() {
        return ContactDynamicsTest.allIntegrators();
    }

    private static int hardFloor(Topology t) {
        return t.addContactBody(new ContactBody("floor", ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED,
                new double[] {-1, -1, -1, 1, 1, 1}, true));
    }

    /**
     * A node loaded onto a hard floor, sliding along it: after every step it lies on the floor (the penalty alone
     * would let it 2 m g / k in as it lands, 20 micrometres), and its tangential velocity is untouched.
     */
    @ParameterizedTest
    @MethodSource("allIntegrators")
    void aNodeOnAHardFloorStaysOnItAndSlidesFreely(String integrator) {
        Topology t = new Topology();
        int floor = hardFloor(t);
        t.addNode(new Vec3(0, 0, 0), M);
        t.addContact(0, floor, K, 0);
        t.setGravity(new Vec3(0, -G, 0));
        Simulation sim = ContactDynamicsTest.simulation(t, Integrators.create(integrator));
        SystemState s = sim.state();
        s.v[0] = 0.3;
        s.v[2] = -0.2;
        double h = ContactDynamicsTest.step(sim, 1e-3);
        while (sim.time() < 0.1) {
            sim.step(h);
            assertTrue(s.x[1] >= -1e-12, integrator + ": below the floor at t = " + sim.time() + ": " + s.x[1]);
            assertTrue(s.v[1] <= 1e-9, integrator + ": no bounce: " + s.v[1]);
        }
        assertEquals(0.3, s.v[0], 1e-12, integrator + ": tangential velocity x");
        assertEquals(-0.2, s.v[2], 1e-12, integrator + ": tangential velocity z");
        assertEquals(0.3 * sim.time(), s.x[0], 1e-9, integrator);
        assertEquals(0, s.contacts.maxPenetrationM(sim.time(), s.x), 1e-12, integrator);
    }

    /**
     * At a 50 ms step with one Newton iteration of one CG iteration (a solve far from converged), a node thrown
     * at a hard floor at 1 m/s does not stay inside it: after every step it is on or above the surface, it comes
     * off no faster than it came (the penalty's spring may throw it back; the projection adds no energy), and its
     * velocity along the floor is untouched.
     */
    @Test
    void anInexactLargeStepDoesNotLeaveANodeInsideTheFloor() {
        Topology t = new Topology();
        int floor = hardFloor(t);
        t.addNode(new Vec3(0, 0.01, 0), M);
        t.addContact(0, floor, K, 0);
        Simulation sim = ContactDynamicsTest.simulation(t,
                new PrefactoredBdf2().setNewtonIterations(1).setKrylovIterations(1));
        SystemState s = sim.state();
        s.v[1] = -1;
        s.v[0] = 0.5;
        for (int k = 0; k < 20; k++) {
            sim.step(0.05);
            assertTrue(s.x[1] >= -1e-12, "below the floor after step " + k + ": " + s.x[1]);
            assertTrue(s.v[1] <= 1 + 1e-9, "off the floor faster than it came: " + s.v[1]);
            assertEquals(0.5, s.v[0], 1e-12, "velocity along the floor");
        }
    }

    /**
     * A rigid column of two nodes standing on a hard floor under gravity: the projection alternates with the links'
     * so that the link keeps its length exactly and the foot is left within an eighth of the penalty's sinking
     * (three rounds, each halving what the link pulls back in).
     */
    @ParameterizedTest
    @MethodSource("allIntegrators")
    void aRigidColumnOnAHardFloorKeepsItsLengthAndItsFootOut(String integrator) {
        double length = 0.01;
        Topology t = new Topology();
        int floor = hardFloor(t);
        t.addNode(new Vec3(0, 0, 0), M);
        t.addNode(new Vec3(0, length, 0), M);
        t.addRigidLink(0, 1, length);
        t.addContact(0, floor, K, 0);
        t.setGravity(new Vec3(0, -G, 0));
        t.applyForce(t.node(1), ForceLaw.constant(new Vec3(0, -0.5, 0))); // a load pressing the column down
        t.setViscousDamping(0.5);
        Simulation sim = ContactDynamicsTest.simulation(t, Integrators.create(integrator));
        SystemState s = sim.state();
        double penaltyAlone = (2 * M * G + 0.5) / K; // 60 micrometres
        double deepest = 0;
        double h = ContactDynamicsTest.step(sim, 1e-3);
        while (sim.time() < 0.2) {
            sim.step(h);
            deepest = Math.max(deepest, -s.x[1]);
            double len = Math.sqrt(Math.pow(s.x[3] - s.x[0], 2) + Math.pow(s.x[4] - s.x[1], 2)
                    + Math.pow(s.x[5] - s.x[2], 2));
            assertEquals(length, len, 1e-9 * length, integrator + ": link length at t = " + sim.time());
        }
        assertTrue(deepest <= penaltyAlone / 8, integrator + ": the foot went " + deepest + " m in, against "
                + penaltyAlone + " m by the penalty alone");
    }

    /** Only nodes on hard bodies are projected; a compliant support (the liver) keeps its penalty's deflection. */
    @Test
    void aSoftBodyIsNotProjected() {
        Topology t = new Topology();
        int soft = t.addContactBody(ContactShapes.body("liver", ContactShapes.plane(0, 1, 0, 0), RigidMotion.FIXED));
        t.addNode(new Vec3(0, 0, 0), M);
        t.addContact(0, soft, K, 0);
        t.applyForce(t.node(0), ForceLaw.constant(new Vec3(0, -0.1, 0)));
        t.setViscousDamping(5);
        Simulation sim = ContactDynamicsTest.simulation(t, Integrators.create("bdf2"));
        assertEquals(0, sim.state().contacts.hardNodes().length);
        sim.runUntil(0.2, 1e-3);
        assertEquals(-0.1 / K, sim.state().x[1], 1e-6 * 0.1 / K, "y = -F / k");
    }

    /**
     * A field that grows slower than the path along its unit normal, as a sampled distance does near a thin bone's
     * middle (here phi = y (0.3 + 0.7 (y / 2 mm)^2), 0.3 m per m at the surface): one projection puts a node 1.5 mm
     * in back on its gap, to a millionth of its penetration, moving it along the normal only; a single move of
     * g - d would have left it a seventh of its penetration inside.
     */
    @Test
    void aNodeInAFieldSlowerThanItsPathIsPutOnItsGap() {
        double a = 2e-3;
        SignedDistance slow = (x, y, z, g, o) -> {
            g[o] = 0;
            g[o + 1] = 1;
            g[o + 2] = 0;
            return y * (0.3 + 0.7 * (y / a) * (y / a));
        };
        double[] x = {0.01, -1.5e-3, -0.02};
        double p = -slow.distance(x[0], x[1], x[2], new double[3], 0);
        double oneMove = slow.distance(0, x[1] + p, 0, new double[3], 0);
        assertTrue(-oneMove > 0.1 * p, "a single move leaves " + -oneMove + " m of " + p + " m");
        ContactForces c = hardPair(slow, 0);
        assertEquals(p, c.project(0, x, new double[] {1 / M}), 1e-15, "the penetration found");
        assertEquals(0, slow.distance(x[0], x[1], x[2], new double[3], 0), 1e-6 * p, "on its gap");
        assertEquals(0.01, x[0], 0, "along the normal only: x");
        assertEquals(-0.02, x[2], 0, "along the normal only: z");
    }

    /**
     * On a bone's sampled distance (a 4 mm plate's {@link DistanceGrid} at its 1.5 mm default cells), a node 0.1 mm
     * off the plate's middle, with a negative gap (it started 0.5 mm inside), is put back on its gap to a millionth
     * of its penetration, where a single move of g - d falls short by more than half: the cell that holds the
     * middle rounds the distance's ridge (-1.33 mm there against -2), so the grid's distance grows at a third of
     * the path across it.
     */
    @Test
    void aNodeDeepInAThinBonesGridIsPutOnItsGap() {
        TriangleMesh plate = TestMeshes.box(new double[] {-0.02, -0.002, -0.02}, new double[] {0.02, 0.002, 0.02});
        DistanceGrid grid = DistanceGrid.build(plate);
        double g = -0.5e-3;
        double[] x = {0.3e-3, 0.1e-3, 0.2e-3};
        double[] n = new double[3];
        double p = g - grid.distance(x[0], x[1], x[2], n, 0);
        double oneMove = grid.distance(x[0] + p * n[0], x[1] + p * n[1], x[2] + p * n[2], new double[3], 0);
        assertTrue(g - oneMove > 0.5 * p, "a single move leaves " + (g - oneMove) + " m of " + p + " m");
        ContactForces c = hardPair(grid, g);
        c.project(0, x, new double[] {1 / M});
        assertEquals(g, grid.distance(x[0], x[1], x[2], new double[3], 0), 1e-6 * p, "on its gap");
        assertEquals(-1.5e-3, x[1], 1e-9, "on the side the grid's normal points to, 0.5 mm inside its face");
    }

    private static ContactForces hardPair(SignedDistance surface, double gap) {
        return new ContactForces(List.of(new ContactBody("bone", surface, RigidMotion.FIXED,
                new double[] {-1, -1, -1, 1, 1, 1}, true)), List.of(new ContactPair(0, 0, K, gap)));
    }
}
