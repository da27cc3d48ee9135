package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.ShuffledScene;
import org.tensim.solver.RigidLinkProjection;
import org.tensim.solver.SystemState;

/** Link colouring and the coloured, parallel Gauss-Seidel projection. */
class ParallelLinkSweepsTest {
    /** A lattice with rigid body diagonals, some links made to share nodes by extra cross links. */
    static SystemState linked(int n, long seed) {
        Topology t = ShuffledScene.shuffle(LatticeScene.build(n, 0.1, 1, 1000, 0, true), seed);
        return SystemState.compile(t);
    }

    static double[] perturbed(SystemState s, long seed) {
        Random rnd = new Random(seed);
        double[] x = s.x.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.005 * rnd.nextGaussian();
        }
        return x;
    }

    @Test
    void noTwoLinksOfOneColourShareANode() {
        for (SystemState s : new SystemState[] {linked(6, 1),
            SystemState.compile(CubeScene.tensegrity(CubeParameters.paper()).topology)}) {
            LinkColoring c = LinkColoring.greedy(s.nodeCount, s.linkA, s.linkB);
            int[][] seen = new int[c.colours()][s.nodeCount];
            for (int i = 0; i < s.linkCount(); i++) {
                int col = c.colour(i);
                assertEquals(0, seen[col][s.linkA[i]]++, "node " + s.linkA[i] + " twice in colour " + col);
                assertEquals(0, seen[col][s.linkB[i]]++, "node " + s.linkB[i] + " twice in colour " + col);
            }
            assertTrue(c.colours() >= 1 && c.colours() <= 8, "colours: " + c.colours());
        }
    }

    @Test
    void projectionGivesTheSameBitsForAnyThreadCountAndMeetsTheTolerance() {
        SystemState s = linked(9, 2); // 512 links: enough to be split when the threshold allows
        double[] start = perturbed(s, 3);
        double[] reference = null;
        for (int t = 1; t <= 4; t++) {
            try (WorkerPool pool = new WorkerPool(t, "test")) {
                RigidLinkProjection p = new RigidLinkProjection();
                p.setSweeps(new ParallelLinkSweeps(s, pool, 1)); // split every colour, however small
                double[] x = start.clone();
                assertTrue(p.project(s, x, RigidLinkProjection.DEFAULT_TOLERANCE, 10000), "converged with " + t + " threads");
                assertTrue(p.maxRelativeError() <= RigidLinkProjection.DEFAULT_TOLERANCE);
                if (reference == null) {
                    reference = x;
                } else {
                    assertArrayEquals(reference, x, "threads " + t);
                }
            }
        }
        assertNotEquals(0, s.linkCount());
    }

    /** The linked lattice with no fixed node, so that every correction is between free nodes. */
    static SystemState free(int n) {
        Topology lat = LatticeScene.build(n, 0.1, 1, 1000, 0, true);
        Topology t = new Topology();
        for (org.tensim.model.Node node : lat.nodes()) {
            t.addNode(node.position(), 1 + 0.1 * (node.id() % 7));
        }
        for (org.tensim.model.RigidLink l : lat.rigidLinks()) {
            t.addRigidLink(l.a(), l.b(), l.length());
        }
        return SystemState.compile(t);
    }

    @Test
    void projectionConservesMomentumAndKeepsFixedNodes() {
        SystemState s = free(7);
        double[] x = perturbed(s, 5);
        double[] before = x.clone();
        try (WorkerPool pool = new WorkerPool(2, "test")) {
            RigidLinkProjection p = new RigidLinkProjection();
            p.setSweeps(new ParallelLinkSweeps(s, pool, 1));
            assertTrue(p.project(s, x, RigidLinkProjection.DEFAULT_TOLERANCE, 10000));
        }
        // Mass-weighted corrections cancel: sum m_i (x_i - x_i^0) is unchanged (0 up to rounding).
        for (int k = 0; k < 3; k++) {
            double moved = 0;
            double scale = 0;
            for (int i = 0; i < s.nodeCount; i++) {
                moved += s.mass[i] * (x[3 * i + k] - before[3 * i + k]);
                scale += s.mass[i] * Math.abs(x[3 * i + k] - before[3 * i + k]);
            }
            assertTrue(Math.abs(moved) <= 1e-12 * scale + 1e-15, "axis " + k + ": " + moved + " of " + scale);
        }
        // Fixed nodes: the lattice's bottom face never moves.
        SystemState fixed = linked(6, 8);
        double[] y = perturbed(fixed, 9);
        double[] y0 = y.clone();
        try (WorkerPool pool = new WorkerPool(2, "test")) {
            RigidLinkProjection p = new RigidLinkProjection();
            p.setSweeps(new ParallelLinkSweeps(fixed, pool, 1));
            p.project(fixed, y, RigidLinkProjection.DEFAULT_TOLERANCE, 10000);
        }
        for (int node : fixed.fixedNode) {
            for (int k = 3 * node; k < 3 * node + 3; k++) {
                assertEquals(y0[k], y[k], 0.0, "fixed node " + node + " moved");
            }
        }
    }

    static double fullMeasure(SystemState s, double[] x) {
        double worst = 0;
        for (int i = 0; i < s.linkCount(); i++) {
            int a = 3 * s.linkA[i];
            int b = 3 * s.linkB[i];
            double l = Math.sqrt(Math.pow(x[b] - x[a], 2) + Math.pow(x[b + 1] - x[a + 1], 2)
                    + Math.pow(x[b + 2] - x[a + 2], 2));
            worst = Math.max(worst, Math.abs(l - s.linkL[i]) / s.linkL[i]);
        }
        return worst;
    }

    @Test
    void measureAfterASweepSkipsOnlyLinksThatAreExact() {
        SystemState s = linked(7, 10);
        SystemState tie = free(5);
        for (SystemState st : new SystemState[] {s, tie}) {
            double[] x = perturbed(st, 11);
            try (WorkerPool pool = new WorkerPool(2, "test")) {
                ParallelLinkSweeps w = new ParallelLinkSweeps(st, pool, 1);
                for (int sweep = 0; sweep < 5; sweep++) {
                    w.sweep(st, x);
                    double fast = w.measure(st, x);
                    double full = fullMeasure(st, x);
                    assertTrue(Math.abs(fast - full) <= 1e-14 + 1e-9 * full, fast + " vs " + full);
                }
            }
        }
        // A link between two fixed nodes is never corrected: the measure must still see it,
        // whether it is swept first or last.
        for (boolean immovableFirst : new boolean[] {true, false}) {
            Topology t = new Topology();
            org.tensim.model.Node a = t.addNode(0, 0, 0, 1).fix();
            org.tensim.model.Node b = t.addNode(1, 0, 0, 1).fix();
            org.tensim.model.Node c = t.addNode(2, 0, 0, 1);
            if (!immovableFirst) {
                t.addRigidLink(b.id(), c.id(), 1);
            }
            t.addRigidLink(a.id(), b.id(), 1.5); // wrong length, cannot be fixed
            if (immovableFirst) {
                t.addRigidLink(b.id(), c.id(), 1);
            }
            SystemState st = SystemState.compile(t);
            try (WorkerPool pool = new WorkerPool(2, "test")) {
                ParallelLinkSweeps w = new ParallelLinkSweeps(st, pool, 1);
                double[] x = st.x.clone();
                w.sweep(st, x);
                assertEquals(1 / 3.0, w.measure(st, x), 1e-12);
                assertEquals(immovableFirst ? 0 : 1, w.worstLink());
            }
        }
    }

    @Test
    void worstLinkIsReportedByAuthoredIndex() {
        SystemState s = linked(5, 6);
        double[] x = s.x.clone();
        int victim = 17;
        x[3 * s.linkB[victim] + 1] += 0.05; // stretch one link only (a node of few links)
        try (WorkerPool pool = new WorkerPool(3, "test")) {
            ParallelLinkSweeps w = new ParallelLinkSweeps(s, pool, 1);
            double e = w.measure(s, x);
            assertTrue(e > 0.01);
            int worst = w.worstLink();
            assertTrue(s.linkA[worst] == s.linkB[victim] || s.linkB[worst] == s.linkB[victim],
                    "worst link " + worst + " touches the moved node");
        }
    }
}
