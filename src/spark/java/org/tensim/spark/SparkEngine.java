package org.tensim.spark;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.Iterator;
import java.util.List;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaFutureAction;
import org.apache.spark.api.java.JavaSparkContext;
import org.tensim.sweep.Point;
import org.tensim.sweep.PointResult;
import org.tensim.sweep.RunSetup;
import org.tensim.sweep.SceneRun;
import org.tensim.sweep.SweepEngine;

/**
 * The sweep's points as Apache Spark tasks. Each point is its own one-task job, submitted
 * asynchronously (at most four per task slot in flight), so that results reach the sink,
 * and the results file, as points finish, in any order, exactly as with the local engine;
 * a task runs {@link SceneRun#run} on an executor, which gives the same bits as a local
 * run of the same point.
 *
 * <p>Master: the one given ({@code local[2]}, {@code local[*]}: embedded in this JVM;
 * {@code spark://host:7077}: a standalone cluster, to which the project's jar
 * {@code build/libs/tensim-spark-submit.jar} is shipped), else the one spark-submit set, else
 * {@code local[*]}. See docs/scaling.md.
 */
public final class SparkEngine implements SweepEngine {
    /** The self-contained jar shipped to a cluster's executors (gradle sparkSubmitJar). */
    static final String SUBMIT_JAR = "tensim-spark-submit.jar";
    private final JavaSparkContext sc;
    private final int slots;

    /** @param master Spark master URL, or null for spark-submit's or else {@code local[*]} */
    public SparkEngine(String master) {
        SparkConf conf = new SparkConf().setAppName("tensim sweep").set("spark.ui.enabled", "false");
        if (master != null) {
            conf.setMaster(master);
        }
        conf.setIfMissing("spark.master", "local[*]");
        String m = conf.get("spark.master");
        if (m.startsWith("local")) {
            conf.setIfMissing("spark.driver.bindAddress", "127.0.0.1").setIfMissing("spark.driver.host", "127.0.0.1");
        } else if (!conf.contains("spark.jars")) {
            Path jar = submitJar();
            if (jar != null) {
                conf.setJars(new String[] {jar.toString()});
            }
        }
        sc = new JavaSparkContext(conf);
        sc.setLogLevel("WARN");
        slots = Math.max(1, sc.defaultParallelism());
    }

    /** The submit jar next to the running one, or under the project's build/libs; null when absent. */
    private static Path submitJar() {
        for (String e : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            if (e.endsWith(SUBMIT_JAR)) {
                return Path.of(e).toAbsolutePath();
            }
        }
        Path p = Path.of(System.getProperty("tensim.home", "."), "build", "libs", SUBMIT_JAR);
        return Files.isRegularFile(p) ? p.toAbsolutePath() : null;
    }

    @Override
    public String describe() {
        return "spark " + sc.master() + " (" + slots + " task slots)";
    }

    @Override
    public void run(RunSetup setup, List<String> names, List<Point> points, Sink sink) throws IOException,
            InterruptedException {
        List<String> n = List.copyOf(names);
        Iterator<Point> next = points.iterator();
        Deque<JavaFutureAction<List<PointResult>>> running = new ArrayDeque<>();
        int maxInFlight = 4 * slots;
        try {
            while (next.hasNext() || !running.isEmpty()) {
                while (next.hasNext() && running.size() < maxInFlight) {
                    Point p = next.next();
                    running.add(sc.parallelize(List.of(p), 1).map(q -> SceneRun.run(setup, n, q)).collectAsync());
                }
                List<JavaFutureAction<List<PointResult>>> finished = new ArrayList<>();
                for (JavaFutureAction<List<PointResult>> f : running) {
                    if (f.isDone()) {
                        finished.add(f);
                    }
                }
                if (finished.isEmpty()) {
                    Thread.sleep(5);
                    continue;
                }
                for (JavaFutureAction<List<PointResult>> f : finished) {
                    running.remove(f);
                    try {
                        for (PointResult r : f.get()) {
                            sink.accept(r);
                        }
                    } catch (java.util.concurrent.ExecutionException e) {
                        throw new IllegalStateException("a Spark task failed: " + e.getCause(), e.getCause());
                    }
                }
            }
        } finally {
            for (JavaFutureAction<List<PointResult>> f : running) {
                f.cancel(true);
            }
        }
    }

    @Override
    public void close() {
        sc.stop();
    }
}
