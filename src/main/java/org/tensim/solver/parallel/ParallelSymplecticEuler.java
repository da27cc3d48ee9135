package org.tensim.solver.parallel;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.SymplecticEuler;

/**
 * Symplectic Euler ({@link SymplecticEuler}) with its node loop split among the
 * threads of a {@link WorkerPool}: node i's update uses node i's data only, with the
 * same operations as {@link SymplecticEuler}, so the result is the same to the last
 * bit for any thread count (tested against {@link SymplecticEuler}).
 */
public final class ParallelSymplecticEuler implements Integrator {
    private final WorkerPool pool;
    private final int minParallel;
    private final WorkerPool.Task update = this::updateSlice;
    private final double[] scratch = new double[6];
    private double[] f;
    private SystemState s;
    private double h;

    /** @param pool the threads that share the node loop (not closed by this integrator) */
    public ParallelSymplecticEuler(WorkerPool pool) {
        this(pool, ParallelMidpointRK2.MIN_PARALLEL_NODES);
    }

    /** @param minParallelNodes nodes (>= 1) from which the loop is split among the threads */
    public ParallelSymplecticEuler(WorkerPool pool, int minParallelNodes) {
        if (minParallelNodes < 1) {
            throw new IllegalArgumentException("minParallelNodes must be >= 1, got " + minParallelNodes);
        }
        this.pool = pool;
        this.minParallel = minParallelNodes;
    }

    @Override
    public String name() {
        return "symplectic-euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return 1;
    }

    @Override
    public void step(ForceModel model, double t, double dt) {
        SystemState st = model.state();
        if (f == null || f.length != 3 * st.nodeCount) {
            f = new double[3 * st.nodeCount];
        }
        s = st;
        h = dt;
        model.computeForces(t, st.x, st.v, f);
        if (st.nodeCount < minParallel || pool.size() == 1) {
            updateRange(0, st.nodeCount);
        } else {
            pool.run(update);
        }
        st.applyMotions(t + dt, st.x, st.v, scratch);
        s = null;
    }

    private void updateSlice(int worker) {
        int n = s.nodeCount;
        int t = pool.size();
        updateRange((int) ((long) n * worker / t), (int) ((long) n * (worker + 1) / t));
    }

    /** v += h w f, then x += h v (the new velocity), as in SymplecticEuler. */
    private void updateRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] fo = f;
        final double dt = h;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                v[k] += dt * w * fo[k];
                x[k] += dt * v[k];
            }
        }
    }
}
