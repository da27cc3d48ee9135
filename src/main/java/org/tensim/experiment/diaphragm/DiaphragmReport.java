package org.tensim.experiment.diaphragm;

import org.tensim.scene.diaphragm.DiaphragmSetup;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Progress;
import org.tensim.io.RunFolder;
import org.tensim.io.RunSignals;
import org.tensim.io.RunStatus;
import org.tensim.io.mesh.VtkSeriesWriter;
import org.tensim.model.Check;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.stability.TimeStep;

/**
 * Runs breathing cycles of a built diaphragm headless and writes, into one folder:
 * <ul>
 * <li>{@code sagittal.png}, {@code axial.png}: displacement vectors x{@code vectorScale}
 * (default 100, as the paper's Fig. 5) over a short interval at mid-inspiration;
 * {@code sagittal-cycle.png}, {@code axial-cycle.png}: end-expiration to
 * end-inspiration, x1;</li>
 * <li>{@code displacements.csv}: every diaphragm node's position and displacement
 * at the chosen times; {@code probe.csv}: the apex and the extents against time;</li>
 * <li>{@code vtk/diaphragm_NNNN.vtk} and {@code vtk/diaphragm.pvd} (ParaView);</li>
 * <li>{@code breathing.png} and {@code summary.json}.</li>
 * </ul>
 * Files are flushed as the run goes; when it diverges the summary says so and what
 * was written is kept.
 */
public final class DiaphragmReport {
    /**
     * Run settings.
     *
     * @param seconds         simulated time, s (the breathing figures need at least one inspiration)
     * @param dtS             time step, s; 0 for the step the time-step policy recommends for the integrator on the scene
     * @param vtkPerCycle     VTK frames per breathing cycle (0: none)
     * @param vectorScale     scale of the mid-inspiration vectors (paper: 100)
     * @param vectorIntervalS interval over which the mid-inspiration displacement is taken, s
     * @param csvTimes        times of the displacement CSV, s; null for end-inspiration and the end of the
     *                        measured cycle (those within the run; the end of a run shorter than Ti)
     */
    public record Options(double seconds, double dtS, int vtkPerCycle, double vectorScale, double vectorIntervalS,
            double[] csvTimes) {
        public Options {
            Check.positive("simulated time", "s", seconds);
            Check.nonNegative("time step", "s", dtS);
            Check.atLeast("VTK frames per cycle", vtkPerCycle, 0);
            Check.positive("vector scale", "", vectorScale);
            Check.positive("vector interval", "s", vectorIntervalS);
        }

        public static Options defaults(double seconds) {
            return new Options(seconds, 0, 8, 100, 0.01, null);
        }
    }

    private DiaphragmReport() {
    }

    /** The files and folders the diaphragm command writes into its folder (docs/outputs.md). */
    public static final List<String> OUTPUTS = List.of("sagittal.png", "axial.png", "sagittal-cycle.png",
            "axial-cycle.png", "breathing.png", "displacements.csv", "probe.csv", "vtk", "lung-points.csv");

    /**
     * Runs and writes everything to {@code out}, a run folder of its own; returns the summary
     * (also in summary.json, with its status).
     */
    public static Map<String, Object> run(DiaphragmSetup.Built built, Options o, Path out, PrintStream log)
            throws Exception {
        return run(built, o, "rk2", out, log);
    }

    /**
     * As {@link #run(DiaphragmSetup.Built, Options, Path, PrintStream)} with the named integrator
     * (see {@code Integrators.names()}); with a time step of 0 the scene's recommended step for that integrator is used.
     */
    public static Map<String, Object> run(DiaphragmSetup.Built built, Options o, String integrator, Path out,
            PrintStream log) throws Exception {
        Map<String, Object> summary = new LinkedHashMap<>();
        RunFolder.run(out, "diaphragm", OUTPUTS, folder -> {
            Map<String, Object> s = run(built, o, org.tensim.solver.integrators.Integrators.create(integrator), 1,
                    folder, log);
            summary.putAll(folder.finish(s.containsKey("diverged") ? RunStatus.DIVERGED : RunStatus.OK, s));
        });
        return summary;
    }

    /**
     * As {@link #run(DiaphragmSetup.Built, Options, String, Path, PrintStream)} with an integrator
     * instance (e.g. an implicit Euler with its own CG tolerance) on {@code threads} threads (>= 1; the
     * spring pass, RK2's and symplectic Euler's node loops and the link sweeps are shared among them,
     * see {@link org.tensim.solver.parallel.Parallelism}). Writes every output but the summary into
     * the run folder and returns the summary's fields; a diverged run's have "diverged" (the message)
     * and its figures are marked DIVERGED. The caller finishes the folder.
     */
    public static Map<String, Object> run(DiaphragmSetup.Built built, Options o,
            org.tensim.solver.Integrator chosen, int threads, RunFolder out, PrintStream log) throws IOException {
        Check.atLeast("thread count", threads, 1);
        Simulation sim = built.scene().newSimulation();
        sim.setIntegrator(chosen);
        try (org.tensim.solver.parallel.Parallelism par = threads > 1
                ? org.tensim.solver.parallel.Parallelism.install(sim, threads) : null) {
            return run(built, o, sim, threads, par == null ? new long[0] : par.pool().workerThreadIds(), out, log);
        }
    }

    /**
     * The run in named steps: plan the instants whose positions are kept, step and sample, sum up,
     * write the files.
     */
    static Map<String, Object> run(DiaphragmSetup.Built built, Options o, Simulation sim, int threads,
            long[] workers, RunFolder out, PrintStream log) throws IOException {
        DiaphragmScene scene = built.scene();
        TimeStep step = scene.timeStep(sim.integrator(), o.dtS());
        double dt = step.seconds();
        BreathingMetrics metrics = new BreathingMetrics(scene, o.seconds());
        Snapshots snapshots = Snapshots.plan(scene, o, metrics.measuredCycleStart());
        VtkSeriesWriter vtk = o.vtkPerCycle() > 0 ? new VtkSeriesWriter(out.file("vtk"), "diaphragm",
                scene.allTriangles(), java.util.Arrays.copyOf(scene.labels(), scene.simulatedNodes()), "tissue") : null;
        // With terms the scene's own bound does not count (the organs' couplings): their frequency, measured.
        Map<String, Object> withTerms = sim.forces().termCount() > 0 ? ModelFrequency.measure(sim, sim.time()) : null;
        Stepping stepping = step(scene, sim, o, dt, metrics, snapshots, vtk, out, workers);
        Map<String, Object> summary = new LinkedHashMap<>();
        SceneMakeUp.describe(summary, built);
        if (withTerms != null) {
            summary.put("omega_measured_with_terms", withTerms);
        }
        if (metrics.complete()) {
            describeBreathing(summary, metrics);
        } else {
            summary.put("breathing", "not measured: the run of " + o.seconds() + " s ends before end-inspiration, "
                    + metrics.inspirationEnd() + " s");
        }
        describeRun(summary, built, o, sim, threads, step, metrics.measuredCycleStart(), stepping);
        if (scene.recorder() != null) {
            for (String f : scene.recorder().files()) {
                out.file(f); // listed before it is written
            }
            scene.recorder().finish(summary, out.dir());
        }
        writeDisplacements(out.file("displacements.csv"), snapshots, scene, sim.state().contacts);
        figures(out, scene, snapshots.kept, snapshots.rest, o, stepping.divergedAtS());
        BreathingChart.write(out.file("breathing.png"), out.dir().resolve("probe.csv"), stepping.divergedAtS());
        if (log != null) {
            log.println("wrote " + out.dir().resolve(RunFolder.SUMMARY) + ", displacements.csv, probe.csv, PNG slices"
                    + (vtk != null ? ", " + vtk.frameCount() + " VTK frames (" + vtk.collection() + ")" : ""));
        }
        return summary;
    }

    /** What the stepping loop measured: wall and CPU time of the steps, and the divergence message if any. */
    private record Stepping(double wallS, double cpuS, String diverged, double divergedAtS) {
    }

    /**
     * Steps to the end, sampling as it goes: snapshots, VTK frames, the probe CSV every 5 ms, the
     * breathing metrics after every step. Stops early, with the message, when the run diverges.
     */
    private static Stepping step(DiaphragmScene scene, Simulation sim, Options o, double dt,
            BreathingMetrics metrics, Snapshots snapshots, VtkSeriesWriter vtk, RunFolder out, long[] workers)
            throws IOException {
        int simulated = scene.simulatedNodes();
        int nd = scene.diaphragmNodes();
        int apex = scene.apexNode();
        double vtkEvery = o.vtkPerCycle() > 0 ? scene.cycle().periodS() / o.vtkPerCycle() : Double.POSITIVE_INFINITY;
        double nextVtk = 0;
        double[] rest = java.util.Arrays.copyOf(sim.state().x0, 3 * simulated);
        snapshots.rest = rest;
        long stepNanos = 0;
        // CPU time of this thread as well as wall time: on a shared machine the wall time also
        // counts the time the thread waited for a core.
        java.lang.management.ThreadMXBean cpu = java.lang.management.ManagementFactory.getThreadMXBean();
        boolean cpuTimed = cpu.isCurrentThreadCpuTimeSupported();
        long cpuNanos = 0;
        String diverged = null;
        double divergedAt = Double.NaN;
        try (CsvWriter probe = out.csv("probe.csv", List.of("t_s", "breathing_level",
                "apex_dz_mm", "extent_x_mm", "extent_y_mm", "extent_z_mm"), 20);
                Progress progress = Progress.start("diaphragm", o.seconds())) {
            double probeEvery = 0.005;
            double nextProbe = 0;
            metrics.begin(sim);
            org.tensim.scene.diaphragm.RunRecorder organs = scene.recorder();
            if (organs != null) {
                organs.begin(sim, metrics.measuredCycleStart(), metrics.inspirationEnd(), scene.cycle().periodS());
            }
            while (true) {
                double t = sim.time();
                snapshots.offer(t, dt, sim.state().x, simulated);
                if (vtk != null && t >= nextVtk - 0.5 * dt) {
                    vtk.frame(t, java.util.Arrays.copyOf(sim.state().x, 3 * simulated), rest);
                    nextVtk += vtkEvery;
                }
                if (t >= nextProbe - 0.5 * dt) {
                    double[] e = extents(sim.state().x, nd);
                    probe.row(t, scene.cycle().level(t), 1e3 * (sim.state().x[3 * apex + 2] - rest[3 * apex + 2]),
                            1e3 * e[0], 1e3 * e[1], 1e3 * e[2]);
                    nextProbe += probeEvery;
                }
                if (t >= o.seconds() - 0.5 * dt) {
                    break;
                }
                RunSignals.checkStop();
                progress.update(t);
                long c0 = cpuTimed ? cpu.getCurrentThreadCpuTime() : 0;
                long t0 = System.nanoTime();
                sim.step(dt);
                stepNanos += System.nanoTime() - t0;
                cpuNanos += cpuTimed ? cpu.getCurrentThreadCpuTime() - c0 : 0;
                metrics.afterStep(sim);
                if (organs != null) {
                    organs.afterStep(sim);
                }
            }
        } catch (SimulationDivergedException e) {
            diverged = e.getMessage();
            divergedAt = e.timeSeconds();
        }
        for (int w = 0; w < workers.length && cpuTimed; w++) {
            // Worker threads exist for this run only: their whole CPU time is the steps' (spinning included).
            cpuNanos += Math.max(0, cpu.getThreadCpuTime(workers[w]));
        }
        return new Stepping(stepNanos / 1e9, cpuTimed ? cpuNanos / 1e9 : Double.NaN, diverged, divergedAt);
    }

    /** The physiological figures of the measured cycle (docs/diaphragm.md says how they are measured). */
    private static void describeBreathing(Map<String, Object> summary, BreathingMetrics metrics) {
        metrics.fields().forEach((k, v) -> summary.put(k, round(v, 3)));
        if (metrics.complete()) {
            Map<String, Object> sites = new LinkedHashMap<>();
            String[] site = metrics.domeSites();
            sites.put("right", site[0]);
            sites.put("left", site[1]);
            summary.put("dome_descent_measured_at", sites);
        }
        if (metrics.worstPenetration() != null) {
            summary.put("deepest_penetration_at", metrics.worstPenetration());
        }
    }

    /** How the run went: time, integrator, step, speed, controls, projection, mesh report, divergence. */
    private static void describeRun(Map<String, Object> summary, DiaphragmSetup.Built built, Options o,
            Simulation sim, int threads, TimeStep step, double measuredCycleStart, Stepping stepping) {
        DiaphragmScene scene = built.scene();
        org.tensim.solver.Integrator chosen = sim.integrator();
        double wall = stepping.wallS();
        double cpuS = stepping.cpuS();
        summary.put("simulated_s", round(sim.time(), 6));
        summary.put("measured_cycle_start_s", measuredCycleStart);
        summary.put("integrator", chosen.name());
        if (chosen instanceof org.tensim.solver.prefactored.PrefactoredBdf2 b) {
            summary.put("newton_iterations", b.newtonIterations());
            summary.put("cg_iterations_cap", b.krylovIterations());
        }
        summary.put("threads", threads);
        if (chosen instanceof org.tensim.solver.integrators.ImplicitEuler ie) {
            summary.put("cg_products_per_step", round(ie.matrixVectorProducts() / (double) Math.max(1, sim.steps()), 1));
            summary.put("cg_unconverged_solves", ie.unconvergedSolves());
        }
        summary.put("dt_s", step.seconds());
        summary.put("dt_rule", step.reason());
        summary.put("omega_max_bound_rad_s", round(scene.omegaMaxBound(), 1));
        summary.put("steps", sim.steps());
        summary.put("steps_per_s", round(sim.steps() / Math.max(wall, 1e-9), 1));
        summary.put("realtime_factor", round(sim.time() / Math.max(wall, 1e-9), 4));
        summary.put("steps_per_cpu_s", round(sim.steps() / cpuS, 1));
        summary.put("realtime_factor_cpu", round(sim.time() / cpuS, 4));
        summary.put("stage_ms_per_step", StepTimings.of(sim));
        summary.put("load_average", round(java.lang.management.ManagementFactory.getOperatingSystemMXBean()
                .getSystemLoadAverage(), 2));
        summary.put("rib_amplitude", scene.controls().ribAmplitude());
        summary.put("muscle_force_pa", scene.controls().muscleAmplitudePa());
        summary.put("breathing_period_s", scene.cycle().periodS());
        summary.put("unconverged_projections", sim.unconvergedProjections());
        if (built.meshReport() != null) {
            summary.put("mesh", built.meshReport().toMap());
        }
        if (stepping.diverged() != null) {
            summary.put("diverged", stepping.diverged());
            summary.put("diverged_at_s", stepping.divergedAtS());
        }
    }

    /**
     * Every diaphragm node's position and displacement at the kept times, and its signed distance to the nearest
     * bone it may touch then and at rest ({@code bone_gap_m}, {@code bone_gap_rest_m}; NaN without one).
     */
    private static void writeDisplacements(Path file, Snapshots snapshots, DiaphragmScene scene,
            org.tensim.solver.ContactForces contacts) throws IOException {
        double[] rest = snapshots.rest;
        int[] labels = scene.labels();
        int nd = scene.diaphragmNodes();
        double[] restGap = contacts.nearestHardDistances(0, rest, nd);
        try (CsvWriter w = new CsvWriter(file, List.of("t_s", "node", "tissue", "x_m", "y_m", "z_m", "ux_m", "uy_m",
                "uz_m", "bone_gap_m", "bone_gap_rest_m"), 1000)) {
            for (int c = 0; c < snapshots.csvTimes.length; c++) {
                int idx = 4 + c;
                if (snapshots.kept[idx] == null) {
                    continue; // the run stopped before this time
                }
                double[] x = snapshots.kept[idx];
                double[] gap = contacts.nearestHardDistances(snapshots.keptTime[idx], x, nd);
                for (int i = 0; i < nd; i++) {
                    w.row(snapshots.keptTime[idx], i, labels[i], x[3 * i], x[3 * i + 1], x[3 * i + 2],
                            x[3 * i] - rest[3 * i], x[3 * i + 1] - rest[3 * i + 1], x[3 * i + 2] - rest[3 * i + 2],
                            gap[i], restGap[i]);
                }
            }
        }
    }

    private static void figures(RunFolder out, DiaphragmScene scene, double[][] kept, double[] rest, Options o,
            double divergedAt) throws IOException {
        java.util.function.UnaryOperator<String> mark = title -> Double.isNaN(divergedAt) ? title
                : Charts.divergedTitle(divergedAt, title);
        int nd = scene.diaphragmNodes();
        int[] upper = java.util.stream.IntStream.range(0, nd).filter(scene.surfaces()::isUpper).toArray();
        int apex = scene.apexNode();
        double xPlane = rest[3 * apex];
        double zPlane = rest[3 * apex + 2] - 0.04;
        double band = 2 * meanEdge(scene);
        if (kept[0] != null && kept[1] != null) {
            SliceFigures.write(out.file("sagittal.png"), mark.apply(String.format(java.util.Locale.ROOT,
                    "Sagittal slice x = %.0f mm: displacement over %.0f ms at mid-inspiration, x%.0f", 1e3 * xPlane,
                    1e3 * o.vectorIntervalS(), o.vectorScale())), kept[0], kept[1], upper, 0, xPlane, band,
                    o.vectorScale());
            SliceFigures.write(out.file("axial.png"), mark.apply(String.format(java.util.Locale.ROOT,
                    "Axial slice z = %.0f mm: displacement over %.0f ms at mid-inspiration, x%.0f", 1e3 * zPlane,
                    1e3 * o.vectorIntervalS(), o.vectorScale())), kept[0], kept[1], upper, 2, zPlane, band,
                    o.vectorScale());
        }
        if (kept[2] != null && kept[3] != null) {
            SliceFigures.write(out.file("sagittal-cycle.png"), mark.apply(String.format(java.util.Locale.ROOT,
                    "Sagittal slice x = %.0f mm: end-expiration to end-inspiration, x1", 1e3 * xPlane)), kept[2],
                    kept[3], upper, 0, xPlane, band, 1);
            SliceFigures.write(out.file("axial-cycle.png"), mark.apply(String.format(java.util.Locale.ROOT,
                    "Axial slice z = %.0f mm: end-expiration to end-inspiration, x1", 1e3 * zPlane)), kept[2],
                    kept[3], upper, 2, zPlane, band, 1);
        }
    }

    static double meanEdge(DiaphragmScene scene) {
        var m = scene.surfaces().mesh();
        double s = 0;
        int n = 0;
        for (int t = 0; t < m.triangleCount(); t += 7) {
            s += Math.sqrt(2 * m.area(t));
            n++;
        }
        return s / Math.max(n, 1);
    }

    private static double[] extents(double[] x, int n) {
        double[] e = new double[3];
        for (int a = 0; a < 3; a++) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                lo = Math.min(lo, x[3 * i + a]);
                hi = Math.max(hi, x[3 * i + a]);
            }
            e[a] = hi - lo;
        }
        return e;
    }

    /**
     * {@code v} rounded to {@code digits} decimals. Infinities and NaN are kept as they are: Math.round would
     * turn them into Long.MAX_VALUE and 0, so that a diverged run's error would read as a number or as none.
     */
    public static double round(double v, int digits) {
        if (!Double.isFinite(v)) {
            return v;
        }
        double f = Math.pow(10, digits);
        return Math.round(v * f) / f;
    }
}
