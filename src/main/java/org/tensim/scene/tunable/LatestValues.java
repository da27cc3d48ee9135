package org.tensim.scene.tunable;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * The newest of a stream of fixed-length arrays of numbers, handed from one writer thread to one reader thread
 * without locks, without allocation and without ever showing a half-written array: a triple buffer, as
 * {@link FrameBuffer}'s (the writer fills its own array and swaps it with the ready slot; the reader swaps its own
 * with the ready slot when a newer one is there).
 */
public final class LatestValues {
    private static final int FRESH = 4;
    private static final int INDEX = 3;

    private final double[][] slots;
    private final AtomicInteger ready = new AtomicInteger(1);
    private int writing;
    private int reading = 2;

    /** Arrays of {@code length} numbers, all NaN at first. */
    public LatestValues(int length) {
        slots = new double[3][length];
        for (double[] s : slots) {
            java.util.Arrays.fill(s, Double.NaN);
        }
    }

    /** Copies {@code values} (at least the arrays' length) and publishes them. Writer thread only. */
    public void publish(double[] values) {
        System.arraycopy(values, 0, slots[writing], 0, slots[writing].length);
        writing = ready.getAndSet(writing | FRESH) & INDEX;
    }

    /**
     * The newest published array: a newer one when there is one, else the one the last call returned (untouched by
     * the writer until the next call). Reader thread only; do not change it.
     */
    public double[] latest() {
        if ((ready.get() & FRESH) != 0) {
            reading = ready.getAndSet(reading) & INDEX;
        }
        return slots[reading];
    }
}
