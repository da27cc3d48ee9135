package org.tensim.experiment.diaphragm;

import java.util.ArrayList;
import java.util.List;
import org.tensim.scene.diaphragm.DiaphragmScene;

/**
 * The instants whose positions are kept, in this order: the vector pair at mid-inspiration (0, 1),
 * end-expiration and end-inspiration of the measured cycle (2, 3), then the CSV times (4 ...).
 */
final class Snapshots {
    final double[] csvTimes;
    final List<Double> wanted;
    final double[][] kept;
    final double[] keptTime;
    /** Rest positions of the simulated nodes, set when stepping starts. */
    double[] rest;

    private Snapshots(double[] csvTimes, List<Double> wanted) {
        this.csvTimes = csvTimes;
        this.wanted = wanted;
        this.kept = new double[wanted.size()][];
        this.keptTime = new double[wanted.size()];
    }

    static Snapshots plan(DiaphragmScene scene, DiaphragmReport.Options o, double start) {
        double ti = scene.cycle().inspirationS();
        double vecA = start + 0.5 * ti - 0.5 * o.vectorIntervalS();
        // By default end-inspiration and the end of the measured cycle, or the end of a shorter run.
        double[] csvTimes = o.csvTimes() != null ? o.csvTimes().clone()
                : java.util.stream.DoubleStream.of(start + ti, Math.min(o.seconds(), start + scene.cycle().periodS()))
                        .filter(t -> t <= o.seconds()).distinct().toArray();
        for (double t : csvTimes) {
            if (!(t >= 0 && t <= o.seconds())) {
                throw new IllegalArgumentException("CSV time " + t + " s is outside the run [0, " + o.seconds()
                        + "] s");
            }
        }
        List<Double> wanted = new ArrayList<>(List.of(vecA, vecA + o.vectorIntervalS(), start, start + ti));
        for (double t : csvTimes) {
            wanted.add(t);
        }
        return new Snapshots(csvTimes, wanted);
    }

    /** Keeps the positions at time t for every wanted instant within half a step of it. */
    void offer(double t, double dt, double[] x, int simulated) {
        for (int i = 0; i < wanted.size(); i++) {
            if (kept[i] == null && t >= wanted.get(i) - 0.5 * dt) {
                kept[i] = java.util.Arrays.copyOf(x, 3 * simulated);
                keptTime[i] = t;
            }
        }
    }
}
