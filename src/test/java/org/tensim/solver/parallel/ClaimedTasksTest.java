package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;
import org.tensim.testsupport.AllocationCounter;

/**
 * {@link WorkerPool#runClaimed}: every task of every job runs exactly once, on whichever thread claims it,
 * jobs interleaved with {@link WorkerPool#run}; a failure is rethrown to the caller; no allocation per job.
 */
class ClaimedTasksTest {
    @Test
    void everyTaskRunsOnceInManyJobsMixedWithRuns() {
        int jobs = 20_000;
        try (WorkerPool pool = new WorkerPool(2, "claim-test")) {
            AtomicIntegerArray runs = new AtomicIntegerArray(16);
            int[] perWorker = new int[2];
            for (int j = 0; j < jobs; j++) {
                int tasks = 2 + j % 15;
                pool.runClaimed(tasks, runs::incrementAndGet);
                if (j % 7 == 0) {
                    pool.run(w -> perWorker[w]++);
                }
            }
            int expected = 0;
            for (int j = 0; j < jobs; j++) {
                expected += 2 + j % 15;
            }
            int total = 0;
            for (int k = 0; k < 16; k++) {
                total += runs.get(k);
            }
            assertEquals(expected, total, "tasks run");
            for (int k = 0; k < 16; k++) {
                int e = 0;
                for (int j = 0; j < jobs; j++) {
                    e += k < 2 + j % 15 ? 1 : 0;
                }
                assertEquals(e, runs.get(k), "runs of task " + k);
            }
            assertEquals((jobs + 6) / 7, perWorker[0]);
            assertEquals((jobs + 6) / 7, perWorker[1]);
        }
    }

    @Test
    void aFailingTaskIsRethrownAndThePoolGoesOn() {
        try (WorkerPool pool = new WorkerPool(2, "claim-test")) {
            for (int round = 0; round < 50; round++) {
                assertThrows(IllegalStateException.class, () -> pool.runClaimed(4, k -> {
                    if (k == 3) {
                        throw new IllegalStateException("task 3");
                    }
                }));
            }
            AtomicIntegerArray runs = new AtomicIntegerArray(4);
            pool.runClaimed(4, runs::incrementAndGet);
            for (int k = 0; k < 4; k++) {
                assertEquals(1, runs.get(k));
            }
        }
    }

    @Test
    void aJobAllocatesNothing() {
        try (WorkerPool pool = new WorkerPool(2, "claim-test")) {
            double[] out = new double[8];
            WorkerPool.Claimable body = k -> out[k] += k;
            for (int i = 0; i < 20_000; i++) {
                pool.runClaimed(8, body);
            }
            AllocationCounter counter = AllocationCounter.currentThreadAnd(pool.workerThreadIds());
            long bytes = counter.bytesAllocatedBy(() -> {
                for (int i = 0; i < 2000; i++) {
                    pool.runClaimed(8, body);
                }
            }, 2);
            assertEquals(0, bytes, "bytes allocated by 2000 jobs");
        }
    }
}
