package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.Parallelism;

/**
 * The BDF2 step allocates nothing after the first step (which factors): the per-thread allocation
 * counters of the stepping thread and of the pool's workers do not move over many steps.
 */
class PrefactoredAllocationTest {
    @ParameterizedTest(name = "{0} thread(s)")
    @ValueSource(ints = {1, 2})
    void bdf2StepWithLinksAllocatesNothing(int threads) {
        java.lang.management.ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(bean instanceof com.sun.management.ThreadMXBean, "no allocation counters");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) bean;
        Assumptions.assumeTrue(mx.isThreadAllocatedMemorySupported(), "no allocation counters");
        mx.setThreadAllocatedMemoryEnabled(true);

        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(6, 0.1, 1, 1000, 0.5, true)),
                new PrefactoredBdf2());
        try (Parallelism p = threads > 1 ? Parallelism.install(sim, threads) : null) {
            long[] workers = p == null ? new long[0] : p.pool().workerThreadIds();
            long[] ids = new long[workers.length + 1];
            ids[0] = Thread.currentThread().getId();
            System.arraycopy(workers, 0, ids, 1, workers.length);
            for (int i = 0; i < 2000; i++) {
                sim.step(0.01);
            }
            long bytes = 0;
            for (int attempt = 0; attempt < 2; attempt++) {
                long before = 0;
                for (long id : ids) {
                    before += mx.getThreadAllocatedBytes(id);
                }
                for (int i = 0; i < 300; i++) {
                    sim.step(0.01);
                }
                long after = 0;
                for (long id : ids) {
                    after += mx.getThreadAllocatedBytes(id);
                }
                bytes = after - before;
                if (bytes == 0) {
                    break;
                }
            }
            assertEquals(0, bytes, "bytes allocated by 300 steps");
        }
    }
}
