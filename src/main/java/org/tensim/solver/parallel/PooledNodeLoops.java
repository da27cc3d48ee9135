package org.tensim.solver.parallel;

import org.tensim.solver.NodeLoops;

/**
 * Node loops split among the threads of a {@link WorkerPool}: worker w of T runs the
 * nodes {@code [n w / T, n (w + 1) / T)}. Installed by {@link Parallelism} on the
 * force model, it parallelises the node loops of every integrator that runs them
 * through {@link org.tensim.solver.ForceModel#nodeLoops()}. Bodies update each node
 * from its own data, so results are the same to the last bit for any thread count.
 *
 * <p>Why a threshold: with the force pass on two threads, RK2's two node loops (5
 * arrays of 3 doubles per node each) became a third of a step on one thread at
 * n = 31 (lattice of 29791 nodes), but below a few thousand nodes a dispatch costs
 * more than the loop.
 */
public final class PooledNodeLoops implements NodeLoops {
    /** Nodes below which a loop runs on the calling thread alone (a dispatch costs more). */
    public static final int MIN_PARALLEL_NODES = 4096;

    private final WorkerPool pool;
    private final int minParallel;
    private final WorkerPool.Task slice = this::slice;
    private Body body;
    private Body taskBody; // during runTasks only
    private final WorkerPool.Claimable task = k -> taskBody.run(k, k + 1);
    private int nodes;

    /**
     * @param pool             the threads (not closed by this object)
     * @param minParallelNodes nodes (>= 1) from which a loop is split among the threads
     */
    public PooledNodeLoops(WorkerPool pool, int minParallelNodes) {
        if (minParallelNodes < 1) {
            throw new IllegalArgumentException("minParallelNodes must be >= 1, got " + minParallelNodes);
        }
        this.pool = pool;
        this.minParallel = minParallelNodes;
    }

    @Override
    public void run(int n, Body b) {
        if (n < minParallel || pool.size() == 1) {
            b.run(0, n); // the whole range on this thread: worker 0 of a team of one
            return;
        }
        dispatch(n, b);
    }

    /**
     * The tasks go to whichever thread claims them first ({@link WorkerPool#runClaimed}), however few they are:
     * on a machine whose other core is busy with another process the caller does not wait for a worker that
     * has not started, it runs the tasks itself.
     */
    @Override
    public void runTasks(int tasks, Body b) {
        if (pool.size() == 1 || tasks < 2) {
            b.run(0, tasks);
            return;
        }
        taskBody = b;
        try {
            pool.runClaimed(tasks, task);
        } finally {
            taskBody = null;
        }
    }

    @Override
    public int threads() {
        return pool.size();
    }

    private void dispatch(int n, Body b) {
        body = b;
        nodes = n;
        try {
            pool.run(slice);
        } finally {
            body = null;
        }
    }

    private void slice(int worker) {
        int t = pool.size();
        body.run((int) ((long) nodes * worker / t), (int) ((long) nodes * (worker + 1) / t));
    }
}
