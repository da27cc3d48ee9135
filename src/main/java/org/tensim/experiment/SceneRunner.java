package org.tensim.experiment;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.CsvWriter;
import org.tensim.io.FileDigest;
import org.tensim.io.Progress;
import org.tensim.io.RunFolder;
import org.tensim.io.RunSignals;
import org.tensim.io.RunStatus;
import org.tensim.scene.file.RunSettings;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * Runs a loaded {@link Scene} headless: each body is its own {@link Simulation}, all stepped in lockstep with
 * the run's integrator and step; after the start and after every {@code every}-th step one CSV row holds the time
 * ({@code t_s}, the first body's clock) and every probe's values. The summary holds the scene file and its digest,
 * every {@code --set}, the run's settings, each body's node count and each CSV column's minimum and maximum, then,
 * for a scene with an {@code expect:} block, each check's measured value and verdict ({@link SceneExpectations}).
 * A body that diverges ends the run with status "diverged"; the CSV keeps the rows written. A run that ends but
 * fails a check has status "expectation_failed" (exit code 3), its outputs kept.
 */
public final class SceneRunner {
    private SceneRunner() {
    }

    /** Runs the scene with {@code run} (the file's settings, possibly overridden) into the run folder. */
    public static Map<String, Object> run(Scene scene, RunSettings run, RunFolder folder) throws IOException {
        List<SceneBody> bodies = new ArrayList<>(scene.bodies().values());
        Map<String, Simulation> sims = new LinkedHashMap<>();
        for (SceneBody b : bodies) {
            sims.put(b.name(), new Simulation(SystemState.compile(b.topology()), Integrators.create(run.integrator())));
        }
        List<String> header = SceneExpectation.columns(scene.probes());
        double[] row = new double[header.size()];
        SceneExpectations.Columns stats = new SceneExpectations.Columns(header);
        Simulation clock = sims.values().iterator().next();
        long steps = run.steps();
        long made = 0;
        SimulationDivergedException diverged = null;
        try (CsvWriter w = folder.csv(run.csv(), header, 1000)) {
            Progress progress = Progress.start("run", run.durationS());
            sample(scene, sims, 0, row);
            stats.add(row);
            w.row(row);
            for (long i = 1; i <= steps; i++) {
                RunSignals.checkStop();
                for (Simulation s : sims.values()) {
                    s.step(run.dtS());
                }
                made = i;
                if (i % run.every() == 0) {
                    sample(scene, sims, clock.time(), row);
                    stats.add(row);
                    w.row(row);
                }
                progress.update(clock.time());
            }
            progress.close();
        } catch (SimulationDivergedException e) {
            diverged = e;
        }
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("scene", scene.file().toString());
        s.put("scene_digest", FileDigest.of(List.of(scene.file())));
        s.put("overrides", scene.overrides());
        s.put("integrator", run.integrator());
        s.put("dt_s", run.dtS());
        s.put("duration_s", run.durationS());
        s.put("steps", made);
        Map<String, Object> nodes = new LinkedHashMap<>();
        for (SceneBody b : bodies) {
            nodes.put(b.name(), b.topology().nodeCount());
        }
        s.put("body_nodes", nodes);
        Map<String, Object> range = new LinkedHashMap<>();
        for (int c = 1; c < header.size(); c++) {
            range.put(header.get(c), Map.of("min", finite(stats.min(c)), "max", finite(stats.max(c))));
        }
        s.put("columns", range);
        if (diverged != null) {
            s.put("diverged", diverged.getMessage());
            s.put("diverged_at_s", diverged.timeSeconds());
        }
        RunStatus status = diverged == null ? RunStatus.OK : RunStatus.DIVERGED;
        if (!scene.expect().isEmpty()) {
            List<Map<String, Object>> outcomes = SceneExpectations.evaluate(scene.expect(), stats, s);
            long failed = SceneExpectations.failed(outcomes);
            s.put("expectations", outcomes);
            s.put("expectations_failed", failed);
            if (failed > 0 && status == RunStatus.OK) {
                status = RunStatus.EXPECTATION_FAILED;
            }
        }
        return folder.finish(status, s);
    }

    private static Object finite(double v) {
        return Double.isFinite(v) ? v : "none";
    }

    /**
     * One CSV row of the scene's probes ({@link SceneExpectation#columns}) at time t: the time, then every
     * probe's values from the bodies' simulations (by body name).
     */
    public static void sample(Scene scene, Map<String, Simulation> sims, double t, double[] row) {
        row[0] = t;
        int c = 1;
        double[] d = new double[3];
        for (SceneProbe p : scene.probes()) {
            SystemState st = sims.get(p.body()).state();
            if (p.quantity().equals("extents")) {
                for (int a = 0; a < 3; a++) {
                    double lo = Double.POSITIVE_INFINITY;
                    double hi = Double.NEGATIVE_INFINITY;
                    for (int n : p.nodes()) {
                        lo = Math.min(lo, st.position(n, a));
                        hi = Math.max(hi, st.position(n, a));
                    }
                    row[c++] = lo;
                    row[c++] = hi;
                }
            } else if (p.nodes().length == 1 && p.quantity().equals("displacement")) {
                st.displacement(p.nodes()[0], d);
                row[c++] = d[0];
                row[c++] = d[1];
                row[c++] = d[2];
            } else {
                // A region's mean, or a surface vertex's weighted sum over the nodes carrying it.
                double[] sum = new double[3];
                for (int i = 0; i < p.nodes().length; i++) {
                    st.displacement(p.nodes()[i], d);
                    double w = p.weights() == null ? 1 : p.weights()[i];
                    sum[0] += w * d[0];
                    sum[1] += w * d[1];
                    sum[2] += w * d[2];
                }
                for (int a = 0; a < 3; a++) {
                    row[c++] = p.weights() == null ? sum[a] / p.nodes().length : sum[a];
                }
            }
        }
    }
}
