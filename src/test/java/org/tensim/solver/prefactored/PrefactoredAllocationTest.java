package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.testsupport.AllocationCounter;

/**
 * The BDF2 step allocates nothing after the first step (which factors): the per-thread allocation
 * counters of the stepping thread and of the pool's workers do not move over many steps.
 */
class PrefactoredAllocationTest {
    @ParameterizedTest(name = "{0} thread(s)")
    @ValueSource(ints = {1, 2})
    void bdf2StepWithLinksAllocatesNothing(int threads) {
        assertNoAllocation(new Simulation(SystemState.compile(LatticeScene.build(6, 0.1, 1, 1000, 0.5, true)),
                new PrefactoredBdf2()), threads, 0.01, 2000);
    }

    /** Membrane triangles (their slabs dispatched on 2 threads), fibres, links and driven nodes. */
    @ParameterizedTest(name = "{0} thread(s)")
    @ValueSource(ints = {1, 2})
    void bdf2StepOnACoarseDiaphragmAllocatesNothing(int threads) throws Exception {
        Simulation sim = DiaphragmSetup.generated(8, null, DiaphragmParameters.defaults(), new BreathingCycle(4, 2),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa())).scene().newSimulation();
        sim.setIntegrator(new PrefactoredBdf2());
        assertNoAllocation(sim, threads, 0.02, 500);
    }

    /** With the rigid links tied in the preconditioner (the thorax's real-time setting). */
    @Test
    void bdf2StepWithTiedLinksAllocatesNothing() throws Exception {
        Simulation sim = DiaphragmSetup.generated(8, null, DiaphragmParameters.defaults(), new BreathingCycle(4, 2),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa())).scene().newSimulation();
        sim.setIntegrator(new PrefactoredBdf2().setLinkCoupling(PrefactoredBdf2.CONTACT_LINK_COUPLING)
                .setNewtonIterations(2).setKrylovIterations(8));
        assertNoAllocation(sim, 2, 0.025, 300);
    }

    /**
     * A diaphragm large enough for the fibres' and shear elements' products and the solves to be shared among
     * the threads ({@link NodeParts}, {@link SubtreeSolve}).
     */
    @Test
    void bdf2StepWithSharedKernelsAllocatesNothing() throws Exception {
        Simulation sim = DiaphragmSetup.generated(28, null, DiaphragmParameters.defaults(), new BreathingCycle(4, 2),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa())).scene().newSimulation();
        PrefactoredBdf2 bdf2 = new PrefactoredBdf2();
        sim.setIntegrator(bdf2);
        assertTrue(sim.state().fibres.count() + sim.state().shears.count() >= SpringJacobian.MIN_SHARED_ELEMENTS,
                "fibres and shear elements shared");
        assertNoAllocation(sim, 2, 0.025, 200);
        assertTrue(bdf2.factorNonZeros() >= SparseCholesky.MIN_SPLIT_ENTRIES, "solves shared");
    }

    /** With contact pairs among the shared kernels: the 28-ring diaphragm on the swept cage's bones. */
    @Test
    void bdf2StepWithSharedContactKernelsAllocatesNothing() throws Exception {
        org.tensim.scene.diaphragm.DiaphragmSpec d = org.tensim.scene.diaphragm.DiaphragmSpec.defaults();
        org.tensim.scene.diaphragm.DiaphragmSpec spec = d.withMesh(d.mesh().withRings(28))
                .withCage(d.cage().withSurfaces(true));
        Simulation sim = DiaphragmSetup.build(spec).scene().newSimulation();
        assertTrue(sim.state().contacts.count() > 0, "contact pairs");
        sim.setIntegrator(new PrefactoredBdf2().setKernelSharing(KernelSharing.ALWAYS));
        assertNoAllocation(sim, 2, 0.025, 100);
    }

    private static void assertNoAllocation(Simulation sim, int threads, double dt, int warmUp) {
        try (Parallelism p = threads > 1 ? Parallelism.install(sim, threads) : null) {
            AllocationCounter counter = AllocationCounter.currentThreadAnd(
                    p == null ? new long[0] : p.pool().workerThreadIds());
            for (int i = 0; i < warmUp; i++) {
                sim.step(dt);
            }
            long bytes = counter.bytesAllocatedBy(() -> {
                for (int i = 0; i < 300; i++) {
                    sim.step(dt);
                }
            }, 2);
            assertEquals(0, bytes, "bytes allocated by 300 steps");
        }
    }
}
