package org.tensim.app.gui;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import org.tensim.scene.tunable.Body;
import org.tensim.solver.SystemState;
import org.tensim.tuning.SimulationRunner;

/**
 * {@code gui --run-for S}: plays the window for S seconds of wall time once its
 * view shows (longer only if no step was done by then: until the first step, at
 * most 10 minutes), closes it, and returns what was measured, so that the window can be
 * checked headless (under Xvfb) and its speed compared between configurations.
 *
 * <p>Measured over the S seconds (after the window is up and the first frames are
 * drawn, so start-up is excluded and reported apart): the real-time factor
 * (simulated over wall seconds), steps per second, frames the 3D view drew per
 * second, and the pictures with a new simulated frame per second (sampled from the
 * view every 4 ms, so a lower bound). The Swing thread is probed every 20 ms: its
 * longest delay says whether the window ever froze.
 */
final class TimedRun {
    private static final int EDT_PROBE_MS = 20;

    private TimedRun() {
    }

    /**
     * Runs the window for {@code seconds} of wall time and closes it.
     *
     * @param paced      false unticks "Real time": as fast as possible
     * @param screenshot PNG of the window saved at the end, or null
     * @param startNanos when the command started (System.nanoTime), for the start-up time
     * @return the summary, one flat map (NaN values as null)
     */
    static Map<String, Object> run(GuiWindow w, double seconds, boolean paced, Path screenshot, long startNanos)
            throws Exception {
        long deadline = System.nanoTime() + 600_000_000_000L;
        while ((w.scene() == null || w.view().framesRendered() < 3) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        double startupS = (System.nanoTime() - startNanos) * 1e-9;
        double loadBefore = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        AtomicLong edtWorstNanos = new AtomicLong();
        AtomicLong edtWorstAt = new AtomicLong();
        AtomicReference<Timer> probe = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            w.controls().setPaced(paced);
            w.play(true);
            w.controls().showPlaying(true);
            long[] last = {System.nanoTime(), System.nanoTime()};
            Timer t = new Timer(EDT_PROBE_MS, e -> {
                long now = System.nanoTime();
                long late = now - last[0] - EDT_PROBE_MS * 1_000_000L;
                if (late > edtWorstNanos.get()) {
                    edtWorstNanos.set(late);
                    edtWorstAt.set(now - last[1]);
                }
                last[0] = now;
            });
            t.start();
            probe.set(t);
        });
        SimulationRunner r = w.runner();
        long cpu0 = processCpuNanos();
        long t0 = System.nanoTime();
        double sim0 = r.simTime();
        long steps0 = r.steps();
        long frames0 = w.view().framesRendered();
        long shownStep = w.view().shownStep();
        long pictures = 0;
        long end = t0 + (long) (seconds * 1e9);
        long stepDeadline = t0 + 600_000_000_000L;
        // Past S, play on until the first step is done (a summary of no step says nothing), within 10 minutes.
        while ((System.nanoTime() < end || (r.steps() == steps0 && System.nanoTime() < stepDeadline))
                && r.divergence() == null) {
            Thread.sleep(4);
            long s = w.view().shownStep();
            if (s != shownStep) {
                pictures++;
                shownStep = s;
            }
        }
        double wall = (System.nanoTime() - t0) * 1e-9;
        double cpu = (processCpuNanos() - cpu0) * 1e-9;
        double sim = r.simTime() - sim0;
        long steps = r.steps() - steps0;
        long frames = w.view().framesRendered() - frames0;
        AtomicReference<Exception> error = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            probe.get().stop();
            if (screenshot != null) {
                try {
                    w.saveScreenshot(screenshot);
                } catch (Exception e) {
                    error.set(e);
                }
            }
        });
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("scene", w.tuning().scene());
        int nodes = 0;
        int springs = 0;
        int links = 0;
        for (Body b : w.scene().bodies()) {
            SystemState st = b.simulation().state();
            nodes += st.nodeCount;
            springs += st.springCount();
            links += st.linkCount();
        }
        m.put("nodes", nodes);
        // The organs' share of the simulated nodes (the lungs and the liver, with their anchors): their cost.
        m.put("organ_nodes", w.scene().organNodes());
        int drawn = 0;
        for (int b : w.scene().organBodies()) {
            drawn += w.scene().bodies().get(b).nodeCount();
        }
        m.put("organ_drawn_vertices", drawn);
        org.tensim.scene.tunable.ViewScene.Resolution res = w.scene().resolution();
        if (res != null) {
            m.put("drawn_nodes", res.drawnNodes());
            m.put("mechanical_nodes", res.mechanicalNodes());
            m.put("resolution_error", finiteOrNull(res.error()));
        }
        m.put("springs", springs);
        m.put("rigid_links", links);
        m.put("integrator", w.tuning().integrator().name());
        m.put("dt_s", r.timeStep());
        m.put("threads", r.threads());
        m.put("paced", paced);
        m.put("realtime_factor", round(sim / wall, 4));
        m.put("fps", round(frames / wall, 1));
        m.put("fps_cap", w.view().frameCap());
        m.put("new_pictures_per_s", round(pictures / wall, 1));
        m.put("steps_per_s", round(steps / wall, 1));
        m.put("error_estimate", finiteOrNull(r.errorEstimate()));
        m.put("edt_longest_delay_ms", round(edtWorstNanos.get() * 1e-6, 1));
        m.put("edt_longest_delay_at_s", round(edtWorstAt.get() * 1e-9, 2));
        m.put("diverged", r.divergence());
        m.put("wall_s", round(wall, 3));
        // On a shared machine: what the process got (simulation, drawing in Mesa's llvmpipe, Swing).
        m.put("process_cpu_s", round(cpu, 2));
        m.put("sim_s_per_process_cpu_s", cpu > 0 ? round(sim / cpu, 4) : null);
        m.put("sim_s", round(sim, 4));
        m.put("steps", steps);
        m.put("frames", frames);
        m.put("startup_s", round(startupS, 2));
        m.put("cores", Runtime.getRuntime().availableProcessors());
        m.put("load_average_before", round(loadBefore, 2));
        m.put("load_average_after",
                round(ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), 2));
        if (screenshot != null) {
            m.put("screenshot", screenshot.toAbsolutePath().toString());
        }
        // The scene's live readouts at the end (the diaphragm's dome descent, contact area...), null where unmeasured.
        SwingUtilities.invokeAndWait(() -> w.live().shownValues().forEach((k, v) -> m.put(k,
                Double.isFinite(v) ? round(v, 3) : null)));
        SwingUtilities.invokeAndWait(w::close);
        if (error.get() != null) {
            throw new java.io.IOException("cannot save screenshot " + screenshot + ": " + error.get().getMessage(),
                    error.get());
        }
        return m;
    }

    /** CPU time of this process, every thread, ns (-1 where the JVM does not tell). */
    private static long processCpuNanos() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() : -1;
    }

    private static Object finiteOrNull(double v) {
        return Double.isFinite(v) ? v : null;
    }

    private static double round(double v, int digits) {
        double f = Math.pow(10, digits);
        return Math.round(v * f) / f;
    }
}
