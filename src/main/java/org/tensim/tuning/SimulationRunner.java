package org.tensim.tuning;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.FrameBuffer;
import org.tensim.scene.tunable.ProbeRecorder;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.integrators.IntegratorChoice;
import org.tensim.solver.integrators.Integrators;

/**
 * Runs a scene's simulations on their own thread. Everything that changes the
 * model (parameters, integrator, a new scene) is queued and done on this thread
 * between two steps, so the model is never locked and never changed mid-step;
 * what a change costs beyond that (a scene rebuilt with new constants) is prepared
 * on another thread meanwhile ({@link ViewScene#prepare}), so the steps go on.
 * After every step the {@link FrameBuffer} (for the scene graph) and the
 * {@link ProbeRecorder} (for the chart) copy what they need.
 *
 * <p>When playing, simulated time is paced to wall time (real-time factor 1 at
 * most) unless pacing is off; a simulation slower than real time runs flat out.
 * A {@link SimulationDivergedException} pauses the run and is reported; the last
 * good frame stays on screen.
 */
public final class SimulationRunner implements Tuning.Target {
    /** What the runner reports; called on the simulation thread (hand over to Swing yourself). */
    public interface Events {
        /** A new scene (start, reset, tendon change) is running, with its buffers. */
        void installed(ViewScene scene, FrameBuffer frames, ProbeRecorder probes);

        void diverged(String body, SimulationDivergedException e);

        /** A command failed (e.g. a mesh could not be loaded); the previous scene keeps running. */
        void failed(String what, RuntimeException e);

        /** A warning from a simulation (time step beyond its critical estimate, projection residual...). */
        void warning(String message);
    }

    /** Simulated time between chart samples, s. */
    static final double PROBE_INTERVAL_S = 0.005;
    private static final long BATCH_NANOS = 15_000_000L;
    /**
     * How far simulated time may fall behind wall time before the debt is dropped, s. A stall
     * shorter than this (a garbage collection, a frame that holds the AWT lock, a background
     * refactorisation) is caught up by running flat out for a moment, so a simulation with
     * headroom keeps an average real-time factor of 1; a simulation slower than real time
     * drops its debt instead of racing to catch up forever. At 1 s the diaphragm paced at 0.975 of
     * real time with 1.19 times headroom after one stall of 1.02 s (2026-11-23 23:01 UTC, quiet):
     * the Java3D renderer holds the AWT lock for up to 0.8-1.2 s at times (docs/gui.md).
     */
    private static final double MAX_LAG_S = 2.0;

    private final SceneFactory factory;
    private final Supplier<Settings> settings;
    private final Events events;
    private final ConcurrentLinkedQueue<Runnable> commands = new ConcurrentLinkedQueue<>();
    private final AtomicInteger pendingSteps = new AtomicInteger();
    private final Thread thread;

    private volatile boolean playing;
    private volatile boolean paced = true;
    private volatile boolean stopped;
    private volatile double dt;
    private volatile double simTime;
    private volatile long steps;
    private volatile long unconvergedProjections;
    private volatile double errorEstimate = Double.NaN;
    private volatile String divergence;

    private ViewScene scene; // simulation thread only
    private boolean tensegrityTendon;
    private final CriticalStepWatch critical = new CriticalStepWatch();
    private final BodyThreads threads;
    private final ChangePreparer preparer = new ChangePreparer();
    private long anchorWall;
    private double anchorSim;
    private boolean reanchor = true;

    /**
     * @param factory  makes the scene (on the simulation thread)
     * @param settings the current tuned values, applied to every new scene
     * @param events   receives reports
     * @param threads  threads that share each step of a body (>= 1), or 0 for the automatic rule of
     *                 {@code diaphragm --threads 0} (all cores from 20,000 springs)
     */
    public SimulationRunner(SceneFactory factory, Supplier<Settings> settings, Events events, int threads) {
        this.threads = new BodyThreads(threads);
        this.factory = factory;
        this.settings = settings;
        this.events = events;
        this.dt = settings.get().values().get(Tuning.TIME_STEP);
        this.tensegrityTendon = settings.get().tensegrityTendon();
        thread = new Thread(this::loop, "tensim-simulation");
        thread.setDaemon(true);
    }

    /** Starts the thread with a first scene (made by the factory, at rest), tuned to the current settings. */
    public void start(ViewScene first) {
        install(() -> first);
        thread.start();
    }

    /** Stops the thread and its workers and waits for it (at most 5 s). */
    public void stop() {
        stopped = true;
        LockSupport.unpark(thread);
        try {
            thread.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        critical.close();
        preparer.close();
    }

    public void play() {
        reanchor = true;
        playing = true;
        LockSupport.unpark(thread);
    }

    public void pause() {
        playing = false;
    }

    public boolean isPlaying() {
        return playing;
    }

    /** Makes one step (while paused). */
    public void stepOnce() {
        pendingSteps.incrementAndGet();
        LockSupport.unpark(thread);
    }

    /** A fresh scene at rest with the current settings; the play state is kept. */
    public void reset() {
        rebuild();
    }

    /** Whether simulated time is paced to wall time. */
    public void setPaced(boolean p) {
        reanchor = true;
        paced = p;
    }

    @Override
    public void applyParameter(String key, double value) {
        if (Tuning.TIME_STEP.equals(key)) {
            dt = value;
            commands.add(() -> { });
        } else {
            commands.add(() -> {
                if (scene == null) {
                    return;
                }
                if (restarts(scene, key)) {
                    // Cannot change in a running simulation: a new scene with the value, from rest.
                    rebuild();
                } else {
                    prepare(scene, key, value);
                }
            });
        }
        LockSupport.unpark(thread);
    }

    /**
     * The costly part of a change (ViewScene.prepare: e.g. rebuilding the diaphragm with new
     * constants) is done on the preparing thread while the simulation steps; its hand-over
     * waits for a gap between steps, and is dropped if another scene has been installed since.
     */
    private void prepare(ViewScene s, String key, double value) {
        preparer.submit(s, key, value, rest -> {
            commands.add(() -> {
                if (scene == s) {
                    rest.run();
                    critical.invalidate();
                }
            });
            LockSupport.unpark(thread);
        }, e -> events.failed("change not applied", e));
    }

    @Override
    public void applyIntegrator(IntegratorChoice choice) {
        commands.add(() -> {
            if (scene != null) {
                threads.setIntegrator(choice::create);
                errorEstimate = Double.NaN;
                critical.invalidate();
            }
        });
        LockSupport.unpark(thread);
    }

    @Override
    public void applyTendonModel(boolean tensegrity) {
        commands.add(() -> tensegrityTendon = tensegrity);
        rebuild();
    }

    @Override
    public void applyMuscleLoad(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad load) {
        rebuild(); // the settings carry the new load
    }

    private static boolean restarts(ViewScene s, String key) {
        return s.parameters().stream().anyMatch(p -> p.key().equals(key) && p.restarts());
    }

    private void rebuild() {
        install(() -> factory.create(tensegrityTendon, settings.get().muscleLoad(), settings.get().values()));
    }

    private void install(Supplier<ViewScene> source) {
        commands.add(() -> {
            ViewScene s = source.get();
            Settings now = settings.get();
            IntegratorChoice integrator = Integrators.choices().stream()
                    .filter(c -> c.name().equals(now.integrator())).findFirst()
                    .orElse(Integrators.choices().get(0));
            for (Map.Entry<String, Double> e : now.values().entrySet()) {
                // A parameter the scene lacks (the tendon's boundary under labels) keeps its value for one that has it.
                boolean has = s.parameters().stream().anyMatch(p -> p.key().equals(e.getKey()));
                if (has && !e.getKey().equals(Tuning.TIME_STEP) && !restarts(s, e.getKey())) {
                    s.apply(e.getKey(), e.getValue());
                }
            }
            List<Body> bodies = s.bodies();
            for (Body b : bodies) {
                b.simulation().setIntegrator(integrator.create());
                b.simulation().setWarningSink(m -> events.warning(b.name() + ": " + m));
            }
            threads.attach(bodies);
            FrameBuffer frames = new FrameBuffer(bodies, s.liveState());
            ProbeRecorder probes = new ProbeRecorder(bodies, PROBE_INTERVAL_S, 1 << 14);
            Simulation last = bodies.get(bodies.size() - 1).simulation();
            last.addListener(frames);
            last.addListener(probes);
            scene = s;
            divergence = null;
            simTime = 0;
            steps = 0;
            unconvergedProjections = 0;
            errorEstimate = Double.NaN;
            reanchor = true;
            critical.newScene();
            events.installed(s, frames, probes);
        });
        LockSupport.unpark(thread);
    }

    private void loop() {
        try {
            run();
        } finally {
            threads.close();
        }
    }

    private void run() {
        while (!stopped) {
            Runnable c;
            while ((c = commands.poll()) != null) {
                try {
                    c.run();
                } catch (RuntimeException e) {
                    events.failed("change not applied", e);
                }
            }
            if (scene != null) {
                critical.poll(scene.bodies());
            }
            if (scene == null || divergence != null) {
                pendingSteps.set(0);
                LockSupport.parkNanos(20_000_000L);
                continue;
            }
            int single = pendingSteps.getAndSet(0);
            if (single > 0) {
                for (int i = 0; i < single && advance(); i++) {
                    // one step per request
                }
                continue;
            }
            if (!playing) {
                LockSupport.parkNanos(20_000_000L);
                continue;
            }
            runBatch();
        }
    }

    /** Steps for up to BATCH_NANOS of wall time, paced, then returns so commands are seen. */
    private void runBatch() {
        long now = System.nanoTime();
        if (reanchor) {
            anchorWall = now;
            anchorSim = simTime;
            reanchor = false;
        }
        long end = now + BATCH_NANOS;
        while (playing && commands.isEmpty() && now < end) {
            double wallS = (now - anchorWall) * 1e-9;
            double ahead = (simTime - anchorSim) - wallS;
            if (paced && ahead >= 0) {
                LockSupport.parkNanos(Math.min(2_000_000L, (long) (ahead * 1e9) + 100_000L));
                return;
            }
            if (paced && ahead < -MAX_LAG_S) {
                // Slower than real time: drop the debt rather than racing to catch up.
                anchorWall = now;
                anchorSim = simTime;
            }
            if (!advance()) {
                return;
            }
            now = System.nanoTime();
        }
    }

    /** One step of every body; false (and paused) on divergence. */
    private boolean advance() {
        double h = dt;
        List<Body> bodies = scene.bodies();
        long unconverged = 0;
        double error = Double.NaN;
        for (Body b : bodies) {
            try {
                b.simulation().step(h);
            } catch (SimulationDivergedException e) {
                playing = false;
                divergence = b.name() + ": " + e.getMessage();
                events.diverged(b.name(), e);
                return false;
            }
            unconverged += b.simulation().unconvergedProjections();
            error = ErrorReadout.worse(error, ErrorReadout.of(b.simulation().integrator()));
        }
        errorEstimate = error;
        Simulation last = bodies.get(bodies.size() - 1).simulation();
        unconvergedProjections = unconverged;
        simTime = last.time();
        steps = last.steps();
        return true;
    }

    /** Simulated time, s (any thread). */
    public double simTime() {
        return simTime;
    }

    /** Steps made by each body since the scene was built (any thread). */
    public long steps() {
        return steps;
    }

    /** Current time step, s. */
    public double timeStep() {
        return dt;
    }

    /** The critical time step estimate of the current scene for its integrator, s (infinite: none). */
    public double criticalTimeStep() {
        return critical.criticalStep();
    }

    /**
     * The integrator's own relative error estimate of the last step, the largest over bodies
     * ({@link ErrorReadout}), or NaN when the integrator gives none.
     */
    public double errorEstimate() {
        return errorEstimate;
    }

    /** Threads that share each step of the largest body. */
    public int threads() {
        return threads.threads();
    }

    /** Steps whose rigid-link projection missed its tolerance, summed over bodies. */
    public long unconvergedProjections() {
        return unconvergedProjections;
    }

    /** The divergence message, or null while the run is sound. Cleared by a reset. */
    public String divergence() {
        return divergence;
    }
}
