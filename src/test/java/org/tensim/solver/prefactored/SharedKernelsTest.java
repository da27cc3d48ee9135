package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.solver.parallel.PooledNodeLoops;
import org.tensim.solver.parallel.WorkerPool;

/**
 * What bdf2 shares among the threads beyond the force model's loops (the fibres' and shear elements' part of
 * the Jacobian products, by {@link NodeParts}, and the preconditioner's solves, {@link SubtreeSolve}) gives the
 * one-thread bits: a product on 1, 2 and 3 threads, and whole steps of a diaphragm on 1 and 2 threads, with the
 * shared kernels and without.
 */
class SharedKernelsTest {
    private static Simulation diaphragm() throws Exception {
        return DiaphragmSetup.generated(28, null, DiaphragmParameters.defaults(), new BreathingCycle(4, 2),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa())).scene().newSimulation();
    }

    /** The 28-ring diaphragm among the parametric cage's swept bones: contact pairs beside fibres and shear elements. */
    private static Simulation diaphragmOnBones() {
        org.tensim.scene.diaphragm.DiaphragmSpec d = org.tensim.scene.diaphragm.DiaphragmSpec.defaults();
        org.tensim.scene.diaphragm.DiaphragmSpec spec = d.withMesh(d.mesh().withRings(28))
                .withCage(d.cage().withSurfaces(true));
        try {
            return DiaphragmSetup.build(spec).scene().newSimulation();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void productHasTheSameBitsOnOneTwoAndThreeThreads() throws Exception {
        productBits(diaphragm().state());
    }

    /** With contact pairs, about half of them pushed deeper than at rest (in contact at the linearisation). */
    @Test
    void productWithContactHasTheSameBitsOnOneTwoAndThreeThreads() throws Exception {
        SystemState s = diaphragmOnBones().state();
        assertTrue(s.contacts.count() > 0, "contact pairs");
        productBits(s);
    }

    private static void productBits(SystemState s) {
        assertTrue(s.fibres.count() + s.shears.count() >= SpringJacobian.MIN_SHARED_ELEMENTS,
                s.fibres.count() + " fibres, " + s.shears.count() + " shear elements");
        Random rnd = new Random(3);
        int[] freeIndex = new int[s.nodeCount];
        int free = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            freeIndex[i] = rnd.nextInt(5) == 0 ? -1 : free++;
        }
        int[] freeNodes = new int[free];
        for (int i = 0; i < s.nodeCount; i++) {
            if (freeIndex[i] >= 0) {
                freeNodes[freeIndex[i]] = i;
            }
        }
        double[] x = new double[s.x0.length];
        for (int k = 0; k < x.length; k++) {
            x[k] = s.x0[k] + 1e-3 * rnd.nextGaussian(); // some elements stretched, some compressed
        }
        if (s.contacts.count() > 0) {
            int active = s.contacts.activeCount(0.7, x);
            assertTrue(active > 0 && active < s.contacts.count(), active + " of " + s.contacts.count() + " in contact");
        }
        double[] p = new double[3 * free];
        for (int k = 0; k < p.length; k++) {
            p[k] = rnd.nextGaussian();
        }
        SpringJacobian serial = new SpringJacobian(s, freeIndex, freeNodes);
        serial.linearise(0.7, x, 0.02, NodeLoops.SERIAL);
        double[] reference = new double[p.length];
        serial.multiply(p, reference);
        for (int threads = 2; threads <= 3; threads++) {
            try (WorkerPool pool = new WorkerPool(threads, "product-test")) {
                SpringJacobian shared = new SpringJacobian(s, freeIndex, freeNodes);
                shared.linearise(0.7, x, 0.02, new PooledNodeLoops(pool, 1));
                double[] out = new double[p.length];
                shared.multiply(p, out);
                assertNotNull(shared.parts(), "the product was shared");
                assertEquals(SpringJacobian.PARTS_PER_THREAD * threads, shared.parts().parts());
                assertArrayEquals(reference, out, threads + " threads");
            }
        }
    }

    /** Positions after {@code steps} bdf2 steps at 25 ms of a 28-ring diaphragm. */
    private static double[] run(int threads, KernelSharing shared, int steps) throws Exception {
        return run(diaphragm(), threads, shared, steps);
    }

    private static double[] run(Simulation sim, int threads, KernelSharing shared, int steps) {
        PrefactoredBdf2 bdf2 = new PrefactoredBdf2().setKernelSharing(shared);
        sim.setIntegrator(bdf2);
        try (Parallelism p = Parallelism.install(sim, threads)) {
            for (int i = 0; i < steps; i++) {
                sim.step(0.025);
            }
        }
        assertTrue(bdf2.factorNonZeros() >= SparseCholesky.MIN_SPLIT_ENTRIES, bdf2.factorNonZeros() + " entries");
        assertTrue(sim.state().fibres.count() + sim.state().shears.count() >= SpringJacobian.MIN_SHARED_ELEMENTS,
                "fibres and shear elements shared");
        return sim.state().x.clone();
    }

    @Test
    void bdf2StepsHaveTheSameBitsOnOneAndTwoThreads() throws Exception {
        double[] one = run(1, KernelSharing.ALWAYS, 12);
        assertArrayEquals(one, run(2, KernelSharing.ALWAYS, 12), "2 threads, shared kernels");
        assertArrayEquals(one, run(2, KernelSharing.NEVER, 12), "2 threads, kernels on the calling thread");
        assertArrayEquals(one, run(2, KernelSharing.MEASURED, 12), "2 threads, shared while measured faster");
    }

    /** The same with contact: the 28-ring diaphragm on the swept cage's bones. */
    @Test
    void bdf2StepsWithContactHaveTheSameBitsOnOneAndTwoThreads() {
        double[] one = run(diaphragmOnBones(), 1, KernelSharing.ALWAYS, 12);
        assertArrayEquals(one, run(diaphragmOnBones(), 2, KernelSharing.ALWAYS, 12), "2 threads, shared kernels");
        assertArrayEquals(one, run(diaphragmOnBones(), 2, KernelSharing.NEVER, 12), "2 threads, on the calling thread");
    }
}
