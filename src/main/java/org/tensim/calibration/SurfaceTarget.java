package org.tensim.calibration;

import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.SurfaceDistance;
import org.tensim.sweep.Measure;
import org.tensim.sweep.PointResult;

/**
 * A target surface at one breathing phase (e.g. segmented from a 4D-CT phase), with no
 * vertex correspondence: at time {@code timeS} of the run, the distance from every
 * diaphragm node to the target surface is measured; the residuals are the mean and the
 * 95th percentile (nearest rank) of those distances over the tolerance.
 *
 * @param source      file the surface was read from (for reports)
 * @param xyz         target vertices, m
 * @param triangles   target triangles
 * @param timeS       simulated time of the phase, s
 * @param toleranceMm distance that counts as one, mm (> 0)
 * @param weight      weight of the squared residuals (> 0)
 * @param prefix      prefix of this target's summary fields (unique per target)
 */
public record SurfaceTarget(String source, double[] xyz, int[] triangles, double timeS, double toleranceMm,
        double weight, String prefix) implements Target {
    @Override
    public String describe() {
        return "surface " + source + " at t = " + timeS + " s, mean and 95th percentile within " + toleranceMm + " mm";
    }

    @Override
    public Measure measure() {
        return new DistanceMeasure(xyz, triangles, timeS, prefix);
    }

    @Override
    public List<String> residualNames() {
        return fields();
    }

    @Override
    public double[] residuals(PointResult r) {
        return new double[] {r.field(prefix + "mean_mm") / toleranceMm, r.field(prefix + "p95_mm") / toleranceMm};
    }

    @Override
    public List<String> fields() {
        return List.of(prefix + "mean_mm", prefix + "p95_mm");
    }

    /** Measures, on the worker, the nodes' distances to the target at the phase's time. */
    record DistanceMeasure(double[] xyz, int[] triangles, double timeS, String prefix) implements Measure {
        @Override
        public Probe start(DiaphragmRunView run) {
            return new Probe() {
                private double mean = Double.NaN;
                private double p95 = Double.NaN;

                @Override
                public void afterStep(double t, double[] x) {
                    if (!Double.isNaN(mean) || t < timeS - 1e-9) {
                        return;
                    }
                    SurfaceDistance s = new SurfaceDistance(xyz, triangles);
                    int n = run.diaphragmNodes();
                    double[] d = new double[n];
                    double sum = 0;
                    for (int i = 0; i < n; i++) {
                        d[i] = 1e3 * s.distance(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
                        sum += d[i];
                    }
                    mean = sum / n;
                    p95 = SurfaceDistance.percentile(d, 95);
                }

                @Override
                public void finish(Map<String, Double> fields) {
                    if (!Double.isNaN(mean)) {
                        fields.put(prefix + "mean_mm", mean);
                        fields.put(prefix + "p95_mm", p95);
                    }
                }
            };
        }
    }
}
