package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.testsupport.AllocationCounter;

/**
 * No allocation in the step: the JVM's per-thread allocation counters of the
 * stepping thread and of the pool's workers do not move over many steps (after a
 * warm-up that lets the JIT compile the step, as in a real run).
 */
class StepAllocationTest {
    @Test
    void parallelStepWithLinksAllocatesNothing() {
        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(8, 0.1, 1, 1000, 0.5, true)));
        try (Parallelism p = Parallelism.install(sim, 2, ParallelSpringPass.Order.AUTO, 1)) {
            AllocationCounter counter = AllocationCounter.currentThreadAnd(p.pool().workerThreadIds());
            for (int i = 0; i < 4000; i++) {
                sim.step(1e-4);
            }
            // Measured twice: a stray allocation from the JIT's last compilations is retried once.
            long bytes = counter.bytesAllocatedBy(() -> {
                for (int i = 0; i < 500; i++) {
                    sim.step(1e-4);
                }
            }, 2);
            assertEquals(0, bytes, "bytes allocated by 500 steps");
        }
    }
}
