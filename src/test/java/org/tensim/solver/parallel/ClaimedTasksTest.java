package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;
import org.tensim.testsupport.AllocationCounter;

/**
 * {@link WorkerPool#runClaimed}: every task of every job runs exactly once, on whichever thread claims it,
 * jobs interleaved with {@link WorkerPool#run}; a failure is rethrown to the caller; no allocation per job. And
 * {@link WorkerPool#setMeasured}: both forms run every share once.
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

    /**
     * Measured, the pool tries each call site on the caller alone after its first shared call, and runs every
     * share exactly once in either form (the caller runs each worker's share in turn).
     */
    @Test
    void aMeasuredPoolRunsEveryShareOnceInBothForms() {
        try (WorkerPool pool = new WorkerPool(2, "claim-test")) {
            pool.setMeasured(true);
            AtomicIntegerArray claimedRuns = new AtomicIntegerArray(5);
            int[] shares = new int[2];
            WorkerPool.Claimable claimedBody = claimedRuns::incrementAndGet;
            WorkerPool.Task task = w -> shares[w]++;
            int calls = 2000;
            for (int i = 0; i < calls; i++) {
                pool.runClaimed(5, claimedBody);
                pool.run(task);
            }
            assertEquals(2 * calls, pool.measuredCalls());
            assertTrue(pool.callerCalls() >= 2, "each site tried on the caller: " + pool.callerCalls());
            for (int k = 0; k < 5; k++) {
                assertEquals(calls, claimedRuns.get(k), "task " + k);
            }
            assertEquals(calls, shares[0]);
            assertEquals(calls, shares[1]);
        }
    }

    @Test
    void aJobAllocatesNothing() {
        try (WorkerPool pool = new WorkerPool(2, "claim-test")) {
            pool.setMeasured(true);
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
