package org.tensim.solver.parallel;

import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * Puts a {@link Simulation} on several threads, the same way for every integrator:
 * on one {@link WorkerPool}, its force model gets a {@link ParallelSpringPass}, a
 * {@link ParallelTrianglePass} when it has enough membrane triangles, and
 * {@link PooledNodeLoops} (which split the integrator's node loops, see
 * {@link org.tensim.solver.NodeLoops}), and, when there are rigid links, its
 * projection gets {@link ParallelLinkSweeps}. The integrator itself is not replaced.
 * Close it to stop the threads and restore the single-threaded loops.
 *
 * <pre>
 *   try (Parallelism p = Parallelism.install(sim, 2)) {
 *       sim.runUntil(10, 1e-3);
 *   }
 * </pre>
 *
 * Results do not depend on the thread count (bit for bit); see the spring pass and
 * the link sweeps for how they may differ from the built-in loops (summation and
 * sweep order). Node loops give the built-in loops' bits.
 */
public final class Parallelism implements AutoCloseable {
    private final Simulation sim;
    private final WorkerPool pool;
    private final ParallelSpringPass springs;
    private final ParallelTrianglePass triangles;
    private final ParallelLinkSweeps links;
    private final PooledNodeLoops nodeLoops;

    private Parallelism(Simulation sim, int threads, ParallelSpringPass.Order order, int minWork) {
        this.sim = sim;
        this.pool = new WorkerPool(threads, "tensim-step");
        SystemState s = sim.state();
        boolean defaults = minWork <= 0;
        this.springs = new ParallelSpringPass(s, pool, order,
                defaults ? ParallelSpringPass.MIN_PARALLEL_SPRINGS : minWork);
        this.links = s.linkCount() == 0 ? null
                : new ParallelLinkSweeps(s, pool, defaults ? ParallelLinkSweeps.MIN_PARALLEL_LINKS : minWork);
        this.nodeLoops = new PooledNodeLoops(pool, defaults ? PooledNodeLoops.MIN_PARALLEL_NODES : minWork);
        this.triangles = s.triangleCount() < (defaults ? ParallelTrianglePass.MIN_PARALLEL_TRIANGLES : minWork) ? null
                : new ParallelTrianglePass(s, pool);
        sim.forces().setSpringPass(springs);
        sim.forces().setTrianglePass(triangles);
        sim.forces().setNodeLoops(nodeLoops);
        sim.projection().setSweeps(links);
    }

    /** Installs with the thread count of the simulation's settings ({@code SolverSettings.threads}). */
    public static Parallelism install(Simulation sim) {
        return install(sim, sim.settings().threads());
    }

    /** Installs with the automatic node order ({@link ParallelSpringPass.Order#AUTO}). */
    public static Parallelism install(Simulation sim, int threads) {
        return install(sim, threads, ParallelSpringPass.Order.AUTO);
    }

    /**
     * Installs a pool of {@code threads} (>= 1, the calling thread included) on sim.
     * The step must then be called from one thread at a time.
     */
    public static Parallelism install(Simulation sim, int threads, ParallelSpringPass.Order order) {
        if (threads < 1) {
            throw new IllegalArgumentException("thread count must be >= 1, got " + threads);
        }
        return new Parallelism(sim, threads, order, 0);
    }

    /**
     * As {@link #install(Simulation, int, ParallelSpringPass.Order)}, with one threshold
     * for the springs, nodes and links (>= 1) from which work is split among the threads
     * (the defaults keep small scenes on one thread, where a dispatch costs more than it
     * saves; 1 splits everything, as tests of thread-count independence need).
     */
    public static Parallelism install(Simulation sim, int threads, ParallelSpringPass.Order order,
            int minParallelWork) {
        if (threads < 1) {
            throw new IllegalArgumentException("thread count must be >= 1, got " + threads);
        }
        if (minParallelWork < 1) {
            throw new IllegalArgumentException("minParallelWork must be >= 1, got " + minParallelWork);
        }
        return new Parallelism(sim, threads, order, minParallelWork);
    }

    /**
     * Springs from which {@link #automaticThreads(int)} uses every core: the real-time study
     * (docs/diaphragm.md) measured two threads 11-24 % faster at 24,733 springs (20 rings) and
     * up, and a third slower at 12,144 (14 rings) and below.
     */
    public static final int AUTO_PARALLEL_SPRINGS = 20_000;

    /** Number of cores the JVM sees: the default thread count. */
    public static int availableCores() {
        return Runtime.getRuntime().availableProcessors();
    }

    /**
     * The automatic thread count of a scene with {@code springs} springs: every core from
     * {@link #AUTO_PARALLEL_SPRINGS}, else 1 (below it a dispatch costs more than it saves).
     */
    public static int automaticThreads(int springs) {
        return springs >= AUTO_PARALLEL_SPRINGS ? availableCores() : 1;
    }

    public int threads() {
        return pool.size();
    }

    public WorkerPool pool() {
        return pool;
    }

    public ParallelSpringPass springPass() {
        return springs;
    }

    /** The node loops installed on the force model. */
    public PooledNodeLoops nodeLoops() {
        return nodeLoops;
    }

    /** The link sweeps, or null when the state has no rigid links. */
    public ParallelLinkSweeps linkSweeps() {
        return links;
    }

    /** Restores the built-in loops and stops the threads. */
    @Override
    public void close() {
        if (sim.forces().springPass() == springs) {
            sim.forces().setSpringPass(null);
        }
        if (triangles != null && sim.forces().trianglePass() == triangles) {
            sim.forces().setTrianglePass(null);
        }
        if (links != null && sim.projection().sweeps() == links) {
            sim.projection().setSweeps(null);
        }
        if (sim.forces().nodeLoops() == nodeLoops) {
            sim.forces().setNodeLoops(null);
        }
        pool.close();
    }
}
