package org.tensim.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.tensim.experiment.SceneExpectations;
import org.tensim.experiment.SceneRunner;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneProbe;
import org.tensim.scene.tunable.FileViewScene;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * One point of a sweep or a calibration over a scene file ({@code "scene": "liver.yaml"}, docs/scenes.md): the
 * file loaded with the spec's overrides, then its fixed values and the point's as {@code --set NAME=VALUE} (in
 * the named parameters' units, range checked by the loader), run headless as {@code tensim run} runs it (its
 * bodies in lockstep, the probes sampled every {@code run.every} steps) with the setup's integrator, step and
 * simulated time. Summary fields: each probe column's {@code _min}, {@code _max}, {@code _final} and
 * {@code _mean} (e.g. {@code sag_mean_dz_m_min}), then {@code steps}, {@code dt_s}, {@code simulated_s}. A run is
 * deterministic: the same setup and values give the same bits on every engine.
 */
public final class SceneFileRun {
    /** The statistics of each column, in field order. */
    static final List<String> STATS = List.of("min", "max", "final", "mean");
    /** Scene files loaded without the points' values (for their parameters and columns), by path. */
    private static final Map<String, Scene> FILES = new ConcurrentHashMap<>();

    private SceneFileRun() {
    }

    /** Whether a setup's scene names a scene file (.yaml, .yml or .json) rather than a built-in scene. */
    public static boolean isFile(String scene) {
        String s = scene.toLowerCase(Locale.ROOT);
        return s.endsWith(".yaml") || s.endsWith(".yml") || s.endsWith(".json");
    }

    /** The file loaded with these overrides (SceneException for a file it refuses), kept for later lookups. */
    public static Scene load(String file, List<String> overrides) {
        Scene s = SceneLoader.load(Path.of(file), overrides);
        FILES.putIfAbsent(file, s);
        return s;
    }

    private static Scene scene(String file) {
        return FILES.computeIfAbsent(file, f -> SceneLoader.load(Path.of(f)));
    }

    /** The file's named parameters, as sweeps and calibrations name them. */
    static List<TunableParameter> parameters(String file) {
        return FileViewScene.controls(scene(file));
    }

    /** The summary fields of a run of the file. */
    static List<String> knownFields(String file) {
        List<String> f = new ArrayList<>();
        List<String> header = SceneExpectation.columns(scene(file).probes());
        for (String c : header.subList(1, header.size())) {
            for (String st : STATS) {
                f.add(c + "_" + st);
            }
        }
        f.addAll(List.of("steps", "dt_s", "simulated_s"));
        return f;
    }

    /** Runs one point; never throws for a refused value or a divergence (they become the status). */
    static PointResult run(RunSetup setup, List<String> names, Point point) {
        long t0 = System.nanoTime();
        long c0 = SceneRun.cpu();
        Map<String, Double> fields = new LinkedHashMap<>();
        List<String> sets = new ArrayList<>(setup.overrides());
        for (Map.Entry<String, Double> e : setup.fixed().entrySet()) {
            sets.add(e.getKey() + "=" + e.getValue());
        }
        for (int i = 0; i < names.size(); i++) {
            // Double.toString reads back to the same bits: every engine loads the same value.
            sets.add(names.get(i) + "=" + point.values()[i]);
        }
        Scene scene;
        Map<String, Simulation> sims = new LinkedHashMap<>();
        try {
            scene = org.tensim.scene.file.CoupledBodies.merge(SceneLoader.load(Path.of(setup.scene()), sets));
            String integrator = setup.integrator() != null ? setup.integrator() : scene.run().integrator();
            for (SceneBody b : scene.bodies().values()) {
                Simulation sim = new Simulation(SystemState.compile(b.topology()), Integrators.create(integrator));
                org.tensim.scene.file.CoupledBodies.addTerms(b, sim);
                sims.put(b.name(), sim);
            }
        } catch (RuntimeException e) {
            return new PointResult(point.id(), point.values(), PointResult.REFUSED, SceneRun.message(e), fields,
                    SceneRun.wall(t0), SceneRun.cpuSince(c0));
        }
        double dt = setup.dtS() > 0 ? setup.dtS() : scene.run().dtS();
        long steps = Math.round(setup.seconds() / dt);
        List<String> header = SceneExpectation.columns(scene.probes());
        SceneExpectations.Columns stats = new SceneExpectations.Columns(header);
        double[] row = new double[header.size()];
        Simulation clock = sims.values().iterator().next();
        String status = PointResult.OK;
        String message = "";
        long made = 0;
        Map<SceneProbe, int[]> springs = SceneRunner.energySprings(scene, sims);
        try {
            SceneRunner.sample(scene, sims, springs, 0, row);
            stats.add(row);
            for (long i = 1; i <= steps; i++) {
                for (Simulation s : sims.values()) {
                    s.step(dt);
                }
                made = i;
                if (i % scene.run().every() == 0) {
                    SceneRunner.sample(scene, sims, springs, clock.time(), row);
                    stats.add(row);
                }
            }
        } catch (SimulationDivergedException e) {
            status = PointResult.DIVERGED;
            message = SceneRun.message(e);
        } catch (RuntimeException e) {
            // e.g. a rigid-link projection that cannot converge: the run failed, the sweep goes on
            status = PointResult.DIVERGED;
            message = SceneRun.message(e);
        }
        for (int c = 1; c < header.size(); c++) {
            for (String st : STATS) {
                fields.put(header.get(c) + "_" + st, stats.value(header.get(c), st));
            }
        }
        fields.put("steps", (double) made);
        fields.put("dt_s", dt);
        fields.put("simulated_s", clock.time());
        return new PointResult(point.id(), point.values(), status, message, fields, SceneRun.wall(t0),
                SceneRun.cpuSince(c0));
    }
}
