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
import org.tensim.model.Topology;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.ShuffledScene;
import org.tensim.solver.ForceModel;
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.ParallelSpringPass;
import org.tensim.solver.parallel.WorkerPool;

/**
 * One force pass (gravity and all springs) on the benchmark lattice (1000 N/m,
 * 0.1 m, 1 kg, undamped), in microseconds. {@code impl}: {@code builtin} is
 * ForceModel's own loop; {@code parallel} the {@link ParallelSpringPass} on
 * T threads. {@code shuffled} numbers the nodes randomly first.
 * Springs per second = springs / time (springs: 3 n^2 (n-1) + 6 n (n-1)^2).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class ForcePassBenchmark {
    @Param({"11", "31"})
    int n;

    /** builtin, or parallel-T for T threads. */
    @Param({"builtin", "parallel-1", "parallel-2"})
    String impl;

    @Param({"false"})
    boolean shuffled;

    @Param({"auto"})
    String order;

    SystemState state;
    ForceModel model;
    WorkerPool pool;
    double[] f;

    @Setup(Level.Trial)
    public void setUp() {
        Topology t = LatticeScene.build(n, 0.1, 1, 1000, 0, false);
        state = SystemState.compile(shuffled ? ShuffledScene.shuffle(t, 1234) : t);
        model = new ForceModel(state);
        f = new double[state.x.length];
        if (impl.startsWith("parallel-")) {
            int threads = Integer.parseInt(impl.substring(impl.indexOf('-') + 1));
            pool = new WorkerPool(threads, "jmh");
            model.setSpringPass(new ParallelSpringPass(state, pool,
                    ParallelSpringPass.Order.valueOf(order.toUpperCase())));
        }
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        if (pool != null) {
            pool.close();
        }
    }

    @Benchmark
    public double[] forcePass() {
        model.computeForces(0, state.x, state.v, f);
        return f;
    }
}
