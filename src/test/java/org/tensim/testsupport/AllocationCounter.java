package org.tensim.testsupport;

import java.lang.management.ManagementFactory;

/**
 * The bytes that some threads allocate, from the JVM's per-thread allocation counters
 * ({@code com.sun.management.ThreadMXBean}), for the tests that a hot loop allocates nothing.
 * A JVM without the counters fails the test (it is not skipped): every JDK the project supports
 * (HotSpot, OpenJDK 17 and later) has them.
 */
public final class AllocationCounter {
    private final com.sun.management.ThreadMXBean mx;
    private final long[] threads;

    private AllocationCounter(long[] threads) {
        java.lang.management.ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        if (!(bean instanceof com.sun.management.ThreadMXBean)
                || !((com.sun.management.ThreadMXBean) bean).isThreadAllocatedMemorySupported()) {
            throw new IllegalStateException("this JVM has no per-thread allocation counters"
                    + " (com.sun.management.ThreadMXBean): run the tests on an OpenJDK (HotSpot) 17 or later");
        }
        mx = (com.sun.management.ThreadMXBean) bean;
        mx.setThreadAllocatedMemoryEnabled(true);
        this.threads = threads;
    }

    /** Counts the calling thread's allocations. */
    public static AllocationCounter currentThread() {
        return new AllocationCounter(new long[] {Thread.currentThread().getId()});
    }

    /** Counts the calling thread's allocations and those of {@code others} (thread ids, e.g. a pool's workers). */
    public static AllocationCounter currentThreadAnd(long... others) {
        long[] ids = new long[others.length + 1];
        ids[0] = Thread.currentThread().getId();
        System.arraycopy(others, 0, ids, 1, others.length);
        return new AllocationCounter(ids);
    }

    /** Bytes allocated so far by the counted threads. */
    public long bytes() {
        long sum = 0;
        for (long id : threads) {
            sum += mx.getThreadAllocatedBytes(id);
        }
        return sum;
    }

    /**
     * Bytes that the counted threads allocate while {@code work} runs, measured up to {@code attempts}
     * times until a measure is 0: a stray allocation of the JIT's last compilations is measured again.
     */
    public long bytesAllocatedBy(Runnable work, int attempts) {
        long bytes = 0;
        for (int attempt = 0; attempt < attempts; attempt++) {
            long before = bytes();
            work.run();
            bytes = bytes() - before;
            if (bytes == 0) {
                break;
            }
        }
        return bytes;
    }
}
