package org.tensim.tuning;

import java.util.ArrayList;
import java.util.List;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.scene.tunable.Body;

/**
 * The worker threads of the running scene's bodies: each body large enough gets
 * a {@link Parallelism} (its force pass, link sweeps and, for RK2 and symplectic
 * Euler, its node loops on several threads), with the rule of
 * {@code diaphragm --threads 0} ({@link Parallelism#automaticThreads(int)}) unless a
 * count is given. Used on the simulation thread only.
 *
 * <p>Parallelism swaps the integrator for its parallel twin when it is installed, so
 * an integrator change goes through {@link #setIntegrator}: uninstall, set, install.
 */
final class BodyThreads {
    private final int requested;
    private final List<Simulation> sims = new ArrayList<>();
    private final List<Parallelism> installed = new ArrayList<>();
    private volatile int threads = 1;

    /** @param requested threads per body (>= 1), or 0 for the automatic rule */
    BodyThreads(int requested) {
        if (requested < 0) {
            throw new IllegalArgumentException("--threads must be 0 (automatic) or more, got " + requested);
        }
        this.requested = requested;
    }

    /** Puts the bodies of a new scene on threads; the previous scene's threads are stopped. */
    void attach(List<Body> bodies) {
        close();
        for (Body b : bodies) {
            Simulation s = b.simulation();
            sims.add(s);
            installed.add(install(s));
        }
    }

    /** Gives every body a new integrator from the factory, keeping the threads. */
    void setIntegrator(java.util.function.Supplier<Integrator> factory) {
        for (int i = 0; i < sims.size(); i++) {
            Simulation s = sims.get(i);
            if (installed.get(i) != null) {
                installed.get(i).close();
            }
            s.setIntegrator(factory.get());
            installed.set(i, install(s));
        }
    }

    private Parallelism install(Simulation s) {
        int n = requested > 0 ? requested : Parallelism.automaticThreads(s.state().springCount());
        threads = Math.max(threads, n);
        return n > 1 ? Parallelism.install(s, n) : null;
    }

    /** Threads that share each step of the largest body (1: single-threaded). */
    int threads() {
        return threads;
    }

    /** Stops every worker and restores the single-threaded loops. */
    void close() {
        for (Parallelism p : installed) {
            if (p != null) {
                p.close();
            }
        }
        installed.clear();
        sims.clear();
        threads = 1;
    }
}
