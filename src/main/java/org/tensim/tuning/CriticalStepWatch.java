package org.tensim.tuning;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicBoolean;
import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.Integrator;
import org.tensim.solver.SystemState;
import org.tensim.scene.tunable.Body;

/**
 * The critical time step of the running scene for its integrators (for the status
 * bar's warning), estimated on a background thread: the power iteration of
 * {@link CriticalTimeStep#estimate} costs hundreds of force passes on a large scene,
 * which on the simulation thread stalled the run after every stiffness change.
 *
 * <p>The simulation thread calls {@link #invalidate} after a change and
 * {@link #poll} between steps; an estimate starts at most every 0.3 s (a slider drag
 * sends many changes) and one at a time. The estimate reads the stiffness and rest
 * positions while the simulation steps; a change made meanwhile leaves the watch
 * stale, so the value is estimated again. Implicit integrators have no critical
 * step: nothing is estimated for them.
 */
final class CriticalStepWatch {
    private static final long MIN_INTERVAL_NANOS = 300_000_000L;

    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "tensim-critical-step");
        t.setDaemon(true);
        t.setPriority(Thread.MIN_PRIORITY);
        return t;
    });
    private final AtomicBoolean busy = new AtomicBoolean();
    private volatile double criticalStep = Double.POSITIVE_INFINITY;
    private volatile int generation;
    private boolean stale = true;
    private long startedAt;

    /** A new scene: the current value no longer applies (simulation thread). */
    void newScene() {
        generation++;
        criticalStep = Double.POSITIVE_INFINITY;
        stale = true;
        startedAt = 0;
    }

    /** Stiffness or integrator changed (simulation thread). */
    void invalidate() {
        stale = true;
    }

    /** Starts an estimate of the bodies' smallest critical step when one is due (simulation thread). */
    void poll(List<Body> bodies) {
        long now = System.nanoTime();
        if (!stale || busy.get() || now - startedAt < MIN_INTERVAL_NANOS) {
            return;
        }
        stale = false;
        startedAt = now;
        List<SystemState> states = new ArrayList<>();
        List<Integrator> integrators = new ArrayList<>();
        for (Body b : bodies) {
            if (b.simulation().integrator().explicit()) {
                states.add(b.simulation().state());
                integrators.add(b.simulation().integrator());
            }
        }
        if (states.isEmpty()) {
            criticalStep = Double.POSITIVE_INFINITY;
            return;
        }
        int gen = generation;
        busy.set(true);
        worker.execute(() -> {
            try {
                double c = Double.POSITIVE_INFINITY;
                for (int i = 0; i < states.size(); i++) {
                    SystemState st = states.get(i);
                    Integrator in = integrators.get(i);
                    CriticalTimeStep e = st.estimateCriticalTimeStep();
                    c = Math.min(c, e.forMethod(in.explicit(), in.undampedStabilityLimit()));
                }
                if (gen == generation) {
                    criticalStep = c;
                }
            } finally {
                busy.set(false);
            }
        });
    }

    /** The latest estimate, s (infinite: none, or an implicit integrator). Any thread. */
    double criticalStep() {
        return criticalStep;
    }

    /** Stops the background thread. */
    void close() {
        worker.shutdownNow();
    }
}
