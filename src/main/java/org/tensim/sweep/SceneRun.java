package org.tensim.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.tensim.experiment.diaphragm.BreathingMetrics;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.integrators.IntegratorChoice;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.TunableScenes;

/**
 * One point of a sweep, run headless on one thread: the scene is made by the GUI's own
 * factory ({@link TunableScenes}) with the point's values applied exactly as the GUI applies
 * them, so that a preset written from a sweep or a calibration reproduces the run in
 * {@code ./tensim gui --preset}. The scene's simulations are stepped with the chosen
 * integrator and time step for the set simulated time.
 *
 * <p>Summary fields: the diaphragm's breathing figures of {@link BreathingMetrics} (last
 * complete cycle; names as in its summary.json), the cube's peak vertical displacements of
 * point P ({@code mss_peak_y_m}, {@code ts_peak_y_m}), and for both {@code steps},
 * {@code dt_s}, {@code simulated_s}, plus the fields of the setup's {@link Measure}s.
 *
 * <p>Time step: the given one, or else the scene's own; for the diaphragm the scene's
 * recommended RK2 step is computed for the default muscle modulus E0, and the highest
 * frequency grows as sqrt(E), so with a stiffer tissue the step is scaled by sqrt(E0 / E).
 *
 * <p>A run is deterministic: the same setup and values give the same bits on every engine.
 */
public final class SceneRun {
    /** Scene factories per geometry, one per JVM: a mesh is read and cleaned once per worker. */
    private static final Map<String, SceneFactory> FACTORIES = new ConcurrentHashMap<>();

    private SceneRun() {
    }

    /** The summary fields a scene can report (before the measures' own), for validating outputs. */
    public static List<String> knownFields(String scene) {
        if (SceneFileRun.isFile(scene)) {
            return SceneFileRun.knownFields(scene);
        }
        List<String> f = new ArrayList<>();
        if (scene.equals("diaphragm")) {
            f.addAll(List.of("dome_excursion_mm", "apex_descent_mm", "ap_extent_change_mm",
                    "transverse_extent_change_mm", "vertical_extent_change_mm", "ap_extent_change_all_nodes_mm",
                    "transverse_extent_change_all_nodes_mm", "thorax_vertical_change_mm", "largest_descent_mm"));
        } else {
            f.addAll(List.of("mss_peak_y_m", "ts_peak_y_m"));
        }
        f.addAll(List.of("steps", "dt_s", "simulated_s"));
        return f;
    }

    /** The tunable parameters of a scene (the GUI's), without building it. */
    public static List<TunableParameter> parameters(String scene) {
        if (SceneFileRun.isFile(scene)) {
            return SceneFileRun.parameters(scene);
        }
        return switch (scene) {
            case "diaphragm" -> DiaphragmViewScene.PARAMETERS;
            case "cube" -> org.tensim.scene.tunable.CubeViewScene.PARAMETERS;
            default -> throw new IllegalArgumentException("scene '" + scene + "' is not a scene; expected one of "
                    + TunableScenes.names());
        };
    }

    /** Runs one point; never throws for a bad value or a divergence (they become the status). */
    public static PointResult run(RunSetup setup, List<String> names, Point point) {
        if (SceneFileRun.isFile(setup.scene())) {
            return SceneFileRun.run(setup, names, point);
        }
        long t0 = System.nanoTime();
        long c0 = cpu();
        Map<String, Double> fields = new LinkedHashMap<>();
        Map<String, Double> values = new LinkedHashMap<>(setup.fixed());
        for (int i = 0; i < names.size(); i++) {
            values.put(names.get(i), point.values()[i]);
        }
        ViewScene scene;
        IntegratorChoice integrator;
        try {
            for (Map.Entry<String, Double> e : values.entrySet()) {
                parameter(setup.scene(), e.getKey()).validate(e.getValue(), "point " + point.id());
            }
            integrator = Integrators.choice(setup.integrator());
            scene = factory(setup).create(true, values);
            for (TunableParameter p : scene.parameters()) {
                if (!p.restarts() && values.containsKey(p.key())) {
                    scene.apply(p.key(), values.get(p.key()));
                }
            }
        } catch (RuntimeException e) {
            return new PointResult(point.id(), point.values(), PointResult.REFUSED, message(e), fields, wall(t0),
                    cpuSince(c0));
        }
        double dt = setup.dtS() > 0 ? setup.dtS() : defaultStep(scene, values);
        List<Simulation> sims = new ArrayList<>();
        for (Body b : scene.bodies()) {
            b.simulation().setIntegrator(integrator.create());
            sims.add(b.simulation());
        }
        Observer obs = scene instanceof DiaphragmViewScene d ? new DiaphragmObserver(d, setup)
                : new CubeObserver(scene.bodies());
        String status = PointResult.OK;
        String message = "";
        Simulation first = sims.get(0);
        try {
            obs.afterStep(first);
            while (first.time() < setup.seconds() - 0.5 * dt) {
                for (Simulation s : sims) {
                    s.step(dt);
                }
                obs.afterStep(first);
            }
        } catch (SimulationDivergedException e) {
            status = PointResult.DIVERGED;
            message = message(e);
        } catch (RuntimeException e) {
            // e.g. a rigid-link projection that cannot converge: the run failed, the sweep goes on
            status = PointResult.DIVERGED;
            message = message(e);
        }
        obs.finish(fields);
        fields.put("steps", (double) first.steps());
        fields.put("dt_s", dt);
        fields.put("simulated_s", first.time());
        return new PointResult(point.id(), point.values(), status, message, fields, wall(t0), cpuSince(c0));
    }

    /** The named parameter of a scene, or an exception naming the known ones. */
    public static TunableParameter parameter(String scene, String key) {
        for (TunableParameter p : parameters(scene)) {
            if (p.key().equals(key)) {
                return p;
            }
        }
        throw new IllegalArgumentException("'" + key + "' is not a parameter of scene '" + scene + "'; known: "
                + parameters(scene).stream().map(TunableParameter::key).toList());
    }

    private static double defaultStep(ViewScene scene, Map<String, Double> values) {
        double dt = scene.defaultTimeStep();
        Double e = values.get(DiaphragmViewScene.TISSUE_STIFFNESS);
        double e0 = DiaphragmParameters.defaults().muscleYoungPa();
        return scene instanceof DiaphragmViewScene && e != null && e > e0 ? dt * Math.sqrt(e0 / e) : dt;
    }

    private static SceneFactory factory(RunSetup s) {
        String key = s.scene() + "|" + String.join("\u0000", s.diaphragm());
        return FACTORIES.computeIfAbsent(key, k -> TunableScenes.factory(s.scene(),
                org.tensim.tuning.DiaphragmOptions.parse(s.diaphragm())));
    }

    static String message(Throwable e) {
        String m = e.getMessage();
        return m == null ? e.getClass().getSimpleName() : m;
    }

    static long cpu() {
        java.lang.management.ThreadMXBean b = java.lang.management.ManagementFactory.getThreadMXBean();
        return b.isCurrentThreadCpuTimeSupported() ? b.getCurrentThreadCpuTime() : -1;
    }

    static double cpuSince(long c0) {
        return c0 < 0 ? Double.NaN : (cpu() - c0) / 1e9;
    }

    static double wall(long t0) {
        return (System.nanoTime() - t0) / 1e9;
    }

    /** What is measured during a run. */
    private interface Observer {
        void afterStep(Simulation sim);

        void finish(Map<String, Double> fields);
    }

    /** The breathing figures and the setup's measures. */
    private static final class DiaphragmObserver implements Observer {
        private final BreathingMetrics metrics;
        private final List<Measure.Probe> probes = new ArrayList<>();

        DiaphragmObserver(DiaphragmViewScene view, RunSetup setup) {
            DiaphragmScene scene = view.scene();
            metrics = new BreathingMetrics(scene, Math.max(setup.seconds(), scene.cycle().inspirationS()));
            int nd = scene.diaphragmNodes();
            boolean[] upper = new boolean[nd];
            for (int v = 0; v < nd; v++) {
                upper[v] = scene.surfaces().isUpper(v);
            }
            Simulation sim = view.bodies().get(0).simulation();
            Measure.DiaphragmRunView run = new Measure.DiaphragmRunView(sim.state().x0.clone(), nd,
                    scene.allTriangles(), upper);
            for (Measure m : setup.measures()) {
                probes.add(m.start(run));
            }
        }

        @Override
        public void afterStep(Simulation sim) {
            metrics.afterStep(sim);
            for (Measure.Probe p : probes) {
                p.afterStep(sim.time(), sim.state().x);
            }
        }

        @Override
        public void finish(Map<String, Double> fields) {
            fields.putAll(metrics.fields());
            for (Measure.Probe p : probes) {
                p.finish(fields);
            }
        }
    }

    /** The most negative vertical displacement of each cube's probe (point P). */
    private static final class CubeObserver implements Observer {
        private final List<Body> bodies;
        private final double[] peak;
        private final double[] d = new double[3];

        CubeObserver(List<Body> bodies) {
            this.bodies = bodies;
            this.peak = new double[bodies.size()];
        }

        @Override
        public void afterStep(Simulation ignored) {
            for (int b = 0; b < bodies.size(); b++) {
                bodies.get(b).simulation().state().displacement(bodies.get(b).probeNode(), d);
                peak[b] = Math.min(peak[b], d[1]);
            }
        }

        @Override
        public void finish(Map<String, Double> fields) {
            fields.put("mss_peak_y_m", peak[0]);
            fields.put("ts_peak_y_m", peak[1]);
        }
    }
}
