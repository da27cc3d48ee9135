package org.tensim.calibration;

import java.util.List;
import java.util.Map;
import org.tensim.sweep.Measure;
import org.tensim.sweep.PointResult;

/**
 * Landmark trajectories (e.g. tracked on 4D-CT): samples (id, t, x, y, z). Each landmark is
 * matched to the diaphragm node nearest to its earliest sample at rest; the residual is the
 * root mean square, over all samples, of the distance between that node at time t and the
 * sample, over the tolerance.
 *
 * @param source      file the landmarks were read from (for reports)
 * @param ids         landmark id of each sample
 * @param times       time of each sample, s
 * @param xyz         position of each sample, m (3 per sample)
 * @param toleranceMm distance that counts as one, mm (> 0)
 * @param weight      weight of the squared residual (> 0)
 * @param prefix      prefix of this target's summary fields (unique per target)
 */
public record LandmarkTarget(String source, String[] ids, double[] times, double[] xyz, double toleranceMm,
        double weight, String prefix) implements Target {
    @Override
    public String describe() {
        return "landmarks " + source + " (" + times.length + " samples), RMS within " + toleranceMm + " mm";
    }

    @Override
    public Measure measure() {
        return new TrackMeasure(ids, times, xyz, prefix);
    }

    @Override
    public List<String> residualNames() {
        return fields();
    }

    @Override
    public double[] residuals(PointResult r) {
        return new double[] {r.field(prefix + "rms_mm") / toleranceMm};
    }

    @Override
    public List<String> fields() {
        return List.of(prefix + "rms_mm");
    }

    /** Follows, on the worker, the matched nodes and sums the squared misses at the samples' times. */
    record TrackMeasure(String[] ids, double[] times, double[] xyz, String prefix) implements Measure {
        @Override
        public Probe start(DiaphragmRunView run) {
            int m = times.length;
            int[] node = new int[m];
            Map<String, Integer> matched = new java.util.HashMap<>();
            Map<String, Integer> earliest = new java.util.HashMap<>();
            for (int k = 0; k < m; k++) {
                Integer e = earliest.get(ids[k]);
                if (e == null || times[k] < times[e]) {
                    earliest.put(ids[k], k);
                }
            }
            for (Map.Entry<String, Integer> e : earliest.entrySet()) {
                int k = e.getValue();
                int best = 0;
                double bestD = Double.POSITIVE_INFINITY;
                for (int v = 0; v < run.diaphragmNodes(); v++) {
                    double d = sq(run.rest()[3 * v] - xyz[3 * k]) + sq(run.rest()[3 * v + 1] - xyz[3 * k + 1])
                            + sq(run.rest()[3 * v + 2] - xyz[3 * k + 2]);
                    if (d < bestD) {
                        bestD = d;
                        best = v;
                    }
                }
                matched.put(e.getKey(), best);
            }
            for (int k = 0; k < m; k++) {
                node[k] = matched.get(ids[k]);
            }
            return new Probe() {
                private final boolean[] taken = new boolean[m];
                private int count;
                private double sum;

                @Override
                public void afterStep(double t, double[] x) {
                    for (int k = 0; k < m; k++) {
                        if (!taken[k] && t >= times[k] - 1e-9) {
                            int v = node[k];
                            sum += sq(x[3 * v] - xyz[3 * k]) + sq(x[3 * v + 1] - xyz[3 * k + 1])
                                    + sq(x[3 * v + 2] - xyz[3 * k + 2]);
                            taken[k] = true;
                            count++;
                        }
                    }
                }

                @Override
                public void finish(Map<String, Double> fields) {
                    if (count == m) {
                        fields.put(prefix + "rms_mm", 1e3 * Math.sqrt(sum / m));
                    }
                }
            };
        }
    }

    private static double sq(double v) {
        return v * v;
    }
}
