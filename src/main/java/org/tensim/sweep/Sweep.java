package org.tensim.sweep;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;
import org.tensim.io.Json;

/**
 * Runs a sweep into a folder: {@code results.csv} (one row per point, appended as points
 * finish; see {@link ResultsFile}), {@code charts/OUTPUT-vs-PARAMETER.png} and
 * {@code sweep.json} (counts by status, wall time, throughput). Points already in an
 * existing {@code results.csv} are skipped: a sweep interrupted and started again
 * resumes where it stopped.
 */
public final class Sweep {
    /**
     * What a sweep did.
     *
     * @param results    every finished point, old and new, by id
     * @param total      points in the spec
     * @param skipped    points found finished in an existing results file
     * @param ran        points run now
     * @param wallS      wall time of the points run now, s
     * @param busyS      sum of the wall times of the points run now, s (busyS / wallS: points running at once)
     * @param summary    the sweep.json content
     */
    public record Outcome(List<PointResult> results, int total, int skipped, int ran, double wallS, double busyS,
            Map<String, Object> summary) {
    }

    private Sweep() {
    }

    /**
     * Runs the spec's points that are not yet in {@code out/results.csv} on the engine.
     *
     * @param progress whether to draw a progress bar with an ETA on standard error (on a terminal)
     * @param log      where one line per finished point goes when there is no progress bar; may be null
     */
    public static Outcome run(SweepSpec spec, Path out, SweepEngine engine, boolean progress, PrintStream log)
            throws IOException, InterruptedException {
        return run(spec, SweepPoints.of(spec), out, engine, progress, log);
    }

    /** As {@link #run(SweepSpec, Path, SweepEngine, boolean, PrintStream)} with given points. */
    public static Outcome run(SweepSpec spec, List<Point> points, Path out, SweepEngine engine, boolean progress,
            PrintStream log) throws IOException, InterruptedException {
        Files.createDirectories(out);
        List<String> names = spec.parameterNames();
        List<Point> todo = new ArrayList<>();
        int skipped = 0;
        long t0;
        double[] busy = {0, 0};
        try (ResultsFile csv = new ResultsFile(out.resolve("results.csv"), names, spec.outputs())) {
            Map<Integer, PointResult> old = csv.done();
            for (Point p : points) {
                PointResult r = old.get(p.id());
                if (r == null) {
                    todo.add(p);
                } else if (!java.util.Arrays.equals(r.values(), p.values())) {
                    throw new IllegalArgumentException(csv.path() + ": point " + p.id() + " was run at "
                            + java.util.Arrays.toString(r.values()) + ", the spec now gives "
                            + java.util.Arrays.toString(p.values()) + "; give another --out or remove the file");
                } else {
                    skipped++;
                }
            }
            if (log != null && skipped > 0) {
                log.println("resuming: " + skipped + " of " + points.size() + " points already in " + csv.path());
            }
            t0 = System.nanoTime();
            JvmCosts c0 = JvmCosts.now();
            try (ProgressBar bar = progress && !todo.isEmpty() ? new ProgressBarBuilder().setTaskName("sweep")
                    .setInitialMax(todo.size()).setStyle(ProgressBarStyle.ASCII).setUnit(" points", 1)
                    .setConsumer(new ConsoleProgressBarConsumer(System.err)).build() : null) {
                int[] n = {0};
                engine.run(spec.setup(), names, todo, r -> {
                    csv.write(r);
                    busy[0] += r.wallS();
                    busy[1] += r.cpuS();
                    n[0]++;
                    if (bar != null) {
                        bar.step();
                        bar.setExtraMessage(r.status().equals(PointResult.OK) ? "" : "point " + r.id() + " "
                                + r.status());
                    } else if (log != null) {
                        log.printf(java.util.Locale.ROOT, "point %d (%d/%d): %s, %.2f s%s%n", r.id(), n[0],
                                todo.size(), r.status(), r.wallS(), r.message().isEmpty() ? "" : ": " + r.message());
                    }
                });
            }
            double wall = (System.nanoTime() - t0) / 1e9;
            JvmCosts c1 = JvmCosts.now();
            List<PointResult> all = new ArrayList<>(csv.done().values());
            all.sort(Comparator.comparingInt(PointResult::id));
            Map<String, Object> s = summary(spec, engine, points.size(), skipped, todo.size(), wall, busy, all);
            c1.putSince(c0, s);
            List<Path> charts = SweepCharts.write(out.resolve("charts"), names, spec.outputs(), all);
            s.put("charts", charts.size());
            Json.write(out.resolve("sweep.json"), s);
            return new Outcome(all, points.size(), skipped, todo.size(), wall, busy[0], s);
        }
    }

    private static Map<String, Object> summary(SweepSpec spec, SweepEngine engine, int total, int skipped, int ran,
            double wall, double[] busy, List<PointResult> all) {
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("scene", spec.setup().geometry());
        s.put("engine", engine.describe());
        s.put("points", total);
        s.put("skipped_already_done", skipped);
        s.put("ran", ran);
        for (String st : List.of(PointResult.OK, PointResult.DIVERGED, PointResult.REFUSED)) {
            s.put(st, all.stream().filter(r -> r.status().equals(st)).count());
        }
        s.put("wall_s", round(wall));
        s.put("points_per_s", ran == 0 ? 0 : round(ran / wall));
        s.put("sum_point_wall_s", round(busy[0]));
        s.put("mean_point_wall_s", ran == 0 ? 0 : round(busy[0] / ran));
        // CPU time the runs got: on a shared machine, busy[1] / wall is how many cores the sweep obtained.
        s.put("sum_point_cpu_s", round(busy[1]));
        s.put("cores_obtained", ran == 0 ? 0 : round(busy[1] / wall));
        s.put("load_average", round(java.lang.management.ManagementFactory.getOperatingSystemMXBean()
                .getSystemLoadAverage()));
        return s;
    }

    private static double round(double v) {
        return Math.round(v * 1e4) / 1e4;
    }
}
