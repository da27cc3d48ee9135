package org.tensim.experiment;

import org.tensim.solver.Simulation;
import org.tensim.solver.StepListener;

/**
 * What a scene graph does after each step: copy the positions, by authored node id,
 * into a float array laid out like a vertex buffer (x, y, z per vertex). Timed so
 * that the benchmark and the real-time study can report the sync separately from the
 * solver; a stand-in for the view's own copy, without a display.
 */
public final class SceneGraphSync implements StepListener {
    private final float[] coords;
    private long nanos;
    private long calls;

    /** A sync of {@code nodes} nodes. */
    public SceneGraphSync(int nodes) {
        coords = new float[3 * nodes];
    }

    @Override
    public void afterStep(Simulation simulation) {
        long t0 = System.nanoTime();
        final double[] x = simulation.state().x;
        final float[] c = coords;
        for (int k = 0; k < c.length; k++) {
            c[k] = (float) x[k];
        }
        nanos += System.nanoTime() - t0;
        calls++;
    }

    /** Mean time per sync since the last reset, ms. */
    public double meanMillis() {
        return calls == 0 ? 0 : nanos / 1e6 / calls;
    }

    /** Starts the mean of {@link #meanMillis()} again. */
    public void reset() {
        nanos = 0;
        calls = 0;
    }

    /** The copied coordinates (keeps the copy from being optimised away). */
    public float[] coords() {
        return coords;
    }
}
