package org.tensim.solver;

/**
 * Runs an integrator's node loops, on the calling thread or split among several
 * (after Box2D v3's stage scheduler: a stage is a range function, the scheduler
 * decides who runs which part). Every integrator writes its per-node updates once, as
 * a {@link Body} over a node range, and asks {@link ForceModel#nodeLoops()} to run it;
 * installing a multi-threaded runner ({@code parallel.Parallelism}) therefore
 * parallelises every integrator the same way, with no second copy of its loops.
 *
 * <p>A body must update node i from node i's data only (no reductions, no writes to
 * other nodes): then the result is the same to the last bit for any split and any
 * thread count.
 */
public interface NodeLoops {
    /** The per-node work of one stage, for the nodes {@code [from, to)}. */
    @FunctionalInterface
    interface Body {
        void run(int from, int to);
    }

    /** Runs the whole range on the calling thread. */
    NodeLoops SERIAL = (nodes, body) -> body.run(0, nodes);

    /**
     * Runs {@code body} over the nodes {@code [0, nodes)} and returns when all of it is
     * done. Allocation-free: callers keep their bodies in fields, not in per-step lambdas.
     */
    void run(int nodes, Body body);

    /**
     * Runs {@code body} over {@code tasks} independent tasks {@code [0, tasks)} (blocks of work that
     * write disjoint data, such as slabs of elements with disjoint node sets), split among the
     * threads whatever their number: unlike {@link #run}, a few large tasks are worth a dispatch.
     * The default runs them all on the calling thread. Allocation-free as {@link #run}.
     */
    default void runTasks(int tasks, Body body) {
        body.run(0, tasks);
    }

    /**
     * Threads that share the work of {@link #run} and {@link #runTasks} (the calling thread included): 1 for
     * the serial runner. Lets a caller keep a serial form of a loop where splitting it costs extra work.
     */
    default int threads() {
        return 1;
    }
}
