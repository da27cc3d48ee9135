package org.tensim.solver.parallel;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * A fixed team of persistent threads that run one {@link Task} together and wait
 * for each other at its end (a fork-join barrier), without allocating per run.
 *
 * <p>Worker 0 is the calling thread; workers 1..size-1 are daemon threads started
 * once. A worker spins briefly ({@link Thread#onSpinWait()}) for the next task, then
 * parks, so that idle pools cost no CPU on a machine shared with other work while
 * back-to-back passes of a step (RK2's two force passes) do not pay the wake-up
 * latency of parking. The caller spins then yields while it waits for the others.
 *
 * <p>Why not an {@code ExecutorService}: submitting a task allocates a future and
 * a queue node per call, which the allocation-free step forbids, and a pool's
 * wake-up through a blocking queue costs tens of microseconds per pass.
 */
public final class WorkerPool implements AutoCloseable {
    /** Work shared by the team; {@code run(w)} is called once per worker w in [0, size). */
    @FunctionalInterface
    public interface Task {
        void run(int worker);
    }

    /** Independent tasks of {@link #runClaimed}: {@code run(k)} does task k, whichever thread calls it. */
    @FunctionalInterface
    public interface Claimable {
        void run(int task);
    }

    /** Spins of {@link Thread#onSpinWait()} before a worker parks (tens of microseconds). */
    private static final int SPINS_BEFORE_PARK = 1 << 12;
    /** Spins of the caller before it starts yielding its core while waiting. */
    private static final int SPINS_BEFORE_YIELD = 1 << 10;

    private final int size;
    private final Thread[] threads;
    private final Slot[] slots;
    private volatile Task task;
    private volatile int epoch;
    private volatile boolean closed;
    private volatile Throwable failure;
    /**
     * The claimed job: its number (bits 32-63), its task count (bits 16-31) and the next task to claim (bits
     * 0-15), in one word so that a claim (a compare-and-set) succeeds only on the job it read.
     */
    private final AtomicLong claim = new AtomicLong();
    /** Tasks of the claimed job finished. */
    private final AtomicInteger finished = new AtomicInteger();
    private volatile Claimable claimed;
    private int claimJobs;

    /** Per-worker state, padded so that two workers' flags never share a cache line. */
    private static final class Slot {
        @SuppressWarnings("unused")
        long p0, p1, p2, p3, p4, p5, p6;
        volatile int done;
        volatile boolean parked;
        @SuppressWarnings("unused")
        long q0, q1, q2, q3, q4, q5, q6;
    }

    /**
     * Starts {@code size - 1} worker threads (none for size 1).
     *
     * @param size number of workers including the caller, >= 1
     * @param name prefix of the worker threads' names
     */
    public WorkerPool(int size, String name) {
        if (size < 1) {
            throw new IllegalArgumentException("thread count must be >= 1, got " + size);
        }
        this.size = size;
        this.slots = new Slot[size];
        this.threads = new Thread[size];
        threads[0] = null; // the caller
        for (int w = 0; w < size; w++) {
            slots[w] = new Slot();
        }
        for (int w = 1; w < size; w++) {
            final int id = w;
            Thread t = new Thread(() -> loop(id), name + "-" + w);
            t.setDaemon(true);
            threads[w] = t;
            t.start();
        }
    }

    /** Number of workers, the caller included. */
    public int size() {
        return size;
    }

    /** Thread ids of the workers other than the caller (for allocation counters in tests). */
    public long[] workerThreadIds() {
        long[] ids = new long[size - 1];
        for (int w = 1; w < size; w++) {
            ids[w - 1] = threads[w].getId();
        }
        return ids;
    }

    /**
     * Runs {@code t.run(w)} on every worker w and returns when all have finished.
     * Writes made by the workers are visible to the caller on return, and the
     * caller's writes before the call are visible to the workers.
     *
     * @throws IllegalStateException after {@link #close()}
     * @throws RuntimeException      or Error: the first failure of a worker, rethrown
     */
    public void run(Task t) {
        if (closed) {
            throw new IllegalStateException("worker pool is closed");
        }
        if (size == 1) {
            t.run(0);
            return;
        }
        task = t;
        final int e = epoch + 1;
        epoch = e; // volatile write: publishes the task and everything written before
        for (int w = 1; w < size; w++) {
            if (slots[w].parked) {
                LockSupport.unpark(threads[w]);
            }
        }
        Throwable own = null;
        try {
            t.run(0);
        } catch (Throwable ex) {
            own = ex;
        }
        for (int w = 1; w < size; w++) {
            final Slot s = slots[w];
            int spins = 0;
            while (s.done != e) {
                if (++spins < SPINS_BEFORE_YIELD) {
                    Thread.onSpinWait();
                } else {
                    Thread.yield();
                }
            }
        }
        rethrow(own);
    }

    /**
     * Runs the tasks {@code [0, tasks)} on whichever workers come first, the caller included, and returns when
     * all are done. Unlike {@link #run}, the caller does not wait for a worker that has not started (its core
     * taken by another process): it claims the tasks that are left itself, and waits only for tasks that
     * another worker has claimed. Tasks must be independent (they write disjoint data), so that who runs which
     * does not change the result. Visibility as {@link #run}.
     *
     * @param tasks number of tasks, in [0, 65535]
     */
    public void runClaimed(int tasks, Claimable body) {
        if (closed) {
            throw new IllegalStateException("worker pool is closed");
        }
        if (tasks < 0 || tasks > 0xFFFF) {
            throw new IllegalArgumentException("tasks must be in [0, 65535], got " + tasks);
        }
        if (size == 1 || tasks < 2) {
            for (int k = 0; k < tasks; k++) {
                body.run(k);
            }
            return;
        }
        claimed = body;
        finished.set(0);
        final long job = (long) (++claimJobs & 0x7FFFFFFF) << 32;
        claim.set(job | (long) tasks << 16); // volatile write: publishes the job and everything written before
        for (int w = 1; w < size; w++) {
            if (slots[w].parked) {
                LockSupport.unpark(threads[w]);
            }
        }
        Throwable own = null;
        try {
            claimTasks(job);
        } catch (Throwable ex) {
            own = ex;
        }
        int spins = 0;
        while (finished.get() != tasks) {
            if (++spins < SPINS_BEFORE_YIELD) {
                Thread.onSpinWait();
            } else {
                Thread.yield();
            }
        }
        claimed = null;
        rethrow(own);
    }

    /** Throws the caller's own failure, else the first worker's (and clears it), if any. */
    private void rethrow(Throwable own) {
        Throwable f = own != null ? own : failure;
        if (f == null) {
            return;
        }
        failure = null;
        if (f instanceof RuntimeException) {
            throw (RuntimeException) f;
        }
        if (f instanceof Error) {
            throw (Error) f;
        }
        throw new IllegalStateException(f);
    }

    /**
     * Claims and runs tasks of the job {@code job} (its number in the high bits) until none is left. A claim
     * that succeeds is on that job, which cannot end before the claimed task is finished: the body read after
     * it is the job's.
     */
    private void claimTasks(long job) {
        while (true) {
            final long c = claim.get();
            final int k = (int) (c & 0xFFFF);
            if ((c & ~0xFFFFFFFFL) != job || k >= (int) ((c >>> 16) & 0xFFFF)) {
                return;
            }
            if (claim.compareAndSet(c, c + 1)) {
                try {
                    claimed.run(k);
                } catch (Throwable ex) {
                    failure = ex;
                } finally {
                    finished.incrementAndGet();
                }
            }
        }
    }

    private void loop(int w) {
        final Slot s = slots[w];
        int seen = 0;
        long seenJob = 0;
        while (true) {
            int spins = 0;
            while (epoch == seen && (claim.get() & ~0xFFFFFFFFL) == seenJob) {
                if (closed) {
                    return;
                }
                if (++spins < SPINS_BEFORE_PARK) {
                    Thread.onSpinWait();
                } else {
                    // Dekker-style handshake with run() and runClaimed(): parked is written before epoch and
                    // claim are re-read, and they write epoch or claim before they read parked.
                    s.parked = true;
                    if (epoch == seen && (claim.get() & ~0xFFFFFFFFL) == seenJob && !closed) {
                        LockSupport.park(this);
                    }
                    s.parked = false;
                }
            }
            final long job = claim.get() & ~0xFFFFFFFFL;
            if (job != seenJob) {
                seenJob = job;
                claimTasks(job);
            }
            if (epoch == seen) {
                continue;
            }
            seen = epoch;
            try {
                task.run(w);
            } catch (Throwable ex) {
                failure = ex;
            }
            s.done = seen;
        }
    }

    /** Stops the worker threads (idempotent). The pool cannot run tasks afterwards. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        for (int w = 1; w < size; w++) {
            LockSupport.unpark(threads[w]);
        }
        for (int w = 1; w < size; w++) {
            try {
                threads[w].join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }
}
