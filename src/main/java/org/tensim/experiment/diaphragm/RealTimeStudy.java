package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * What reaches real time, and at what accuracy: the diaphragm at several
 * resolutions (the resolution study's ring counts) with several integrators and
 * time steps, each run from rest (one inspiration by default, up to one breathing
 * period) with the scene-graph sync of the GUI after every step, timed, and compared
 * with RK2 at the scene's stable step on two threads at the same resolution, and
 * with the paper's configuration (that RK2 at 43 rings).
 *
 * <p>Speed: the real-time factor is simulated seconds per wall second of the
 * stepping loop (steps, projection, listeners, sync), and also per CPU second of
 * the stepping thread(s), which a shared machine disturbs less. Accuracy: the
 * relative RMS difference of the upper surface's displacement at the end of the
 * run against the paper's configuration, by nearest node ({@link ResolutionStudy#error});
 * against RK2 at the same mesh, the relative RMS difference of the whole displacement
 * field at the end and at the worst of the samples taken every 50 ms, and the
 * apex's descent ({@link StudyRun#errorAgainst}): the tolerance of {@code --realtime}.
 *
 * <p>Configurations: the paper's RK2 at the scene's stable step (1 and 2 threads;
 * and with the sternum's node mass scaled, which lifts the sternum's limit on the
 * step at coarse resolutions), and implicit Euler at 5, 10 and 20 ms with a CG
 * tolerance of 1e-3 (the catalogue's {@value Integrators#REAL_TIME_IMPLICIT}; a larger
 * step than RK2's stability allows; the CG solve is the price), and the large-step BDF2 ({@link PrefactoredBdf2}, two threads) at
 * 5-50 ms with 4 and 8 CG iterations a step, and with 2, 3 and 6 Newton iterations of 8 (at 5-50 ms:
 * how much of the error is the inexact solve's). The comparison with RK2 at the same
 * resolution separates the integrator's error from the resolution's.
 */
public final class RealTimeStudy {
    /** Ring counts; the last one is the paper's resolution and holds the reference. */
    public static final int[] RINGS = {10, 14, 20, 28, 43};
    /** Implicit Euler steps tried, s. */
    static final double[] IMPLICIT_STEPS = {0.005, 0.01, 0.02};
    /** BDF2 steps tried, s (a multiple of each divides {@link StudyRun#SAMPLE_S} or the run). */
    static final double[] BDF2_STEPS = {0.005, 0.01, 0.02, 0.025, 1.0 / 30, 0.05};
    /** CG iterations per step of the more accurate BDF2 rows (the default is {@link PrefactoredBdf2#DEFAULT_KRYLOV_ITERATIONS}). */
    static final int BDF2_MORE_CG = 8;
    /**
     * CG caps either side of the default ({@link PrefactoredBdf2#DEFAULT_KRYLOV_ITERATIONS}, 5) at the real-time
     * setting's step: 4, the default until the geodesic tendon, and 6.
     */
    static final int[] BDF2_OTHER_CG = {4, 6};
    /** Newton iterations of the most accurate BDF2 rows (the default is one: a linearly implicit step). */
    static final int[] BDF2_NEWTON = {2, 3, 6};
    /** Steps of those rows, s. */
    static final double[] BDF2_NEWTON_STEPS = {0.005, 0.01, 0.02, 0.025, 0.05};
    /** Relative RMS displacement error against RK2 at the same mesh accepted by {@code --realtime}. */
    public static final double TOLERANCE = 0.05;
    /** Difference of the apex's descent from RK2's accepted by {@code --realtime}, mm. */
    public static final double APEX_TOLERANCE_MM = 1;

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
        // First: the reference of every other run at the same resolution.
        c.add(new Config("rk2 at the stable step / 2 threads", () -> Integrators.create("rk2"), 0, 2, false));
        c.add(new Config("rk2 at the stable step / 1 thread", () -> Integrators.create("rk2"), 0, 1, false));
        c.add(new Config("rk2 at the stable step / sternum mass x10 / 1 thread", () -> Integrators.create("rk2"), 0,
                1, true));
        for (double h : IMPLICIT_STEPS) {
            c.add(new Config(String.format(Locale.ROOT, "implicit-euler at %.0f ms / 1 thread", 1e3 * h),
                    Integrators.choice(Integrators.REAL_TIME_IMPLICIT)::create, h, 1, false));
        }
        for (double h : BDF2_STEPS) {
            c.add(new Config(String.format(Locale.ROOT, "bdf2 at %.0f ms / 2 threads", 1e3 * h),
                    () -> Integrators.create(PrefactoredBdf2.NAME), h, 2, false));
        }
        for (double h : BDF2_STEPS) {
            c.add(new Config(String.format(Locale.ROOT, "bdf2 at %.0f ms with %d CG / 2 threads", 1e3 * h,
                    BDF2_MORE_CG), () -> new PrefactoredBdf2().setKrylovIterations(BDF2_MORE_CG), h, 2, false));
        }
        for (int cg : BDF2_OTHER_CG) {
            c.add(new Config(String.format(Locale.ROOT, "bdf2 at %.0f ms with %d CG / 2 threads",
                    1e3 * Integrators.REAL_TIME_STEP_S, cg), () -> new PrefactoredBdf2().setKrylovIterations(cg),
                    Integrators.REAL_TIME_STEP_S, 2, false));
        }
        for (int newton : BDF2_NEWTON) {
            for (double h : BDF2_NEWTON_STEPS) {
                c.add(new Config(String.format(Locale.ROOT, "bdf2 at %.0f ms with %d Newton x %d CG / 2 threads",
                        1e3 * h, newton, BDF2_MORE_CG), () -> new PrefactoredBdf2().setNewtonIterations(newton)
                                .setKrylovIterations(BDF2_MORE_CG), h, 2, false));
            }
        }
        return c;
    }

    /**
     * Runs every configuration at every resolution, writes {@code realtime.csv},
     * {@code realtime.json} and {@code realtime.png} to {@code out}, and returns the summary.
     *
     * @param seconds simulated time per run, s (capped at one breathing period)
     */
    public static Map<String, Object> run(Path boxes, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls, double seconds, Path out, PrintStream log) throws IOException {
        return run(RINGS, null, boxes, p, cycle, controls, seconds, out, log);
    }

    /**
     * As {@link #run(Path, DiaphragmParameters, BreathingCycle, DiaphragmControls, double, Path, PrintStream)}
     * at the given ring counts (ascending; the last one holds the reference of the error against the paper's
     * configuration), with the configurations whose label {@code only} finds (null: all; the first, the
     * same-resolution reference, always runs).
     */
    public static Map<String, Object> run(int[] ringCounts, Pattern only, Path boxes, DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls, double seconds, Path out, PrintStream log)
            throws IOException {
        return run(ringCounts, only, boxes, p, BoundaryConditions.defaults(), cycle, controls, seconds, out, log);
    }

    /** As the overload above with the given attachment and muscle-load models. */
    public static Map<String, Object> run(int[] ringCounts, Pattern only, Path boxes, DiaphragmParameters p,
            BoundaryConditions bc, BreathingCycle cycle, DiaphragmControls controls, double seconds, Path out,
            PrintStream log) throws IOException {
        Files.createDirectories(out);
        double runS = Math.min(seconds, cycle.periodS());
        List<Config> configs = new ArrayList<>();
        for (Config c : configs()) {
            if (configs.isEmpty() || only == null || only.matcher(c.label()).find()) {
                configs.add(c);
            }
        }
        DiaphragmParameters scaled = p.withStructureNodeMass(STERNUM_MASS_SCALE * p.structureNodeMassKg());
        List<Map<String, Object>> rows = new ArrayList<>();
        ResolutionStudy.Run reference = null;
        try (CsvWriter csv = new CsvWriter(out.resolve("realtime.csv"), List.of("rings", "nodes", "springs",
                "config", "dt_s", "realtime_factor", "realtime_factor_cpu", "apex_descent_mm", "cg_products_per_step",
                "relative_rms_error", "error_vs_rk2_same_resolution", "worst_error_vs_rk2_same_resolution",
                "apex_difference_mm"), 1)) {
            // Finest first: the reference is the first run, and a long study can be read as it goes.
            for (int i = ringCounts.length - 1; i >= 0; i--) {
                int rings = ringCounts[i];
                DiaphragmScene scene = DiaphragmSetup.generated(rings, null, boxes, p, cycle, controls, bc).scene();
                DiaphragmScene scaledScene = DiaphragmSetup.generated(rings, null, boxes, scaled, cycle, controls, bc)
                        .scene();
                StudyRun own = null; // RK2 on two threads (the first configuration) at this resolution
                for (Config c : configs) {
                    StudyRun r = c == configs.get(0)
                            ? StudyRun.reference(scene, rings, c, runS,
                                    ReferenceCache.file(out, rings, scene, p, bc, cycle, controls), log)
                            : StudyRun.simulate(c.scaledSternum() ? scaledScene : scene, rings, c, runS);
                    reference = reference == null ? r.run() : reference;
                    own = own == null ? r : own;
                    double e = r.diverged() ? Double.POSITIVE_INFINITY
                            : r.run() == reference ? 0 : ResolutionStudy.error(reference, r.run());
                    double[] eOwn = r.errorAgainst(own);
                    Map<String, Object> row = row(rings, c, r, e, eOwn);
                    rows.add(row);
                    csv.rowText(String.valueOf(rings), String.valueOf(r.run().nodes()),
                            String.valueOf(r.run().springs()), c.label(), String.valueOf(r.run().dt()),
                            String.valueOf(r.realtimeWall()), String.valueOf(r.realtimeCpu()),
                            String.valueOf(r.apexDescentMm()), String.valueOf(r.productsPerStep()), String.valueOf(e),
                            String.valueOf(eOwn[0]), String.valueOf(eOwn[1]), String.valueOf(eOwn[3]));
                    if (log != null) {
                        log.println(String.format(Locale.ROOT, "%d rings, %s: dt %.2e s, %.3f of real time (wall), "
                                + "%.3f (CPU); error vs RK2 here %.4f at the end, %.4f at worst (t = %.2f s), apex "
                                + "%+.2f mm; vs the paper's configuration %.3f%s", rings, c.label(), r.run().dt(),
                                r.realtimeWall(), r.realtimeCpu(), eOwn[0], eOwn[1], eOwn[2], eOwn[3], e,
                                r.diverged() ? ", diverged" : ""));
                    }
                }
            }
        }
        Map<String, Object> best = null;
        Map<String, Object> fastest = null;
        int finest = ringCounts[ringCounts.length - 1];
        for (Map<String, Object> row : rows) {
            double rt = (double) row.get("realtime_factor");
            if (rt >= 1 && !(boolean) row.get("diverged")
                    && (best == null || (double) row.get("relative_rms_error") < (double) best.get("relative_rms_error"))) {
                best = row;
            }
            if ((int) row.get("rings") == finest && (boolean) row.get("within_tolerance")
                    && (fastest == null || rt > (double) fastest.get("realtime_factor"))) {
                fastest = row;
            }
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("simulated_s_per_run", runS);
        summary.put("reference", finest + " rings, " + configs.get(0).label());
        summary.put("sync", "positions copied to a float vertex array after every step (as the GUI's scene graph)");
        summary.put("tolerance", "relative RMS displacement error against RK2 at the same mesh <= "
                + TOLERANCE + " at the end and at the worst sample, apex descent within " + APEX_TOLERANCE_MM
                + " mm of RK2's at the end");
        summary.put("load_average", DiaphragmReport.round(
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), 2));
        summary.put("most_accurate_in_real_time", best);
        summary.put("fastest_within_tolerance_at_" + finest + "_rings", fastest);
        summary.put("runs", rows);
        RealTimeChart.write(out.resolve("realtime.png"), rows);
        Json.write(out.resolve("realtime.json"), summary);
        return summary;
    }

    /** One row of the study's table. */
    private static Map<String, Object> row(int rings, Config c, StudyRun r, double e, double[] eOwn) {
        Map<String, Object> row = new LinkedHashMap<>();
        row.put("rings", rings);
        row.put("nodes", r.run().nodes());
        row.put("springs", r.run().springs());
        row.put("config", c.label());
        row.put("threads", c.threads());
        row.put("dt_s", r.run().dt());
        row.put("realtime_factor", DiaphragmReport.round(r.realtimeWall(), 4));
        row.put("realtime_factor_cpu", DiaphragmReport.round(r.realtimeCpu(), 4));
        row.put("apex_descent_mm", DiaphragmReport.round(r.apexDescentMm(), 3));
        row.put("cg_products_per_step", DiaphragmReport.round(r.productsPerStep(), 1));
        row.put("relative_rms_error", DiaphragmReport.round(e, 4));
        row.put("error_vs_rk2_same_resolution", DiaphragmReport.round(eOwn[0], 4));
        row.put("worst_error_vs_rk2_same_resolution", DiaphragmReport.round(eOwn[1], 4));
        row.put("worst_error_time_s", DiaphragmReport.round(eOwn[2], 3));
        row.put("apex_difference_mm", DiaphragmReport.round(eOwn[3], 3));
        row.put("worst_apex_difference_mm", DiaphragmReport.round(eOwn[4], 3));
        row.put("within_tolerance", eOwn[0] <= TOLERANCE && eOwn[1] <= TOLERANCE && eOwn[3] <= APEX_TOLERANCE_MM);
        row.put("diverged", r.diverged());
        return row;
    }
}
