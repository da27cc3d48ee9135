package org.tensim.jmh;

import java.util.Random;
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
import org.tensim.solver.RigidLinkProjection;
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.ParallelLinkSweeps;
import org.tensim.solver.parallel.WorkerPool;

/**
 * One Gauss-Seidel sweep of the rigid-link projection plus its two error measures
 * (the projection capped at one iteration), on the lattice with a rigid link along
 * a body diagonal of every cell ((n-1)^3 links), from perturbed positions restored
 * before each call (a copy of 3 n^3 doubles, included). {@code impl}: {@code builtin}
 * sweeps in authored order; {@code coloured} by link colour on T threads.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class ProjectionBenchmark {
    @Param({"31"})
    int n;

    /** builtin, or coloured-T for T threads. */
    @Param({"builtin", "coloured-1", "coloured-2"})
    String impl;

    SystemState state;
    RigidLinkProjection projection;
    WorkerPool pool;
    double[] start;
    double[] x;

    @Setup(Level.Trial)
    public void setUp() {
        state = SystemState.compile(LatticeScene.build(n, 0.1, 1, 1000, 0, true));
        Random rnd = new Random(1);
        start = state.x.clone();
        for (int k = 0; k < start.length; k++) {
            start[k] += 1e-3 * rnd.nextGaussian();
        }
        x = start.clone();
        projection = new RigidLinkProjection();
        if (impl.startsWith("coloured-")) {
            int threads = Integer.parseInt(impl.substring(impl.indexOf('-') + 1));
            pool = new WorkerPool(threads, "jmh");
            projection.setSweeps(new ParallelLinkSweeps(state, pool));
        }
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        if (pool != null) {
            pool.close();
        }
    }

    @Benchmark
    public double sweep() {
        System.arraycopy(start, 0, x, 0, x.length);
        // one sweep: a tolerance no sweep meets, a cap of one
        projection.project(state, x, 1e-300, 1);
        return projection.maxRelativeError();
    }
}
