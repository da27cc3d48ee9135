package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.model.ContactBody;
import org.tensim.model.ContactPair;
import org.tensim.model.LinearMapping;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.integrators.Integrators;

/**
 * Contact on a fine surface carried by a coarse model: the fine points touch, the coarse nodes receive the forces
 * through the mapping's transpose.
 */
class MappedContactTest {
    private static final double SIDE_M = 0.1;
    private static final int FINE = 9; // fine points per side of the plate

    /**
     * A square coarse plate of 4 nodes (0: (0, 0), 1: (L, 0), 2: (L, L), 3: (0, L), at height z0) carrying a FINE x
     * FINE grid of points by bilinear weights (they sum to 1).
     */
    private static LinearMapping grid() {
        LinearMapping.Builder b = new LinearMapping.Builder(4);
        for (int i = 0; i < FINE; i++) {
            for (int j = 0; j < FINE; j++) {
                double u = i / (FINE - 1.0);
                double v = j / (FINE - 1.0);
                b.add(new int[] {0, 1, 2, 3}, new double[] {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v});
            }
        }
        return b.build();
    }

    private static List<ContactPair> everyPoint(int points, double k) {
        List<ContactPair> pairs = new ArrayList<>();
        for (int i = 0; i < points; i++) {
            pairs.add(new ContactPair(i, 0, k, 0));
        }
        return pairs;
    }

    private static Topology plate(double z0, double massKg, double springK) {
        Topology t = new Topology();
        double[][] c = {{0, 0}, {SIDE_M, 0}, {SIDE_M, SIDE_M}, {0, SIDE_M}};
        for (double[] p : c) {
            t.addNode(p[0], p[1], z0, massKg);
        }
        for (int a = 0; a < 4; a++) {
            for (int b = a + 1; b < 4; b++) {
                t.addSpring(t.node(a), t.node(b), springK, 0);
            }
        }
        return t;
    }

    @Test
    void aFineSurfaceContactOnACoarseModelGivesTheSameReactionAsTheLoad() {
        double m = 0.05; // kg per coarse node
        double g = 9.81;
        double k = 2e4; // N/m per fine point: k / m per node far above 1 / h^2 at 10 ms
        Topology t = plate(0.002, m, 1e4);
        t.setGravity(new Vec3(0, 0, -g));
        t.setViscousDamping(2.0);
        LinearMapping fine = grid();
        ContactBody floor = ContactShapes.body("floor", ContactShapes.plane(0, 0, 1, 0), RigidMotion.FIXED);
        MappedContact contact = new MappedContact(fine, List.of(floor), everyPoint(fine.pointCount(), k));
        assertEquals(FINE * FINE, contact.pointCount());
        // the contact step (3 Newton iterations): a one-sided penalty this stiff (k / m ~ 1e7 / s^2 for the plate)
        // keeps bouncing under a single Newton iteration at 10 ms, as the nodes' own contact does without its
        // projection stage
        Simulation sim = ContactDynamicsTest.simulation(t, Integrators.create(Integrators.CONTACT));
        sim.forces().addTerm(contact);
        sim.runUntil(3, 0.01);
        double load = 4 * m * g;
        double[] reaction = contact.totalForceN(sim.time(), sim.state().x);
        assertEquals(load, reaction[2], 1e-6 * load, "the floor holds the plate's weight; z = " + sim.state().x[2] + " t = " + sim.time());
        assertEquals(0, reaction[0], 1e-12);
        assertEquals(0, reaction[1], 1e-12);
        // the plate rests level, each fine point sinking by its share of the load over its stiffness
        double[] p = contact.maxPenetrationPastGap(sim.time(), sim.state().x);
        assertEquals(load / (FINE * FINE * k), p[0], 1e-3 * p[0], "penetration on the fine surface");
        assertEquals(FINE * FINE, contact.activeCount(sim.time(), sim.state().x));
        assertTrue(Math.abs(sim.state().v[2]) < 1e-6, "at rest: v_z = " + sim.state().v[2]);
    }

    @Test
    void withoutItsTangentTheSameStiffContactBlowsUpTheLargeStep() {
        // The same plate and step with the term's forces only (no tangent): the penalty, treated explicitly,
        // is unstable at 10 ms (k / m per node ~ 1e5 / s^2 against 1 / h^2 = 1e4): why the tangent is there.
        double m = 0.05;
        Topology t = plate(0.002, m, 1e4);
        t.setGravity(new Vec3(0, 0, -9.81));
        t.setViscousDamping(2.0);
        LinearMapping fine = grid();
        ContactBody floor = ContactShapes.body("floor", ContactShapes.plane(0, 0, 1, 0), RigidMotion.FIXED);
        MappedContact contact = new MappedContact(fine, List.of(floor), everyPoint(fine.pointCount(), 2e4));
        ForceTerm forcesOnly = (time, x, v, f) -> contact.addForces(time, x, v, f);
        Simulation sim = ContactDynamicsTest.simulation(t, Integrators.create("bdf2"));
        sim.forces().addTerm(forcesOnly);
        double worst = 0;
        for (int s = 0; s < 300; s++) {
            sim.step(0.01);
            worst = Math.max(worst, Double.isFinite(sim.state().x[2]) ? Math.abs(sim.state().x[2]) : 1e9);
        }
        assertTrue(worst > 0.01, "explicit penalty at 10 ms stayed within " + worst + " m");
    }

    @Test
    void onAHardBodyTheProjectionPutsTheFineSurfaceBackOnItsGap() {
        // a soft penalty (the plate's weight would sink it by load / (81 k) = 2.4 mm) on a hard floor: after every
        // step the fine points are put back through their nodes, and the plate rests on the floor
        double m = 0.05;
        double k = 10;
        LinearMapping fine = grid();
        ContactBody floor = new ContactBody("floor", ContactShapes.plane(0, 0, 1, 0), RigidMotion.FIXED,
                ContactShapes.BOUNDS, true);
        for (boolean hard : new boolean[] {false, true}) {
            Topology t = plate(0.002, m, 1e4);
            t.setGravity(new Vec3(0, 0, -9.81));
            t.setViscousDamping(2.0);
            ContactBody b = hard ? floor : ContactShapes.body("floor", ContactShapes.plane(0, 0, 1, 0),
                    RigidMotion.FIXED);
            MappedContact contact = new MappedContact(fine, List.of(b), everyPoint(fine.pointCount(), k));
            assertEquals(hard ? 4 : 0, contact.projectedNodes().length);
            Simulation sim = ContactDynamicsTest.simulation(t, Integrators.create("bdf2"));
            sim.forces().addTerm(contact);
            sim.runUntil(3, 0.02);
            double p = contact.maxPenetrationPastGap(sim.time(), sim.state().x)[0];
            if (hard) {
                assertTrue(p < 1e-9, "penetration after the projection " + p + " m");
                for (int j = 0; j < 4; j++) {
                    assertEquals(0, sim.state().x[3 * j + 2], 1e-9, "node " + j + " rests on the floor");
                }
            } else {
                assertEquals(4 * m * 9.81 / (FINE * FINE * k), p, 1e-3 * p, "the penalty alone: load over k");
            }
        }
    }

    /** A sphere's signed distance (curved normals) touching some of the fine points of a tilted plate. */
    private static MappedContact onSphere(LinearMapping fine) {
        SignedDistance ball = ContactShapes.sphere(0.05, 0.05, -0.3, 0.3005);
        ContactBody b = ContactShapes.body("ball", ball, RigidMotion.FIXED);
        return new MappedContact(fine, List.of(b), everyPoint(fine.pointCount(), 3e3));
    }

    private static double[] tilted() {
        return new double[] {0, 0, 0.0002, 0.1, 0, -0.0003, 0.1, 0.1, 0.0001, 0.0, 0.1, 0.0004};
    }

    @Test
    void theForcesAreMinusTheEnergysGradientOnTheCoarseNodes() {
        MappedContact c = onSphere(grid());
        double[] x = tilted();
        double[] f = new double[12];
        c.addForces(0, x, new double[12], f);
        assertTrue(c.activeCount(0, x) > 0 && c.activeCount(0, x) < FINE * FINE, "some points touch");
        double h = 1e-8;
        for (int k = 0; k < 12; k++) {
            double[] a = x.clone();
            double[] b = x.clone();
            a[k] += h;
            b[k] -= h;
            double grad = (c.energy(0, a) - c.energy(0, b)) / (2 * h);
            assertEquals(-grad, f[k], 1e-6 * Math.max(1, Math.abs(f[k])), "coordinate " + k);
        }
    }

    @Test
    void theTangentIsTheForcesDerivativeForAPlane() {
        // a plane's normal is constant: K = W^T k n n^T W is then the exact derivative of the forces
        ContactBody tiltedFloor = ContactShapes.body("floor", ContactShapes.plane(0.2, -0.1, 1, 0), RigidMotion.FIXED);
        LinearMapping fine = grid();
        MappedContact c = new MappedContact(fine, List.of(tiltedFloor), everyPoint(fine.pointCount(), 3e3));
        double[] x = tilted();
        c.linearise(0, x);
        double[] z = {0.3, -0.2, 0.5, 0.1, 0.4, -0.6, -0.3, 0.2, 0.1, 0.7, -0.1, 0.2};
        double[] kz = new double[12];
        c.multiplyAdd(z, kz, null, 1);
        double h = 1e-9;
        double[] fa = new double[12];
        double[] fb = new double[12];
        double[] a = x.clone();
        double[] b = x.clone();
        for (int k = 0; k < 12; k++) {
            a[k] += h * z[k];
            b[k] -= h * z[k];
        }
        c.addForces(0, a, new double[12], fa);
        c.addForces(0, b, new double[12], fb);
        for (int k = 0; k < 12; k++) {
            double dfdz = (fa[k] - fb[k]) / (2 * h);
            assertEquals(-dfdz, kz[k], 1e-6 * Math.max(1, Math.abs(kz[k])), "coordinate " + k);
        }
        // the compact layout (node 2 left out) gives the same rows for the others
        int[] offset = {0, 3, -1, 6};
        double[] zc = {z[0], z[1], z[2], z[3], z[4], z[5], z[9], z[10], z[11]};
        double[] yc = new double[9];
        c.multiplyAdd(zc, yc, offset, 1);
        double[] z0 = z.clone();
        z0[6] = 0;
        z0[7] = 0;
        z0[8] = 0;
        double[] full = new double[12];
        c.multiplyAdd(z0, full, null, 1);
        int[] rows = {0, 1, 2, 3, 4, 5, 9, 10, 11};
        for (int r = 0; r < rows.length; r++) {
            assertEquals(full[rows[r]], yc[r], 1e-12);
        }
    }

    @Test
    void theNodesReceiveThePointsTotalForceAndMoment() {
        LinearMapping fine = grid();
        SignedDistance plane = ContactShapes.plane(0.2, -0.1, 1, 0);
        ContactBody b = ContactShapes.body("floor", plane, RigidMotion.FIXED);
        double k = 3e3;
        MappedContact c = new MappedContact(fine, List.of(b), everyPoint(fine.pointCount(), k));
        double[] x = tilted();
        double[] f = new double[12];
        c.addForces(0, x, new double[12], f);
        double[] p = new double[3 * fine.pointCount()];
        fine.apply(x, p);
        double[] points = new double[6]; // total force, then moment about the origin, of the points' forces
        double[] n = new double[3];
        for (int i = 0; i < fine.pointCount(); i++) {
            double d = plane.distance(p[3 * i], p[3 * i + 1], p[3 * i + 2], n, 0);
            double kp = k * Math.max(0, -d);
            double[] fi = {kp * n[0], kp * n[1], kp * n[2]};
            add(points, p, 3 * i, fi, 0);
        }
        double[] nodes = new double[6];
        for (int j = 0; j < 4; j++) {
            add(nodes, x, 3 * j, f, 3 * j);
        }
        assertTrue(Math.abs(points[2]) > 0.1, "the plate presses: " + points[2] + " N");
        for (int a = 0; a < 6; a++) {
            assertEquals(points[a], nodes[a], 1e-12 * Math.abs(points[2]), "component " + a);
        }
    }

    /** Adds force f (at fo) and its moment about the origin at point r (at ro) to sum (force, moment). */
    private static void add(double[] sum, double[] r, int ro, double[] f, int fo) {
        sum[0] += f[fo];
        sum[1] += f[fo + 1];
        sum[2] += f[fo + 2];
        sum[3] += r[ro + 1] * f[fo + 2] - r[ro + 2] * f[fo + 1];
        sum[4] += r[ro + 2] * f[fo] - r[ro] * f[fo + 2];
        sum[5] += r[ro] * f[fo + 1] - r[ro + 1] * f[fo];
    }

    @Test
    void aPairOnAPointTheSurfaceDoesNotHaveIsRefusedNamingIt() {
        LinearMapping fine = grid();
        ContactBody b = ContactShapes.body("floor", ContactShapes.plane(0, 0, 1, 0), RigidMotion.FIXED);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new MappedContact(fine, List.of(b), List.of(new ContactPair(81, 0, 1, 0))));
        assertTrue(e.getMessage().contains("pair 0 is on point 81") && e.getMessage().contains("0..80"),
                e.getMessage());
    }
}
