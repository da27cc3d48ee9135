package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.TensegrityElement;

class RigidLinkProjectionTest {
    /** A random tensegrity element, perturbed, with unequal masses and one fixed node. */
    static Topology perturbedElement(Random rnd, boolean fixOne) {
        Topology t = new Topology();
        TensegrityElement e = TensegrityElement.build(t, Vec3.ZERO, 1, 0.5, 1, 10, 0, true);
        if (fixOne) {
            e.nodes.get(0).fix();
        }
        return t;
    }

    static double[] perturb(SystemState s, Random rnd, double amount) {
        double[] x = s.x.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += amount * rnd.nextGaussian();
        }
        return x;
    }

    static double maxRelError(SystemState s, double[] x) {
        double worst = 0;
        for (int i = 0; i < s.linkCount(); i++) {
            int a = 3 * s.linkA[i];
            int b = 3 * s.linkB[i];
            double len = Math.sqrt(Math.pow(x[b] - x[a], 2) + Math.pow(x[b + 1] - x[a + 1], 2)
                    + Math.pow(x[b + 2] - x[a + 2], 2));
            worst = Math.max(worst, Math.abs(len - s.linkL[i]) / s.linkL[i]);
        }
        return worst;
    }

    @Test
    void everyLinkIsWithinToleranceAfterProjection() {
        Random rnd = new Random(7);
        // Links sharing nodes: a chain of rigid links plus a closing triangle, so Gauss-Seidel must iterate.
        Topology t = new Topology();
        for (int i = 0; i < 10; i++) {
            t.addNode(i, 0.8 * (i % 2), 0.1 * i, 0.5 + rnd.nextDouble()); // a zigzag: well-shaped triangles
        }
        for (int i = 0; i < 9; i++) {
            t.addRigidLink(t.node(i), t.node(i + 1));
        }
        t.addRigidLink(t.node(0), t.node(2));
        SystemState s = SystemState.compile(t);
        double[] x = perturb(s, rnd, 0.05);
        assertTrue(maxRelError(s, x) > 1e-3, "the perturbation must break the links");
        RigidLinkProjection p = new RigidLinkProjection();
        assertTrue(p.project(s, x, 1e-10, RigidLinkProjection.DEFAULT_MAX_ITERATIONS), "projection converges");
        assertTrue(p.iterations() > 1, "shared nodes need several sweeps, made " + p.iterations());
        assertTrue(maxRelError(s, x) <= 1e-10, "independent check of every link: " + maxRelError(s, x));
        assertEquals(maxRelError(s, x), p.maxRelativeError(), 1e-15, "reported error is the real one");
    }

    @Test
    void massWeightedProjectionConservesLinearMomentumAndCentreOfMass() {
        Random rnd = new Random(11);
        Topology t = perturbedElement(rnd, false);
        // Unequal masses: rebuild with random masses.
        Topology u = new Topology();
        for (Node n : t.nodes()) {
            u.addNode(n.position(), 0.2 + 3 * rnd.nextDouble());
        }
        t.rigidLinks().forEach(l -> u.addRigidLink(l.a(), l.b(), l.length()));
        SystemState s = SystemState.compile(u);
        double[] x = perturb(s, rnd, 0.1);
        double[] before = centreOfMassMoment(s, x);
        new RigidLinkProjection().project(s, x, RigidLinkProjection.DEFAULT_TOLERANCE,
                RigidLinkProjection.DEFAULT_MAX_ITERATIONS);
        double[] after = centreOfMassMoment(s, x);
        for (int k = 0; k < 3; k++) {
            assertEquals(before[k], after[k], 1e-12, "sum m x, axis " + k);
        }
    }

    static double[] centreOfMassMoment(SystemState s, double[] x) {
        double[] m = new double[3];
        for (int i = 0; i < s.nodeCount; i++) {
            for (int k = 0; k < 3; k++) {
                m[k] += s.mass[i] * x[3 * i + k];
            }
        }
        return m;
    }

    @Test
    void fixedNodesNeverMove() {
        Random rnd = new Random(5);
        Topology t = perturbedElement(rnd, true);
        SystemState s = SystemState.compile(t);
        double[] x = perturb(s, rnd, 0.1);
        double[] fixed = {x[0], x[1], x[2]};
        RigidLinkProjection p = new RigidLinkProjection();
        assertTrue(p.project(s, x, RigidLinkProjection.DEFAULT_TOLERANCE, RigidLinkProjection.DEFAULT_MAX_ITERATIONS));
        assertEquals(fixed[0], x[0], 0);
        assertEquals(fixed[1], x[1], 0);
        assertEquals(fixed[2], x[2], 0);
        assertTrue(maxRelError(s, x) <= RigidLinkProjection.DEFAULT_TOLERANCE);
    }

    @Test
    void contradictoryLinksAreReportedWithTheirResidual() {
        // Three collinear nodes with links 0-1 = 1, 1-2 = 1 and 0-2 = 3: impossible (triangle inequality).
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(1, 0.1, 0, 1);
        t.addNode(2, 0, 0, 1);
        t.addRigidLink(0, 1, 1);
        t.addRigidLink(1, 2, 1);
        t.addRigidLink(0, 2, 3);
        SystemState s = SystemState.compile(t);
        RigidLinkProjection p = new RigidLinkProjection();
        double[] x = s.x.clone();
        assertFalse(p.project(s, x, RigidLinkProjection.DEFAULT_TOLERANCE, 50), "cannot converge");
        assertFalse(p.converged());
        assertEquals(50, p.iterations());
        assertTrue(p.maxRelativeError() > 0.05, "residual reported: " + p.maxRelativeError());
        assertTrue(p.worstLink() >= 0);
    }

    @Test
    void simulationKeepsLinksAndConservesMomentumOfAFreeTensegrity() {
        Random rnd = new Random(3);
        Topology t = new Topology();
        TensegrityElement.build(t, Vec3.ZERO, 1, 0.5, 1, 50, 0.5, true);
        SystemState s = SystemState.compile(t);
        for (int k = 0; k < s.v.length; k++) {
            s.v[k] = rnd.nextGaussian();
        }
        Simulation sim = new Simulation(s);
        double[] p0 = new double[3];
        s.momentum(p0);
        double[] p = new double[3];
        for (int i = 0; i < 2000; i++) {
            sim.step(1e-3);
            assertTrue(sim.projection().maxRelativeError() <= sim.settings().projectionTolerance(),
                    "step " + i + " link error " + sim.projection().maxRelativeError());
        }
        assertTrue(maxRelError(s, s.x) <= 1e-9);
        s.momentum(p);
        for (int k = 0; k < 3; k++) {
            assertEquals(p0[k], p[k], 1e-9, "momentum axis " + k);
        }
        assertEquals(0, sim.unconvergedProjections());
    }
}
