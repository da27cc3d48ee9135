package org.tensim.tuning;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import org.tensim.scene.tunable.ViewScene;

/**
 * Prepares parameter changes on a background thread, in the order they were made,
 * one at a time ({@link ViewScene#prepare}: e.g. the diaphragm rebuilt with new
 * constants), while the simulation keeps stepping; what is left of each change is
 * handed back for the simulation thread.
 */
final class ChangePreparer {
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "tensim-prepare-change");
        t.setDaemon(true);
        return t;
    });

    /**
     * Prepares {@code key = value} on scene s in the background.
     *
     * @param handOver receives the rest of the change, to run on the simulation thread
     * @param failed   receives a change that could not be prepared
     */
    void submit(ViewScene s, String key, double value, Consumer<Runnable> handOver, Consumer<RuntimeException> failed) {
        worker.execute(() -> {
            Runnable rest;
            try {
                rest = s.prepare(key, value);
            } catch (RuntimeException e) {
                failed.accept(e);
                return;
            }
            handOver.accept(rest);
        });
    }

    /** Stops the background thread; changes not yet prepared are dropped. */
    void close() {
        worker.shutdownNow();
    }
}
