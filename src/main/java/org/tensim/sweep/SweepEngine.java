package org.tensim.sweep;

import java.io.IOException;
import java.util.List;

/**
 * Runs the points of a sweep, each an independent headless run ({@link SceneRun#run}),
 * and hands every result to a sink on the calling thread as soon as it is known, so that
 * the results file grows as points finish.
 */
public interface SweepEngine extends AutoCloseable {
    /** Receives results, one at a time, on the thread that called {@link #run}. */
    @FunctionalInterface
    interface Sink {
        void accept(PointResult r) throws IOException;
    }

    /** Engine name for reports, e.g. {@code local (2 workers)}. */
    String describe();

    /**
     * Runs the points and returns when all are done (or throws when the sink fails or the thread is
     * interrupted; results handed over before that are kept by the sink).
     */
    void run(RunSetup setup, List<String> names, List<Point> points, Sink sink) throws IOException,
            InterruptedException;

    @Override
    void close();
}
