package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * No allocation in the step: the JVM's per-thread allocation counters of the
 * stepping thread and of the pool's workers do not move over many steps (after a
 * warm-up that lets the JIT compile the step, as in a real run).
 */
class StepAllocationTest {
    static long allocated(com.sun.management.ThreadMXBean mx, long[] ids) {
        long sum = 0;
        for (long id : ids) {
            sum += mx.getThreadAllocatedBytes(id);
        }
        return sum;
    }

    @Test
    void parallelStepWithLinksAllocatesNothing() {
        java.lang.management.ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(bean instanceof com.sun.management.ThreadMXBean, "no allocation counters");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) bean;
        Assumptions.assumeTrue(mx.isThreadAllocatedMemorySupported(), "no allocation counters");
        mx.setThreadAllocatedMemoryEnabled(true);

        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(8, 0.1, 1, 1000, 0.5, true)));
        try (Parallelism p = Parallelism.install(sim, 2, ParallelSpringPass.Order.AUTO, 1)) {
            long[] workers = p.pool().workerThreadIds();
            long[] ids = new long[workers.length + 1];
            ids[0] = Thread.currentThread().getId();
            System.arraycopy(workers, 0, ids, 1, workers.length);
            for (int i = 0; i < 4000; i++) {
                sim.step(1e-4);
            }
            // Measure twice: a stray allocation from the JIT's last compilations is retried once.
            long bytes = 0;
            for (int attempt = 0; attempt < 2; attempt++) {
                long before = allocated(mx, ids);
                for (int i = 0; i < 500; i++) {
                    sim.step(1e-4);
                }
                bytes = allocated(mx, ids) - before;
                if (bytes == 0) {
                    break;
                }
            }
            assertEquals(0, bytes, "bytes allocated by 500 steps");
        }
    }
}
