package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.model.ForceLaw;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.Severity;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * Every registered integrator, with its node loops split among threads, gives its
 * single-threaded bits whatever the split; and Parallelism installs the split loops
 * the same way for every integrator, without replacing it.
 */
public class ParallelIntegratorsTest {
    static List<String> names() {
        return Integrators.names();
    }

    /** A lattice large enough to be split, with a driven node and a sinusoidal force (also used elsewhere). */
    public static Topology scene() {
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

    private static Simulation run(Topology t, String name, NodeLoops loops) {
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create(name));
        sim.apply(sim.settings().withStepLimitSeverity(Severity.IGNORE));
        sim.forces().setNodeLoops(loops);
        sim.runUntil(0.05, 1e-3);
        return sim;
    }

    @ParameterizedTest
    @MethodSource("names")
    void sameBitsAsTheSerialLoopsForAnyThreadCount(String name) {
        Topology t = scene();
        Simulation reference = run(t, name, null);
        for (int threads = 1; threads <= 3; threads++) {
            try (WorkerPool pool = new WorkerPool(threads, "test")) {
                Simulation sim = run(t, name, new PooledNodeLoops(pool, 1));
                assertArrayEquals(reference.state().x, sim.state().x, name + ": positions, threads " + threads);
                assertArrayEquals(reference.state().v, sim.state().v, name + ": velocities, threads " + threads);
            }
        }
    }

    @Test
    void parallelismInstallsTheNodeLoopsKeepsTheIntegratorAndRestores() {
        Simulation sim = new Simulation(SystemState.compile(LatticeScene.build(3, 0.1, 1, 1000, 0, false)));
        Integrator original = sim.integrator();
        try (Parallelism p = Parallelism.install(sim, 2)) {
            assertSame(p.nodeLoops(), sim.forces().nodeLoops());
            assertSame(original, sim.integrator());
            sim.step(1e-3);
        }
        assertSame(NodeLoops.SERIAL, sim.forces().nodeLoops());
        assertSame(original, sim.integrator());
        assertSame(MidpointRK2.class, original.getClass());
    }
}
