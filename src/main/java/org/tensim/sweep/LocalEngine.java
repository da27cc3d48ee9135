package org.tensim.sweep;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorCompletionService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The default engine: one worker thread per core, each running whole points one after
 * the other; a point's simulation runs on its worker alone (one thread per run), which on
 * many independent runs uses the cores better than sharing each step among them.
 */
public final class LocalEngine implements SweepEngine {
    private final int workers;
    private final ExecutorService pool;

    /** @param workers points run at once (>= 1), normally the number of cores */
    public LocalEngine(int workers) {
        if (workers < 1) {
            throw new IllegalArgumentException("local engine needs at least 1 worker, got " + workers);
        }
        this.workers = workers;
        AtomicInteger n = new AtomicInteger();
        ThreadFactory f = r -> {
            Thread t = new Thread(r, "sweep-worker-" + n.incrementAndGet());
            t.setDaemon(true); // an interrupted sweep must not be held open by a running point
            return t;
        };
        this.pool = Executors.newFixedThreadPool(workers, f);
    }

    @Override
    public String describe() {
        return "local (" + workers + " worker" + (workers == 1 ? "" : "s") + ")";
    }

    @Override
    public void run(RunSetup setup, List<String> names, List<Point> points, Sink sink) throws IOException,
            InterruptedException {
        ExecutorCompletionService<PointResult> done = new ExecutorCompletionService<>(pool);
        for (Point p : points) {
            done.submit(() -> SceneRun.run(setup, names, p));
        }
        for (int i = 0; i < points.size(); i++) {
            try {
                sink.accept(done.take().get());
            } catch (ExecutionException e) {
                // SceneRun.run turns every expected failure into a status: this is a defect, not a point's fate.
                throw new IllegalStateException("a sweep point failed unexpectedly: " + e.getCause(), e.getCause());
            }
        }
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }
}
