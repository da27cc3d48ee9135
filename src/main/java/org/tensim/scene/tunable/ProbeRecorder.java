package org.tensim.scene.tunable;

import java.util.List;
import org.tensim.solver.Simulation;
import org.tensim.solver.StepListener;

/**
 * Samples the displacement (m) of each body's probe node every
 * {@code intervalS} seconds of simulated time into a preallocated ring, for the
 * live chart. The simulation thread writes; one reader (the Swing thread) copies
 * out what is new with {@link #drain(Sink)}. A reader that falls more than a ring
 * behind loses the oldest samples, never blocks the simulation.
 */
public final class ProbeRecorder implements StepListener {
    /** Receives samples in time order: time (s) and, per body, displacement (m) x, y, z. */
    public interface Sink {
        void sample(double t, double[][] displacement);
    }

    private final List<Body> bodies;
    private final double interval;
    private final int capacity;
    private final double[] time;
    private final double[][][] disp; // [body][axis][slot]
    private final double[] scratch = new double[3];
    private final double[][] out;
    private volatile long written;
    private long read;
    private double next;

    /**
     * @param intervalS simulated time between samples, s (> 0)
     * @param capacity  samples kept in the ring (>= 2)
     */
    public ProbeRecorder(List<Body> bodies, double intervalS, int capacity) {
        if (!(intervalS > 0)) {
            throw new IllegalArgumentException("probe sampling interval must be > 0 s, got " + intervalS);
        }
        if (capacity < 2) {
            throw new IllegalArgumentException("probe ring capacity must be >= 2, got " + capacity);
        }
        this.bodies = List.copyOf(bodies);
        this.interval = intervalS;
        this.capacity = capacity;
        time = new double[capacity];
        disp = new double[bodies.size()][3][capacity];
        out = new double[bodies.size()][3];
        record(bodies.get(0).simulation().time());
    }

    @Override
    public void afterStep(Simulation last) {
        double t = last.time();
        if (t + 1e-12 >= next) {
            record(t);
        }
    }

    private void record(double t) {
        long w = written;
        int slot = (int) (w % capacity);
        time[slot] = t;
        for (int b = 0; b < bodies.size(); b++) {
            Body body = bodies.get(b);
            body.simulation().state().displacement(body.probeNode(), scratch);
            disp[b][0][slot] = scratch[0];
            disp[b][1][slot] = scratch[1];
            disp[b][2][slot] = scratch[2];
        }
        next = t + interval;
        written = w + 1; // volatile write publishes the slot
    }

    /** Passes every sample recorded since the last call to the sink, oldest first. Reader thread only. */
    public void drain(Sink sink) {
        long w = written;
        long from = Math.max(read, w - capacity + 1);
        for (long i = from; i < w; i++) {
            int slot = (int) (i % capacity);
            for (int b = 0; b < out.length; b++) {
                out[b][0] = disp[b][0][slot];
                out[b][1] = disp[b][1][slot];
                out[b][2] = disp[b][2][slot];
            }
            sink.sample(time[slot], out);
        }
        read = w;
    }

    /** Samples recorded so far. */
    public long count() {
        return written;
    }
}
