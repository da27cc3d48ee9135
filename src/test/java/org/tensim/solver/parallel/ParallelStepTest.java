package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.ShuffledScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * Whole steps on several threads: the trajectory does not depend on the thread
 * count (bit for bit), and the reordered, coloured solver follows the built-in
 * single-threaded one within {@link #TRAJECTORY_TOLERANCE_M}.
 */
class ParallelStepTest {
    /**
     * Largest position difference allowed between the built-in loops and the parallel
     * solver after {@link #STEPS} steps, m. The two differ by the order of the sums
     * at a node (rounding, 1e-16 relative) and by the order of the Gauss-Seidel link
     * sweeps, whose iterates agree only to the projection tolerance (1e-9 of a 0.17 m
     * link) at each step.
     */
    static final double TRAJECTORY_TOLERANCE_M = 1e-7;
    static final int STEPS = 300;
    static final double DT = 1e-3;

    static Topology scene(boolean shuffled) {
        Topology t = LatticeScene.build(6, 0.1, 1, 1000, 0.5, true);
        return shuffled ? ShuffledScene.shuffle(t, 77) : t;
    }

    static SystemState run(Topology t, int threads) {
        Simulation sim = new Simulation(SystemState.compile(t));
        if (threads == 0) {
            sim.runUntil(STEPS * DT, DT);
            return sim.state();
        }
        // Every loop split, however small the scene: the test is about the split.
        try (Parallelism p = Parallelism.install(sim, threads, ParallelSpringPass.Order.AUTO, 1)) {
            sim.runUntil(STEPS * DT, DT);
        }
        return sim.state();
    }

    static double maxDiff(double[] a, double[] b) {
        double d = 0;
        for (int k = 0; k < a.length; k++) {
            d = Math.max(d, Math.abs(a[k] - b[k]));
        }
        return d;
    }

    @Test
    void trajectoryIsIdenticalForAnyThreadCount() {
        for (boolean shuffled : new boolean[] {false, true}) {
            Topology t = scene(shuffled);
            SystemState one = run(t, 1);
            for (int threads = 2; threads <= 4; threads++) {
                SystemState s = run(t, threads);
                assertArrayEquals(one.x, s.x, "positions, " + threads + " threads, shuffled " + shuffled);
                assertArrayEquals(one.v, s.v, "velocities, " + threads + " threads, shuffled " + shuffled);
            }
        }
    }

    @Test
    void parallelSolverFollowsTheBuiltInOneOnAuthoredAndShuffledMeshes() {
        for (boolean shuffled : new boolean[] {false, true}) {
            Topology t = scene(shuffled);
            SystemState reference = run(t, 0);
            SystemState parallel = run(t, 2);
            double d = maxDiff(reference.x, parallel.x);
            assertTrue(d <= TRAJECTORY_TOLERANCE_M, "shuffled " + shuffled + ": max difference " + d + " m");
            // And the motion is not trivial: the lattice sags under gravity.
            assertTrue(maxDiff(reference.x, reference.x0) > 1e-3);
        }
    }
}
