package org.tensim.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.experiment.diaphragm.ResolutionStudy;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.parallel.Parallelism;

/**
 * What reaches real time, and at what accuracy: the diaphragm at several
 * resolutions (the resolution study's ring counts) with several integrators and
 * time steps, each run through one inspiration with the scene-graph sync of the
 * GUI after every step, timed, and compared with the paper's configuration (RK2 at
 * the scene's stable step, 43 rings: the reference).
 *
 * <p>Speed: the real-time factor is simulated seconds per wall second of the
 * stepping loop (steps, projection, listeners, sync), and also per CPU second of
 * the stepping thread(s), which a shared machine disturbs less. Accuracy: the
 * relative RMS difference of the upper surface's displacement at the end of the
 * run against the reference, by nearest node ({@link ResolutionStudy#error}), and
 * the apex's descent.
 *
 * <p>Configurations: the paper's RK2 at the scene's stable step (1 and 2 threads;
 * and with the sternum's node mass scaled, which lifts the sternum's limit on the
 * step at coarse resolutions), and implicit Euler at 5, 10 and 20 ms with a CG
 * tolerance of 1e-3 (a larger step than RK2's stability allows; the CG solve is
 * the price). Each run is also compared with the paper's RK2 at its own
 * resolution, which separates the integrator's error from the resolution's.
 */
public final class RealTimeStudy {
    /** Ring counts; the last one is the paper's resolution and holds the reference. */
    static final int[] RINGS = {10, 14, 20, 28, 43};
    /** Implicit Euler steps tried, s. */
    static final double[] IMPLICIT_STEPS = {0.005, 0.01, 0.02};
    /** CG relative residual for the implicit steps: 1e-2 and 1e-3 gave the same field to 4 digits here. */
    static final double CG_TOLERANCE = 1e-3;

    /**
     * Selective mass scaling of the sternum nodes in the scaled configuration: x10 (20 g to 200 g a node).
     * The sternum moves with the ribs, a few millimetres over an inspiration: its inertial force at 200 g
     * is of the order of 0.2 kg x 0.02 m/s^2 = 4 mN, against attachment springs of 100 N/m stretched by
     * millimetres (0.1 N each, hundreds of them). The scaling is checked by the error against the same
     * resolution without it.
     */
    static final double STERNUM_MASS_SCALE = 10;

    /**
     * One setting: name as shown, integrator factory, time step (0: the scene's RK2 step), threads, and
     * whether the sternum's node mass is scaled ({@link #STERNUM_MASS_SCALE}).
     */
    record Config(String label, Supplier<Integrator> integrator, double dt, int threads, boolean scaledSternum) {
    }

    private RealTimeStudy() {
    }

    static List<Config> configs() {
        List<Config> c = new ArrayList<>();
        c.add(new Config("rk2 at the stable step / 1 thread", () -> Integrators.create("rk2"), 0, 1, false));
        c.add(new Config("rk2 at the stable step / 2 threads", () -> Integrators.create("rk2"), 0, 2, false));
        c.add(new Config("rk2 at the stable step / sternum mass x10 / 1 thread", () -> Integrators.create("rk2"), 0,
                1, true));
        for (double h : IMPLICIT_STEPS) {
            c.add(new Config(String.format(Locale.ROOT, "implicit-euler at %.0f ms / 1 thread", 1e3 * h),
                    () -> new ImplicitEuler().setTolerance(CG_TOLERANCE), h, 1, false));
        }
        return c;
    }

    /**
     * Runs every configuration at every resolution, writes {@code realtime.csv},
     * {@code realtime.json} and {@code realtime.png} to {@code out}, and returns the summary.
     *
     * @param seconds simulated time per run, s (capped at one inspiration)
     */
    public static Map<String, Object> run(Path boxes, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls, double seconds, Path out, PrintStream log) throws IOException {
        return run(RINGS, boxes, p, cycle, controls, seconds, out, log);
    }

    /** As {@link #run(Path, DiaphragmParameters, BreathingCycle, DiaphragmControls, double, Path, PrintStream)}
     * at the given ring counts (ascending; the last one holds the reference). */
    static Map<String, Object> run(int[] ringCounts, Path boxes, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls, double seconds, Path out, PrintStream log) throws IOException {
        Files.createDirectories(out);
        double runS = Math.min(seconds, cycle.inspirationS());
        List<Config> configs = configs();
        DiaphragmParameters scaled = p.withStructureNodeMass(STERNUM_MASS_SCALE * p.structureNodeMassKg());
        List<Map<String, Object>> rows = new ArrayList<>();
        ResolutionStudy.Run reference = null;
        try (CsvWriter csv = new CsvWriter(out.resolve("realtime.csv"), List.of("rings", "nodes", "springs",
                "config", "dt_s", "realtime_factor", "realtime_factor_cpu", "apex_descent_mm", "cg_products_per_step",
                "relative_rms_error", "error_vs_rk2_same_resolution"), 1)) {
            // Finest first: the reference is the first run, and a long study can be read as it goes.
            for (int i = ringCounts.length - 1; i >= 0; i--) {
                int rings = ringCounts[i];
                DiaphragmScene scene = DiaphragmSetup.generated(rings, boxes, p, cycle, controls).scene();
                DiaphragmScene scaledScene = DiaphragmSetup.generated(rings, boxes, scaled, cycle, controls).scene();
                ResolutionStudy.Run own = null; // the paper's RK2 (the first configuration) at this resolution
                for (Config c : configs) {
                    double[] tm = new double[5];
                    ResolutionStudy.Run r = simulate(c.scaledSternum() ? scaledScene : scene, rings, c, runS, tm);
                    reference = reference == null ? r : reference;
                    own = own == null ? r : own;
                    double e = r == reference ? 0 : ResolutionStudy.error(reference, r);
                    double eOwn = r == own ? 0 : ResolutionStudy.error(own, r);
                    Map<String, Object> row = new LinkedHashMap<>();
                    row.put("rings", rings);
                    row.put("nodes", r.nodes());
                    row.put("springs", r.springs());
                    row.put("config", c.label());
                    row.put("threads", c.threads());
                    row.put("dt_s", r.dt());
                    row.put("realtime_factor", DiaphragmReport.round(tm[0], 4));
                    row.put("realtime_factor_cpu", DiaphragmReport.round(tm[1], 4));
                    row.put("apex_descent_mm", DiaphragmReport.round(tm[2], 3));
                    row.put("cg_products_per_step", DiaphragmReport.round(tm[3], 1));
                    row.put("relative_rms_error", DiaphragmReport.round(e, 4));
                    row.put("error_vs_rk2_same_resolution", DiaphragmReport.round(eOwn, 4));
                    row.put("diverged", tm[4] > 0);
                    rows.add(row);
                    csv.rowText(String.valueOf(rings), String.valueOf(r.nodes()), String.valueOf(r.springs()),
                            c.label(), String.valueOf(r.dt()), String.valueOf(tm[0]), String.valueOf(tm[1]),
                            String.valueOf(tm[2]), String.valueOf(tm[3]), String.valueOf(e), String.valueOf(eOwn));
                    if (log != null) {
                        log.println(String.format(Locale.ROOT,
                                "%d rings, %s: dt %.2e s, %.3f of real time (wall), %.3f (CPU), error %.3f%s", rings,
                                c.label(), r.dt(), tm[0], tm[1], e, tm[4] > 0 ? ", diverged" : ""));
                    }
                }
            }
        }
        Map<String, Object> best = null;
        for (Map<String, Object> row : rows) {
            if ((double) row.get("realtime_factor") >= 1 && !(boolean) row.get("diverged")
                    && (best == null || (double) row.get("relative_rms_error") < (double) best.get("relative_rms_error"))) {
                best = row;
            }
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("simulated_s_per_run", runS);
        summary.put("reference", ringCounts[ringCounts.length - 1] + " rings, " + configs.get(0).label());
        summary.put("sync", "positions copied to a float vertex array after every step (as the GUI's scene graph)");
        summary.put("load_average", DiaphragmReport.round(
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), 2));
        summary.put("most_accurate_in_real_time", best);
        summary.put("runs", rows);
        chart(out.resolve("realtime.png"), rows);
        Json.write(out.resolve("realtime.json"), summary);
        return summary;
    }

    /**
     * One run; fills {@code timing} with the wall and CPU real-time factors, the apex's descent (mm), the CG
     * products per step (0 for explicit methods) and 1 if the run diverged.
     */
    private static ResolutionStudy.Run simulate(DiaphragmScene scene, int rings, Config c, double seconds,
            double[] timing) {
        Simulation sim = scene.newSimulation();
        Integrator in = c.integrator().get();
        sim.setIntegrator(in);
        double dt = scene.timeStep(in, c.dt()).seconds();
        int nd = scene.diaphragmNodes();
        SceneGraphSync sync = new SceneGraphSync(sim.state().nodeCount);
        sim.addListener(sync);
        int apex = scene.apexNode();
        double z0 = sim.state().x[3 * apex + 2];
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        boolean cpuTimed = mx.isThreadCpuTimeSupported();
        long steps = Math.round(seconds / dt);
        long wall;
        long cpu = 0;
        boolean diverged = false;
        try (Parallelism par = c.threads() > 1 ? Parallelism.install(sim, c.threads()) : null) {
            long[] ids = par == null ? new long[0] : par.pool().workerThreadIds();
            long cpu0 = cpuTimed ? cpuOf(mx, ids) : 0;
            long t0 = System.nanoTime();
            try {
                for (long i = 0; i < steps; i++) {
                    sim.step(dt);
                }
            } catch (SimulationDivergedException e) {
                diverged = true;
            }
            wall = System.nanoTime() - t0;
            cpu = cpuTimed ? cpuOf(mx, ids) - cpu0 : 0;
        }
        double simulated = sim.time();
        timing[0] = simulated / (wall / 1e9);
        timing[1] = cpuTimed ? simulated / (cpu / 1e9) : Double.NaN;
        timing[2] = -1e3 * (sim.state().x[3 * apex + 2] - z0);
        timing[3] = in instanceof ImplicitEuler ie ? ie.matrixVectorProducts() / (double) Math.max(1, sim.steps()) : 0;
        timing[4] = diverged ? 1 : 0;
        boolean[] upper = new boolean[nd];
        for (int v = 0; v < nd; v++) {
            upper[v] = scene.surfaces().isUpper(v);
        }
        return new ResolutionStudy.Run("double dome", rings + " rings, " + c.label(), scene.topology().nodeCount(),
                scene.topology().springs().size(), wall / 1e9 / simulated, dt,
                java.util.Arrays.copyOf(sim.state().x0, 3 * nd), java.util.Arrays.copyOf(sim.state().x, 3 * nd),
                upper);
    }

    /** CPU time of the calling thread plus the given worker threads, ns. */
    private static long cpuOf(ThreadMXBean mx, long[] workers) {
        long t = mx.getCurrentThreadCpuTime();
        for (long id : workers) {
            long w = mx.getThreadCpuTime(id);
            if (w > 0) {
                t += w;
            }
        }
        return t;
    }

    private static void chart(Path png, List<Map<String, Object>> rows) throws IOException {
        XYChart c = Charts.lineChart("Diaphragm: error against the paper's configuration vs real-time factor",
                "simulated seconds per wall second (1 = real time), one inspiration, sync included",
                "relative RMS displacement error at end-inspiration", 1000, 650);
        c.getStyler().setXAxisLogarithmic(true);
        List<String> labels = new ArrayList<>();
        for (Map<String, Object> r : rows) {
            if (!labels.contains((String) r.get("config"))) {
                labels.add((String) r.get("config"));
            }
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = 0;
        double top = 0;
        int colour = 0;
        for (String label : labels) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (Map<String, Object> r : rows) {
                double e = (double) r.get("relative_rms_error");
                double f = (double) r.get("realtime_factor");
                if (r.get("config").equals(label) && !(boolean) r.get("diverged") && f > 0) {
                    x.add(f);
                    y.add(e);
                    lo = Math.min(lo, f);
                    hi = Math.max(hi, f);
                    top = Math.max(top, e);
                }
            }
            if (!x.isEmpty()) {
                XYSeries s = c.addSeries(label + " (10 to 43 rings)", x, y);
                s.setMarker(SeriesMarkers.CIRCLE);
                s.setLineColor(Charts.color(colour));
                s.setMarkerColor(Charts.color(colour));
                colour++;
            }
        }
        if (hi > 0) {
            Charts.addLine(c, "real time", new double[] {1, 1}, new double[] {0, Math.max(top, 0.1)});
            c.getStyler().setXAxisMin(Math.min(lo, 1) / 1.5);
            c.getStyler().setXAxisMax(Math.max(hi, 1) * 1.5);
        }
        c.getStyler().setMarkerSize(7);
        Charts.savePng(c, png);
    }
}
