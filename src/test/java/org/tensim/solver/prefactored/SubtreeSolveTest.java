package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.parallel.PooledNodeLoops;
import org.tensim.solver.parallel.WorkerPool;
import org.tensim.testsupport.AllocationCounter;

/**
 * The two-thread solves ({@link SubtreeSolve}) give the one-thread solves' bits, whoever runs which group
 * and in which order, on matrices whose factors pair columns (a shell-like grid of node pairs) and whose
 * elimination forest has several trees (disconnected blocks); and they allocate nothing.
 */
class SubtreeSolveTest {
    /** Runs the tasks on the calling thread, the last first: the groups must not depend on each other. */
    private static final NodeLoops REVERSED = new NodeLoops() {
        @Override
        public void run(int nodes, Body body) {
            body.run(0, nodes);
        }

        @Override
        public void runTasks(int tasks, Body body) {
            for (int t = tasks - 1; t >= 0; t--) {
                body.run(t, t + 1);
            }
        }

        @Override
        public int threads() {
            return 2;
        }
    };

    /**
     * A shell-like matrix (a grid of node pairs, each coupled to its twin, its grid neighbours and their
     * twins, random weights, a mass term), {@code copies} disconnected copies of it.
     */
    private static SparseCholesky shell(int side, int copies, long seed) {
        int per = 2 * side * side;
        int n = per * copies;
        List<double[]> entries = new ArrayList<>();
        Random r = new Random(seed);
        double[] diagonal = new double[n];
        for (int copy = 0; copy < copies; copy++) {
            int base = copy * per;
            for (int i = 0; i < side; i++) {
                for (int j = 0; j < side; j++) {
                    int a = base + 2 * (i * side + j);
                    couple(entries, diagonal, r, a, a + 1);
                    if (i + 1 < side) {
                        int b = a + 2 * side;
                        couple(entries, diagonal, r, a, b);
                        couple(entries, diagonal, r, a + 1, b + 1);
                        couple(entries, diagonal, r, a, b + 1);
                    }
                    if (j + 1 < side) {
                        couple(entries, diagonal, r, a, a + 2);
                        couple(entries, diagonal, r, a + 1, a + 3);
                        couple(entries, diagonal, r, a + 1, a + 2);
                    }
                }
            }
        }
        int count = entries.size() + n;
        int[] rows = new int[count];
        int[] cols = new int[count];
        double[] vals = new double[count];
        for (int k = 0; k < entries.size(); k++) {
            rows[k] = (int) entries.get(k)[0];
            cols[k] = (int) entries.get(k)[1];
            vals[k] = entries.get(k)[2];
        }
        for (int i = 0; i < n; i++) {
            rows[entries.size() + i] = i;
            cols[entries.size() + i] = i;
            vals[entries.size() + i] = diagonal[i] + 0.01 * (1 + r.nextDouble());
        }
        return SparseCholesky.factor(SparseCholesky.analyse(n, rows, cols, vals, count), rows, cols, vals, count,
                "the shell-like test matrix");
    }

    private static void couple(List<double[]> entries, double[] diagonal, Random r, int i, int j) {
        double w = 1 + r.nextDouble();
        entries.add(new double[] {i, j, -w});
        entries.add(new double[] {j, i, -w});
        diagonal[i] += w;
        diagonal[j] += w;
    }

    private static double[] gaussian(int n, long seed) {
        Random r = new Random(seed);
        double[] b = new double[n];
        for (int k = 0; k < n; k++) {
            b[k] = r.nextGaussian();
        }
        return b;
    }

    private static void assertSameBits(SparseCholesky ch) {
        int n = ch.size();
        double[] b = gaussian(3 * n, 5);
        double[] serial = b.clone();
        ch.solve3(serial, new double[3 * n]);
        double[] reversed = b.clone();
        ch.solve3(reversed, new double[3 * n], REVERSED);
        assertArrayEquals(serial, reversed, "groups solved the last first, on one thread");
        try (WorkerPool pool = new WorkerPool(2, "subtree-test")) {
            PooledNodeLoops loops = new PooledNodeLoops(pool, 1);
            for (int round = 0; round < 5; round++) {
                double[] two = b.clone();
                ch.solve3(two, new double[3 * n], loops);
                assertArrayEquals(serial, two, "two threads, round " + round);
            }
        }
    }

    @Test
    void twoThreadsGiveTheSerialSolvesBits() {
        SparseCholesky ch = shell(60, 1, 3);
        SubtreeSolve split = ch.split();
        assertNotNull(split, ch.factorNonZeros() + " entries");
        int[] groups = split.groupEntries();
        assertEquals(split.entries(), groups[0] + groups[1] + split.topEntries() + split.cutEntries(),
                "every entry of L in a group, the top or the cut");
        assertTrue(groups[0] > 0 && groups[1] > 0, "two groups of work: " + groups[0] + ", " + groups[1]);
        assertTrue(split.topEntries() + split.cutEntries() < split.entries() / 2,
                "a small top: " + split.topEntries() + " + " + split.cutEntries() + " of " + split.entries());
        assertSameBits(ch);
    }

    @Test
    void aForestOfSeveralTreesSplitsByTrees() {
        SparseCholesky ch = shell(25, 3, 7);
        assertNotNull(ch.split());
        assertSameBits(ch);
    }

    @Test
    void aSmallFactorKeepsTheSerialSolve() {
        SparseCholesky ch = shell(6, 1, 1);
        assertTrue(ch.factorNonZeros() < SparseCholesky.MIN_SPLIT_ENTRIES);
        assertNull(ch.split());
        double[] b = gaussian(3 * ch.size(), 2);
        double[] serial = b.clone();
        ch.solve3(serial, new double[b.length]);
        ch.solve3(b, new double[b.length], REVERSED);
        assertArrayEquals(serial, b);
    }

    @Test
    void twoThreadSolvesAllocateNothing() {
        SparseCholesky ch = shell(40, 1, 9);
        int n = ch.size();
        double[] b = gaussian(3 * n, 4);
        double[] work = new double[3 * n];
        try (WorkerPool pool = new WorkerPool(2, "subtree-test")) {
            PooledNodeLoops loops = new PooledNodeLoops(pool, 1);
            for (int i = 0; i < 2000; i++) {
                ch.solve3(b, work, loops);
            }
            AllocationCounter counter = AllocationCounter.currentThreadAnd(pool.workerThreadIds());
            long bytes = counter.bytesAllocatedBy(() -> {
                for (int i = 0; i < 200; i++) {
                    ch.solve3(b, work, loops);
                }
            }, 2);
            assertEquals(0, bytes, "bytes allocated by 200 solves");
        }
    }
}
