package org.tensim.scene.tunable;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.tensim.solver.Simulation;
import org.tensim.solver.StepListener;

/**
 * Hands the node positions of every body from the simulation thread to the
 * renderer without locks and without ever showing a half-updated state.
 *
 * <p>It is a double buffer with a spare (triple buffering): the simulation writes
 * a whole frame into its own buffer after each step, then swaps it with the
 * "ready" slot in one atomic operation; the renderer swaps its own buffer with the
 * ready slot when a newer frame is there. Neither side ever waits for the other,
 * neither side ever sees a buffer the other is writing, and the model is never
 * locked. Registered as a {@link StepListener} of the last body's simulation, so
 * all bodies have completed the step when it copies.
 *
 * <p>The copy converts to float (what the graphics card takes) and allocates
 * nothing. A scene's {@link LiveState} (the nodes in contact, the domes' descent) is
 * measured at the same moment into the same frame, so the marks drawn always belong to
 * the positions drawn; its readouts are also handed to the window ({@link #readouts()}).
 */
public final class FrameBuffer implements StepListener {
    /** One published frame: positions of each body (3 floats per node, m), time and step count. */
    public static final class Frame {
        /** Positions per body, m, 3 per node. */
        public final float[][] positions;
        /** Simulated time of the frame, s. */
        public double time;
        /** Steps completed at the frame. */
        public long step;
        /** The live state's mark per node of its body ({@link LiveState#body()}), or null without one. */
        public final byte[] marks;
        /** The live state's readouts, or null without one. */
        public final double[] readouts;

        Frame(List<Body> bodies, LiveState live) {
            positions = new float[bodies.size()][];
            for (int b = 0; b < bodies.size(); b++) {
                positions[b] = new float[3 * bodies.get(b).nodeCount()];
            }
            marks = live == null ? null : new byte[bodies.get(live.body()).nodeCount()];
            readouts = live == null ? null : new double[live.readouts().size()];
        }
    }

    private static final int FRESH = 4;
    private static final int INDEX = 3;

    private final List<Body> bodies;
    private final Frame[] frames = new Frame[3];
    /** Index of the ready frame, with the FRESH bit when the renderer has not taken it yet. */
    private final AtomicInteger ready = new AtomicInteger(1);
    private int writing;
    private int reading = 2;

    private final LiveState live;
    private final LatestValues readouts;

    public FrameBuffer(List<Body> bodies) {
        this(bodies, null);
    }

    /** As {@link #FrameBuffer(List)} with a scene's live state (null for none), measured into every frame. */
    public FrameBuffer(List<Body> bodies, LiveState live) {
        this.bodies = List.copyOf(bodies);
        this.live = live;
        this.readouts = live == null ? null : new LatestValues(live.readouts().size());
        for (int i = 0; i < 3; i++) {
            frames[i] = new Frame(this.bodies, live);
        }
        // All three start with the initial state, so the first frame drawn is a whole one.
        for (int i = 0; i < 3; i++) {
            copyInto(frames[i], bodies.get(0).simulation());
        }
    }

    /** Copies every body's state into the write buffer, then publishes it. Simulation thread only. */
    @Override
    public void afterStep(Simulation last) {
        copyInto(frames[writing], last);
        writing = ready.getAndSet(writing | FRESH) & INDEX;
    }

    private void copyInto(Frame f, Simulation timeSource) {
        for (int b = 0; b < bodies.size(); b++) {
            double[] x = bodies.get(b).simulation().state().x;
            float[] out = f.positions[b];
            for (int k = 0; k < x.length; k++) {
                out[k] = (float) x[k];
            }
        }
        f.time = timeSource.time();
        f.step = timeSource.steps();
        if (live != null) {
            live.measure(bodies.get(live.body()).simulation(), f.marks, f.readouts);
            readouts.publish(f.readouts);
        }
    }

    /** The scene's live state, or null. */
    public LiveState live() {
        return live;
    }

    /**
     * The newest readouts of the live state, for the window's thread (one reader: {@link LatestValues}); null
     * without a live state.
     */
    public LatestValues readouts() {
        return readouts;
    }

    /**
     * The newest complete frame if one was published since the last call, else
     * null. The frame stays valid, and untouched by the simulation, until the next
     * call. Renderer thread only.
     */
    public Frame takeNewer() {
        if ((ready.get() & FRESH) == 0) {
            return null;
        }
        reading = ready.getAndSet(reading) & INDEX;
        return frames[reading];
    }

    /** The bodies whose positions this buffer carries, in order. */
    public List<Body> bodies() {
        return bodies;
    }
}
