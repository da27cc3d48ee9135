package org.tensim.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.solver.prefactored.Bdf2Part;
import org.tensim.solver.prefactored.KernelSharing;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * Two integrators of the catalogue on the same scene, in one JVM, timed in alternating rounds: a ratio of
 * before and after measured at the same moments, so that the load of a shared machine falls on both alike.
 * Each integrator steps its own copy of the scene (the same scene, the same step); a round runs
 * {@code steps} steps of each, the order alternating from round to round. For each round: wall and CPU time
 * per step, and for {@code bdf2}'s family the wall time per step of its solves with the factor
 * ({@link Bdf2Part#SOLVES}), with the time of day (UTC) and the machine's 1-minute load average. A last line
 * gives the medians of the ratios (first / second: above 1, the second is faster) and how far apart the two
 * scenes' positions ended.
 */
final class InterleavedComparison {
    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("HH:mm:ss");

    private InterleavedComparison() {
    }

    /** What a round of one integrator measured. */
    private static final class Side {
        final String name;
        final Simulation sim;
        final Integrator integrator;
        final double dt;
        final Parallelism parallelism;
        long steps;
        /** bdf2's parts, total ms, when the timed rounds began; and the steps made by then. */
        final double[] partsAtStart = new double[Bdf2Part.values().length];
        long stepsAtStart;

        Side(String name, Simulation sim, Integrator integrator, double dt, Parallelism parallelism) {
            this.name = name;
            this.sim = sim;
            this.integrator = integrator;
            this.dt = dt;
            this.parallelism = parallelism;
        }

        /** Total ms of bdf2's solves so far (0 for other integrators). */
        double solveMillis() {
            return partMillis(Bdf2Part.SOLVES);
        }

        /** Total ms of a part of bdf2's solve so far (0 for other integrators). */
        double partMillis(Bdf2Part part) {
            return integrator instanceof PrefactoredBdf2 b ? b.partMillisPerStep(part) * steps : 0;
        }
    }

    /**
     * Runs the comparison and hands each line (a round, then the summary) to {@code out} as it is made.
     *
     * @param scenes  a new copy of the scene per call
     * @param names   two integrator names of the catalogue
     * @param dtS     time step, s; 0 for the scene's recommendation for the first integrator
     */
    static List<Map<String, Object>> run(SceneSource scenes, List<String> names, int threads, double dtS, int steps,
            int rounds, int warmUpSteps, Consumer<Map<String, Object>> out) throws Exception {
        List<Side> sides = new ArrayList<>();
        List<Map<String, Object>> lines = new ArrayList<>();
        try {
            double dt = 0;
            for (String n : names) {
                DiaphragmScene d = scenes.build();
                Integrator in = create(n);
                if (dt == 0) {
                    dt = d.timeStep(in, dtS).seconds();
                }
                Simulation sim = d.newSimulation();
                sim.setIntegrator(in);
                int t = threadsOf(n, threads);
                Parallelism p = t > 1 ? Parallelism.install(sim, t) : null;
                sides.add(new Side(n, sim, in, dt, p));
            }
            for (int i = 0; i < warmUpSteps; i++) {
                for (Side s : sides) {
                    s.sim.step(s.dt);
                    s.steps++;
                }
            }
            for (Side s : sides) {
                for (Bdf2Part part : Bdf2Part.values()) {
                    s.partsAtStart[part.ordinal()] = s.partMillis(part);
                }
                s.stepsAtStart = s.steps;
            }
            ThreadMXBean mx = ManagementFactory.getThreadMXBean();
            double[][] stepRatio = new double[3][rounds];
            double[][] stepMs = new double[2][rounds];
            for (int r = 0; r < rounds; r++) {
                Map<String, Object> m = new LinkedHashMap<>();
                m.put("round", r + 1);
                m.put("utc", LocalTime.now(ZoneOffset.UTC).format(CLOCK));
                double[] wall = new double[sides.size()];
                double[] cpu = new double[sides.size()];
                double[] solve = new double[sides.size()];
                for (int k = 0; k < sides.size(); k++) {
                    int which = r % 2 == 0 ? k : sides.size() - 1 - k;
                    Side s = sides.get(which);
                    double solve0 = s.solveMillis();
                    long c0 = mx.getCurrentThreadCpuTime();
                    long t0 = System.nanoTime();
                    for (int i = 0; i < steps; i++) {
                        s.sim.step(s.dt);
                    }
                    long t1 = System.nanoTime();
                    long c1 = mx.getCurrentThreadCpuTime();
                    s.steps += steps;
                    wall[which] = (t1 - t0) / 1e6 / steps;
                    cpu[which] = (c1 - c0) / 1e6 / steps;
                    solve[which] = (s.solveMillis() - solve0) / steps;
                }
                for (int k = 0; k < sides.size(); k++) {
                    String n = sides.get(k).name;
                    m.put(n + "_step_ms", round(wall[k]));
                    m.put(n + "_step_cpu_ms", round(cpu[k]));
                    m.put(n + "_solve_ms", round(solve[k]));
                }
                stepRatio[0][r] = wall[0] / wall[1];
                stepRatio[1][r] = solve[0] / solve[1];
                stepRatio[2][r] = cpu[0] / cpu[1];
                stepMs[0][r] = wall[0];
                stepMs[1][r] = wall[1];
                m.put("step_ratio", round(stepRatio[0][r]));
                m.put("step_cpu_ratio", round(cpu[0] / cpu[1]));
                m.put("solve_ratio", round(stepRatio[1][r]));
                m.put("load_average", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
                lines.add(m);
                out.accept(m);
            }
            Map<String, Object> sum = new LinkedHashMap<>();
            sum.put("compare", names.get(0) + " / " + names.get(1));
            sum.put("utc", LocalTime.now(ZoneOffset.UTC).format(CLOCK));
            sum.put("nodes", sides.get(0).sim.state().nodeCount);
            sum.put("threads", names.stream().map(n -> threadsOf(n, threads)).toList());
            sum.put("dt_s", sides.get(0).dt);
            sum.put("steps_per_round", steps);
            sum.put("rounds", rounds);
            sum.put("step_ratio_median", round(LatticeBenchmark.median(stepRatio[0])));
            sum.put("step_ratio_min", round(LatticeBenchmark.min(stepRatio[0])));
            sum.put("step_ratio_max", round(LatticeBenchmark.max(stepRatio[0])));
            sum.put("step_cpu_ratio_median", round(LatticeBenchmark.median(stepRatio[2])));
            sum.put("step_cpu_ratio_min", round(LatticeBenchmark.min(stepRatio[2])));
            sum.put("step_cpu_ratio_max", round(LatticeBenchmark.max(stepRatio[2])));
            sum.put("solve_ratio_median", round(LatticeBenchmark.median(stepRatio[1])));
            sum.put("solve_ratio_min", round(LatticeBenchmark.min(stepRatio[1])));
            sum.put("solve_ratio_max", round(LatticeBenchmark.max(stepRatio[1])));
            double[] a = sides.get(0).sim.state().x;
            double[] b = sides.get(1).sim.state().x;
            double[] x0 = sides.get(0).sim.state().x0;
            double diff = 0;
            double moved = 0;
            for (int k = 0; k < a.length; k++) {
                diff = Math.max(diff, Math.abs(a[k] - b[k]));
                moved = Math.max(moved, Math.abs(a[k] - x0[k]));
            }
            for (Side s : sides) {
                if (s.integrator instanceof PrefactoredBdf2 bdf) {
                    // Where a step's time goes: wall ms per step over the timed rounds; "step" is their mean,
                    // "rest" the step's time outside the parts (predictor, history, driven nodes, error
                    // estimate, stages 2-3 and the check).
                    Map<String, Object> parts = new LinkedHashMap<>();
                    long timed = s.steps - s.stepsAtStart;
                    double sumParts = 0;
                    for (Bdf2Part part : Bdf2Part.values()) {
                        double ms = (s.partMillis(part) - s.partsAtStart[part.ordinal()]) / timed;
                        sumParts += ms;
                        parts.put(part.name().toLowerCase(), round(ms));
                    }
                    double step = java.util.Arrays.stream(stepMs[sides.indexOf(s)]).average().orElse(Double.NaN);
                    parts.put("rest", round(step - sumParts));
                    parts.put("step", round(step));
                    sum.put(s.name + "_parts_ms_per_step", parts);
                    sum.put(s.name + "_factor_nonzeros", bdf.factorNonZeros());
                }
            }
            sum.put("simulated_s", sides.get(0).steps * sides.get(0).dt);
            sum.put("max_position_difference_mm", round(diff * 1e3));
            sum.put("max_displacement_mm", round(moved * 1e3));
            sum.put("load_average", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
            lines.add(sum);
            out.accept(sum);
            return lines;
        } finally {
            for (Side s : sides) {
                if (s.parallelism != null) {
                    s.parallelism.close();
                }
            }
        }
    }

    /**
     * The integrator of a side's name: a name of the catalogue, optionally followed by {@value #SERIAL} or
     * {@value #SHARED} (a {@code bdf2} whose solves and products' fibres and shear elements stay on the calling
     * thread, or are always shared: {@link PrefactoredBdf2#setKernelSharing}; by default shared while measured
     * faster) and by {@code @T} (its own thread count).
     */
    static Integrator create(String side) {
        String n = side.replaceFirst("@\\d+$", "");
        KernelSharing sharing = n.endsWith(SERIAL) ? KernelSharing.NEVER
                : n.endsWith(SHARED) ? KernelSharing.ALWAYS : null;
        if (sharing != null) {
            n = n.substring(0, n.lastIndexOf(':'));
        }
        Integrator in = org.tensim.solver.integrators.Integrators.create(n);
        if (sharing != null) {
            if (!(in instanceof PrefactoredBdf2 b)) {
                throw new IllegalArgumentException(SERIAL + " and " + SHARED + " apply to the bdf2 family, not to "
                        + side);
            }
            b.setKernelSharing(sharing);
        }
        return in;
    }

    /** The thread count of a side: its {@code @T}, else {@code threads}. */
    static int threadsOf(String side, int threads) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("@(\\d+)$").matcher(side);
        return m.find() ? Integer.parseInt(m.group(1)) : threads;
    }

    /** Suffix of a side's name whose bdf2 keeps its solves and products on the calling thread. */
    static final String SERIAL = ":serial";
    /** Suffix of a side's name whose bdf2 always shares its solves and products among the threads. */
    static final String SHARED = ":shared";

    private static double round(double v) {
        return Math.round(v * 1e4) / 1e4;
    }

    /** A new copy of the scene per call. */
    interface SceneSource {
        DiaphragmScene build() throws Exception;
    }
}
