package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.ShuffledScene;
import org.tensim.solver.ForceModel;
import org.tensim.solver.SystemState;

/**
 * The parallel spring pass: identical bits for every thread count, and the same
 * forces as the built-in loop (bit for bit on the lattice, whose sorted spring order
 * is the authored one; within 1e-12 of the largest force elsewhere, the summation
 * order at a node being different).
 */
class ParallelSpringPassTest {
    static final double RELATIVE_TOLERANCE = 1e-12;

    static SystemState perturbed(Topology t, long seed) {
        SystemState s = SystemState.compile(t);
        Random rnd = new Random(seed);
        for (int k = 0; k < s.x.length; k++) {
            s.x[k] += 0.01 * rnd.nextGaussian();
            s.v[k] = 0.5 * rnd.nextGaussian();
        }
        return s;
    }

    static double[] builtIn(SystemState s) {
        double[] f = new double[s.x.length];
        new ForceModel(s).computeForces(0.3, s.x, s.v, f);
        return f;
    }

    static double[] parallel(SystemState s, int threads, ParallelSpringPass.Order order) {
        try (WorkerPool pool = new WorkerPool(threads, "test")) {
            ForceModel fm = new ForceModel(s);
            fm.setSpringPass(new ParallelSpringPass(s, pool, order, 1)); // split however small
            double[] f = new double[s.x.length];
            fm.computeForces(0.3, s.x, s.v, f);
            // A second pass into the same array must give the same result (buffers reset).
            double[] g = new double[s.x.length];
            fm.computeForces(0.3, s.x, s.v, g);
            assertArrayEquals(f, g);
            return f;
        }
    }

    static void assertClose(double[] expected, double[] actual) {
        double scale = 0;
        for (double e : expected) {
            scale = Math.max(scale, Math.abs(e));
        }
        for (int k = 0; k < expected.length; k++) {
            if (Math.abs(expected[k] - actual[k]) > RELATIVE_TOLERANCE * scale) {
                throw new AssertionError("component " + k + ": " + expected[k] + " vs " + actual[k]);
            }
        }
    }

    @Test
    void latticeForcesAreBitIdenticalToTheBuiltInLoopForAnyThreadCount() {
        for (double damping : new double[] {0, 3}) {
            SystemState s = perturbed(LatticeScene.build(7, 0.1, 1, 1000, damping, false), 1);
            double[] reference = builtIn(s);
            for (int t = 1; t <= 5; t++) {
                assertArrayEquals(reference, parallel(s, t, ParallelSpringPass.Order.AUTHORED),
                        "threads " + t + ", damping " + damping);
            }
        }
    }

    @Test
    void shuffledMeshIsReorderedAndGivesTheSameBitsForAnyThreadCount() {
        for (double damping : new double[] {0, 3}) {
            Topology t = ShuffledScene.shuffle(LatticeScene.build(7, 0.1, 1, 1000, damping, false), 42);
            SystemState s = perturbed(t, 2);
            double[] reference = builtIn(s);
            double[] one = parallel(s, 1, ParallelSpringPass.Order.AUTO);
            assertClose(reference, one);
            for (int th = 2; th <= 5; th++) {
                assertArrayEquals(one, parallel(s, th, ParallelSpringPass.Order.AUTO), "threads " + th);
            }
            for (ParallelSpringPass.Order o : ParallelSpringPass.Order.values()) {
                assertClose(reference, parallel(s, 3, o));
            }
        }
    }

    @Test
    void autoOrderPermutesOnlyWhenItShortensTheSprings() {
        SystemState lattice = SystemState.compile(LatticeScene.build(9, 0.1, 1, 1000, 0, false));
        SystemState shuffled = SystemState.compile(
                ShuffledScene.shuffle(LatticeScene.build(9, 0.1, 1, 1000, 0, false), 5));
        try (WorkerPool pool = new WorkerPool(2, "test")) {
            ParallelSpringPass a = new ParallelSpringPass(lattice, pool, ParallelSpringPass.Order.AUTO);
            assertFalse(a.permuted(), "the lattice is already in a local order");
            ParallelSpringPass b = new ParallelSpringPass(shuffled, pool, ParallelSpringPass.Order.AUTO);
            assertTrue(b.permuted());
            assertTrue(b.internalSpan() * ParallelSpringPass.AUTO_GAIN < b.authoredSpan(),
                    b.authoredSpan() + " -> " + b.internalSpan());
        }
    }

    @Test
    void stiffnessChangedThroughTheStateIsSeenByThePass() {
        SystemState s = perturbed(LatticeScene.build(5, 0.1, 1, 1000, 0, false), 3);
        try (WorkerPool pool = new WorkerPool(2, "test")) {
            ForceModel fm = new ForceModel(s);
            fm.setSpringPass(new ParallelSpringPass(s, pool, ParallelSpringPass.Order.RCM, 1));
            double[] f = new double[s.x.length];
            fm.computeForces(0, s.x, s.v, f);
            s.setSpringStiffness(10, 5000);
            s.setSpringDamping(11, 2);
            fm.computeForces(0, s.x, s.v, f);
            assertClose(builtIn(s), f);
        }
    }

    @Test
    void moreThreadsThanNodesStillWork() {
        SystemState s = perturbed(LatticeScene.build(2, 0.1, 1, 1000, 0, false), 4);
        assertArrayEquals(builtIn(s), parallel(s, 11, ParallelSpringPass.Order.AUTHORED));
    }
}
