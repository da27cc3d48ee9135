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
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.WorkerPool;

/**
 * The alternative that was measured against the owner-computes pass: a node-centred
 * gather over a CSR adjacency. Each node sums the forces of its incident springs
 * (each spring is computed twice, once from each end), with no write conflicts and
 * no buffers. Same lattice and units as {@link ForcePassBenchmark} (gravity included),
 * microseconds per pass; threads split the nodes in equal ranges.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class GatherBenchmark {
    @Param({"11", "31"})
    int n;

    @Param({"1", "2"})
    int threads;

    SystemState s;
    WorkerPool pool;
    int[] start;
    int[] other3; // 3 x the other end of each incidence
    double[] k;
    double[] rl;
    double[] f;
    WorkerPool.Task task;

    @Setup(Level.Trial)
    public void setUp() {
        s = SystemState.compile(LatticeScene.build(n, 0.1, 1, 1000, 0, false));
        int nodes = s.nodeCount;
        start = new int[nodes + 1];
        for (int i = 0; i < s.springCount(); i++) {
            start[s.springA[i] + 1]++;
            start[s.springB[i] + 1]++;
        }
        for (int i = 0; i < nodes; i++) {
            start[i + 1] += start[i];
        }
        int[] fill = java.util.Arrays.copyOf(start, nodes);
        other3 = new int[start[nodes]];
        k = new double[start[nodes]];
        rl = new double[start[nodes]];
        for (int i = 0; i < s.springCount(); i++) {
            int a = s.springA[i];
            int b = s.springB[i];
            int p = fill[a]++;
            other3[p] = 3 * b;
            k[p] = s.springK[i];
            rl[p] = s.springL[i];
            int q = fill[b]++;
            other3[q] = 3 * a;
            k[q] = s.springK[i];
            rl[q] = s.springL[i];
        }
        f = new double[3 * nodes];
        pool = new WorkerPool(threads, "jmh");
        task = w -> gather((int) ((long) nodes * w / threads), (int) ((long) nodes * (w + 1) / threads));
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        pool.close();
    }

    void gather(int lo, int hi) {
        final double[] x = s.x;
        final double[] m = s.mass;
        final double gy = -9.81;
        for (int i = lo; i < hi; i++) {
            final int a = 3 * i;
            final double xa = x[a];
            final double ya = x[a + 1];
            final double za = x[a + 2];
            double fx = 0;
            double fy = m[i] * gy;
            double fz = 0;
            for (int p = start[i]; p < start[i + 1]; p++) {
                final int b = other3[p];
                final double dx = x[b] - xa;
                final double dy = x[b + 1] - ya;
                final double dz = x[b + 2] - za;
                final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                final double sc = len > 0 ? k[p] * (len - rl[p]) / len : 0;
                fx += sc * dx;
                fy += sc * dy;
                fz += sc * dz;
            }
            f[a] = fx;
            f[a + 1] = fy;
            f[a + 2] = fz;
        }
    }

    @Benchmark
    public double[] gatherPass() {
        pool.run(task);
        return f;
    }
}
