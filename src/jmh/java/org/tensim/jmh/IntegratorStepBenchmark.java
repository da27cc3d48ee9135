package org.tensim.jmh;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.ExplicitRungeKutta;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.parallel.PooledNodeLoops;
import org.tensim.solver.parallel.WorkerPool;

/**
 * One integrator step (its force passes and node loops, no projection) on the
 * benchmark lattice (1000 N/m, 0.1 m, 1 kg, axial damping 0.5 N s/m, bottom fixed,
 * gravity), in microseconds. {@code method}: a registry name, or
 * {@code rk2-tableau}, the generic {@link ExplicitRungeKutta} on the midpoint
 * tableau, against which the hand-fused {@code rk2} ({@link MidpointRK2}) is
 * measured in the same run. {@code loops}: {@code serial}, or {@code pool-T} for
 * the node loops on T threads (the force pass stays single-threaded).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class IntegratorStepBenchmark {
    @Param({"31"})
    int n;

    @Param({"rk2", "rk2-tableau"})
    String method;

    @Param({"serial"})
    String loops;

    SystemState state;
    ForceModel model;
    Integrator integrator;
    WorkerPool pool;
    double t;

    @Setup(Level.Trial)
    public void setUp() {
        state = SystemState.compile(LatticeScene.build(n, 0.1, 1, 1000, 0.5, false));
        model = new ForceModel(state);
        integrator = "rk2-tableau".equals(method) ? new ExplicitRungeKutta("rk2", 2, MidpointRK2.TABLEAU)
                : Integrators.create(method);
        if (loops.startsWith("pool-")) {
            pool = new WorkerPool(Integer.parseInt(loops.substring(5)), "jmh");
            model.setNodeLoops(new PooledNodeLoops(pool, 1));
        }
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        if (pool != null) {
            pool.close();
        }
    }

    @Benchmark
    public double[] step() {
        integrator.step(model, t, 1e-4);
        t += 1e-4;
        return state.x;
    }
}
