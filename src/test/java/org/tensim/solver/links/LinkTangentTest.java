package org.tensim.solver.links;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.solver.SystemState;

/**
 * The links' tangent space of the implicit step: P is the mass-weighted (M-orthogonal) projector
 * onto the linearised constraints, for disjoint links (one sweep) and for links that share nodes
 * (swept to convergence): P u meets the constraints, P P = P, M P is symmetric, and P^T = M P M^-1;
 * the same in BDF2's compact layout and in implicit Euler's full one.
 */
class LinkTangentTest {
    /** A fixed node, a free triangle of links hanging from it by a link, and a disjoint free link. */
    static SystemState scene() {
        return scene(true);
    }

    /** The same without the triangle's links a-b and c-a: every node in at most one link (one sweep). */
    static SystemState disjointScene() {
        return scene(false);
    }

    private static SystemState scene(boolean triangle) {
        Topology t = new Topology();
        Node top = t.addNode(0, 0, 0, 1).fix();
        Node a = t.addNode(0.01, 0.002, -0.1, 0.3);
        Node b = t.addNode(0.09, -0.01, -0.15, 0.7);
        Node c = t.addNode(-0.05, 0.03, -0.17, 1.9);
        Node d = t.addNode(0.3, 0, 0, 0.2);
        Node e = t.addNode(0.32, 0.05, -0.04, 0.5);
        t.addRigidLink(top, a);
        if (triangle) {
            t.addRigidLink(a, b);
        }
        t.addRigidLink(b, c);
        if (triangle) {
            t.addRigidLink(c, a);
        }
        t.addRigidLink(d, e);
        return SystemState.compile(t);
    }

    /** Compact layout: the fixed node 0 has no slot, free nodes 1..5 at slots 0..4. */
    static LinkTangent tangent(SystemState s) {
        LinkTangent lt = new LinkTangent(s, new int[] {-1, 0, 1, 2, 3, 4}, 5);
        lt.linearise(s.x, 0.01);
        return lt;
    }

    /** Compact (15 values) to full (18 values, node 0 first). */
    static double[] full(double[] compact) {
        double[] out = new double[compact.length + 3];
        System.arraycopy(compact, 0, out, 3, compact.length);
        return out;
    }

    static double[] random(Random r, int n) {
        double[] u = new double[n];
        for (int k = 0; k < n; k++) {
            u[k] = r.nextGaussian();
        }
        return u;
    }

    /** The constraints' values (v_b - v_a) . n of compact u at the scene's positions. */
    static double[] rates(SystemState s, double[] u) {
        return rates(s, s.x, u);
    }

    /** The constraints' values (v_b - v_a) . n of compact u at positions x, free nodes 1..5 at compact 0..4. */
    static double[] rates(SystemState s, double[] x, double[] u) {
        double[] out = new double[s.linkCount()];
        for (int i = 0; i < s.linkCount(); i++) {
            int a = s.linkA[i];
            int b = s.linkB[i];
            double[] n = new double[3];
            double len = 0;
            for (int c = 0; c < 3; c++) {
                n[c] = x[3 * b + c] - x[3 * a + c];
                len += n[c] * n[c];
            }
            len = Math.sqrt(len);
            for (int c = 0; c < 3; c++) {
                double vb = b == 0 ? 0 : u[3 * (b - 1) + c];
                double va = a == 0 ? 0 : u[3 * (a - 1) + c];
                out[i] += (vb - va) * n[c] / len;
            }
        }
        return out;
    }

    static double mDot(SystemState s, double[] u, double[] w) {
        double sum = 0;
        for (int k = 0; k < u.length; k++) {
            sum += s.mass[1 + k / 3] * u[k] * w[k];
        }
        return sum;
    }

    @Test
    void isTheMassWeightedProjectorForDisjointLinksToo() {
        projectorProperties(disjointScene());
    }

    @Test
    void isTheMassWeightedProjectorOntoTheLinearisedConstraints() {
        projectorProperties(scene());
    }

    private static void projectorProperties(SystemState s) {
        LinkTangent lt = tangent(s);
        Random r = new Random(7);
        for (int trial = 0; trial < 5; trial++) {
            double[] u = random(r, 15);
            double[] w = random(r, 15);
            double[] pu = u.clone();
            double[] pw = w.clone();
            lt.project(pu);
            lt.project(pw);
            for (double rate : rates(s, pu)) {
                assertEquals(0, rate, 1e-12, "P u meets every constraint, the shared ones too");
            }
            double[] ppu = pu.clone();
            lt.project(ppu);
            for (int k = 0; k < u.length; k++) {
                assertEquals(pu[k], ppu[k], 1e-12, "P P = P");
            }
            assertEquals(mDot(s, u, pw), mDot(s, pu, w), 1e-10, "u . M P w = P u . M w");
            double[] dual = w.clone();
            lt.projectDual(dual);
            double lhs = 0;
            double rhs = 0;
            for (int k = 0; k < u.length; k++) {
                lhs += u[k] * dual[k];
                rhs += pu[k] * w[k];
            }
            assertEquals(lhs, rhs, 1e-10, "u . P^T w = P u . w");
        }
    }

    @Test
    void fullLayoutActsAsTheCompactOneAndLeavesTheFixedNodeAlone() {
        SystemState s = scene();
        LinkTangent compact = tangent(s);
        LinkTangent fullLayout = LinkTangent.fullLayout(s);
        fullLayout.linearise(s.x, 0.01);
        Random r = new Random(11);
        double[] u = random(r, 15);
        double[] uf = full(u);
        uf[0] = 3;
        uf[1] = -2;
        uf[2] = 5; // the fixed node's slot: P is the identity there
        compact.project(u);
        fullLayout.project(uf);
        double[] w = random(r, 15);
        double[] wf = full(w);
        wf[1] = 7;
        compact.projectDual(w);
        fullLayout.projectDual(wf);
        assertEquals(3, uf[0], 0);
        assertEquals(-2, uf[1], 0);
        assertEquals(5, uf[2], 0);
        assertEquals(7, wf[1], 0);
        for (int k = 0; k < 15; k++) {
            assertEquals(u[k], uf[k + 3], 1e-14, "P u, component " + k);
            assertEquals(w[k], wf[k + 3], 1e-12, "P^T w, component " + k);
        }
    }

    @Test
    void constrainedIncrementMeetsTheTargetsAndKeepsTheTangentialPart() {
        SystemState s = scene();
        double beta = 0.01;
        double[] x = s.x.clone();
        x[3 * 2] += 0.004; // links a-b, b-c and the fixed one stretched or shortened: nonzero targets
        x[3 * 4 + 2] -= 0.003;
        x[3 * 5 + 1] += 0.002;
        LinkTangent lt = tangent(s);
        lt.linearise(x, beta);
        Random r = new Random(3);
        double[] u = random(r, 15);
        double[] cu = u.clone();
        lt.constrainIncrement(cu);
        double[] rate = rates(s, x, cu);
        for (int i = 0; i < s.linkCount(); i++) {
            int a = 3 * s.linkA[i];
            int b = 3 * s.linkB[i];
            double len = Math.sqrt(Math.pow(x[b] - x[a], 2) + Math.pow(x[b + 1] - x[a + 1], 2)
                    + Math.pow(x[b + 2] - x[a + 2], 2));
            assertEquals((s.linkL[i] - len) / beta, rate[i], 1e-10, "link " + i + " reaches its length to first order");
        }
        double[] pu = u.clone();
        double[] pcu = cu.clone();
        lt.project(pu);
        lt.project(pcu);
        double[] v = new double[18];
        lt.constrain(v);
        for (int k = 0; k < 15; k++) {
            assertEquals(pu[k], pcu[k], 1e-12, "tangential part kept, component " + k);
            assertEquals(cu[k] - pcu[k], v[k + 3], 1e-12, "constrain() shifts by the same normal part");
        }
    }

    @Test
    void rejectsASlotMapOfTheWrongShape() {
        SystemState s = scene();
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> new LinkTangent(s, new int[] {-1, 0, 1}, 5));
        org.junit.jupiter.api.Assertions.assertTrue(e.getMessage().contains("3 slots given for 6 nodes"), e.getMessage());
        e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> new LinkTangent(s, new int[] {-1, 0, 1, 2, 3, 5}, 5));
        org.junit.jupiter.api.Assertions.assertTrue(e.getMessage().contains("node 5 has slot 5"), e.getMessage());
    }
}
