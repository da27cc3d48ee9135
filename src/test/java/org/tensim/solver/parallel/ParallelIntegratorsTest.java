package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.ForceLaw;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.SymplecticEuler;

/** The split RK2 and symplectic Euler are the originals, bit for bit, whatever the split. */
class ParallelIntegratorsTest {
    /** A lattice large enough to be split, with a driven node and a sinusoidal force. */
    static Topology scene() {
        Topology t = LatticeScene.build(17, 0.1, 1, 1000, 0.5, false);
        Node driven = t.node(17 * 17 * 17 - 1);
        driven.drive((time, rest, out, o) -> {
            out[o] = rest.x() + 0.01 * Math.sin(10 * time);
            out[o + 1] = rest.y();
            out[o + 2] = rest.z();
        });
        t.applyForce(t.node(17 * 17 * 8 + 17 * 8 + 8), ForceLaw.sinusoid(5, 2, 0, new Vec3(0, 0, 1)));
        return t;
    }

    @Test
    void sameBitsAsMidpointRK2ForAnyThreadCount() {
        Topology t = scene();
        Simulation reference = new Simulation(SystemState.compile(t), new MidpointRK2());
        reference.runUntil(0.05, 1e-3);
        for (int threads = 1; threads <= 3; threads++) {
            try (WorkerPool pool = new WorkerPool(threads, "test")) {
                Simulation sim = new Simulation(SystemState.compile(t), new ParallelMidpointRK2(pool, 1));
                sim.runUntil(0.05, 1e-3);
                assertArrayEquals(reference.state().x, sim.state().x, "positions, threads " + threads);
                assertArrayEquals(reference.state().v, sim.state().v, "velocities, threads " + threads);
            }
        }
    }

    @Test
    void sameBitsAsSymplecticEulerForAnyThreadCount() {
        Topology t = scene();
        Simulation reference = new Simulation(SystemState.compile(t), new SymplecticEuler());
        reference.runUntil(0.05, 1e-3);
        for (int threads = 1; threads <= 3; threads++) {
            try (WorkerPool pool = new WorkerPool(threads, "test")) {
                Simulation sim = new Simulation(SystemState.compile(t), new ParallelSymplecticEuler(pool, 1));
                sim.runUntil(0.05, 1e-3);
                assertArrayEquals(reference.state().x, sim.state().x, "positions, threads " + threads);
                assertArrayEquals(reference.state().v, sim.state().v, "velocities, threads " + threads);
            }
        }
        Simulation swapped = new Simulation(SystemState.compile(t), new SymplecticEuler());
        try (Parallelism p = Parallelism.install(swapped, 2)) {
            assertTrue(swapped.integrator() instanceof ParallelSymplecticEuler);
        }
        assertTrue(swapped.integrator() instanceof SymplecticEuler);
    }

    @Test
    void parallelismSwapsTheIntegratorAndRestoresIt() {
        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(3, 0.1, 1, 1000, 0, false)));
        MidpointRK2 original = (MidpointRK2) sim.integrator();
        try (Parallelism p = Parallelism.install(sim, 2)) {
            assertTrue(sim.integrator() instanceof ParallelMidpointRK2);
            sim.step(1e-3);
        }
        assertSame(original, sim.integrator());
    }
}
