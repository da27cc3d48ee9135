package org.tensim.solver.parallel;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.SystemState;

/**
 * The paper's midpoint RK2 ({@link MidpointRK2}) with its two node loops split
 * among the threads of a {@link WorkerPool}: node i's update uses node i's data
 * only, with the same operations as {@link MidpointRK2}, so the result is the same
 * to the last bit for any thread count and any split (tested against
 * {@link MidpointRK2}). The force evaluations go through the {@link ForceModel}, so
 * they are parallel when it has a {@link ParallelSpringPass}.
 *
 * <p>Why: with the force pass on two threads, RK2's two node loops (5 arrays of 3
 * doubles per node each) became a third of a step on one thread at n = 31.
 */
public final class ParallelMidpointRK2 implements Integrator {
    /** Nodes below which a loop runs on the calling thread alone (a dispatch costs more). */
    static final int MIN_PARALLEL_NODES = 4096;

    private final WorkerPool pool;
    private final int minParallel;
    private final WorkerPool.Task half = this::halfStep;
    private final WorkerPool.Task full = this::fullStep;
    private final double[] scratch = new double[6];
    private double[] f;
    private double[] xm;
    private double[] vm;
    private SystemState s;
    private double h;

    /** @param pool the threads that share the node loops (not closed by this integrator) */
    public ParallelMidpointRK2(WorkerPool pool) {
        this(pool, MIN_PARALLEL_NODES);
    }

    /** As {@link #ParallelMidpointRK2(WorkerPool)}, splitting the loops from {@code minParallelNodes} nodes on. */
    public ParallelMidpointRK2(WorkerPool pool, int minParallelNodes) {
        if (minParallelNodes < 1) {
            throw new IllegalArgumentException("minParallelNodes must be >= 1, got " + minParallelNodes);
        }
        this.pool = pool;
        this.minParallel = minParallelNodes;
    }

    @Override
    public String name() {
        return "rk2";
    }

    @Override
    public int order() {
        return 2;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 2;
    }

    /**
     * 0, as for {@link MidpointRK2}: undamped, RK2 grows at every step size
     * (|R(i w h)| &gt; 1). Used by critical time step checks that ask integrators.
     */
    public double undampedStabilityLimit() {
        return 0;
    }

    @Override
    public void step(ForceModel model, double t, double dt) {
        SystemState st = model.state();
        int n3 = 3 * st.nodeCount;
        if (f == null || f.length != n3) {
            f = new double[n3];
            xm = new double[n3];
            vm = new double[n3];
        }
        s = st;
        h = dt;
        final double hh = 0.5 * dt;

        model.computeForces(t, st.x, st.v, f);
        dispatch(half, st.nodeCount);
        st.applyMotions(t + hh, xm, vm, scratch);

        model.computeForces(t + hh, xm, vm, f);
        dispatch(full, st.nodeCount);
        st.applyMotions(t + dt, st.x, st.v, scratch);
        s = null;
    }

    private void dispatch(WorkerPool.Task task, int nodes) {
        if (nodes < minParallel || pool.size() == 1) {
            // The whole range on this thread: worker 0 of a team of one.
            if (task == half) {
                halfRange(0, nodes);
            } else {
                fullRange(0, nodes);
            }
        } else {
            pool.run(task);
        }
    }

    private int from(int worker, int nodes) {
        return (int) ((long) nodes * worker / pool.size());
    }

    private void halfStep(int worker) {
        int n = s.nodeCount;
        halfRange(from(worker, n), from(worker + 1, n));
    }

    private void fullStep(int worker) {
        int n = s.nodeCount;
        fullRange(from(worker, n), from(worker + 1, n));
    }

    /** x_m = x + h/2 v, v_m = v + h/2 a1 for nodes [lo, hi): as in MidpointRK2. */
    private void halfRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] fo = f;
        final double[] xmo = xm;
        final double[] vmo = vm;
        final double hh = 0.5 * h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            // Fixed and driven nodes (w = 0) are not integrated (see MidpointRK2).
            final boolean free = w != 0;
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                xmo[k] = free ? x[k] + hh * v[k] : x[k];
                vmo[k] = free ? v[k] + hh * w * fo[k] : v[k];
            }
        }
    }

    /** x += h v_m, v += h a2 for the free nodes of [lo, hi): as in MidpointRK2. */
    private void fullRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] fo = f;
        final double[] vmo = vm;
        final double dt = h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                x[k] += dt * vmo[k];
                v[k] += dt * w * fo[k];
            }
        }
    }
}
