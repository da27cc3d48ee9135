package org.tensim.experiment.lungs;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.analysis.lungs.SiProfile;
import org.tensim.io.CsvWriter;
import org.tensim.scene.diaphragm.RunRecorder;
import org.tensim.scene.lungs.ThoraxOrgans;
import org.tensim.solver.Simulation;
import org.tensim.solver.SurfaceSliding;

/**
 * Records the organs of a thorax run: the lung points every {@link #EVERY_S} over the measured cycle
 * ({@code lung-points.csv}: {@code t_s,point,lung,x_mm,y_mm,z_mm}, lung "right" or "left"), the couplings' largest
 * departure from their rest relation over the run (penetration and separation, mm, read every
 * {@link #READ_S}), the liver's
 * superior-inferior motion (its nodes' mean z, peak to peak over the measured cycle) and, in {@code summary.json},
 * {@code lung_points} (end-exhale and end-inhale instants, the period, the superior axis) and {@code organs}.
 */
public final class OrganRecorder implements RunRecorder {
    /** Interval of the lung points' instants, s. */
    public static final double EVERY_S = 0.05;
    /** The file of the points' trajectories, in the run's folder. */
    public static final String FILE = "lung-points.csv";
    /** Interval of the couplings' and the liver's read-outs, s. */
    static final double READ_S = 0.01;

    private final ThoraxOrgans organs;
    private final List<SurfaceSliding> terms;
    private final List<Double> times = new ArrayList<>();
    private final List<double[]> frames = new ArrayList<>();
    private final double[] worstPen;
    private final double[] worstSep;
    private double start = Double.NaN;
    private double inspEnd;
    private double period;
    private double nextFrame;
    private double nextRead;
    private double lastT;
    private double liverMin = Double.POSITIVE_INFINITY;
    private double liverMax = Double.NEGATIVE_INFINITY;
    private double[] eePoints;
    private double[] eiPoints;

    /** @param terms the organs' installed terms ({@link ThoraxOrgans#install}), in the order of its couplings */
    public OrganRecorder(ThoraxOrgans organs, List<SurfaceSliding> terms) {
        this.organs = organs;
        this.terms = terms;
        this.worstPen = new double[terms.size()];
        this.worstSep = new double[terms.size()];
    }

    @Override
    public void begin(Simulation sim, double measuredStartS, double inspirationEndS, double periodS) {
        start = measuredStartS;
        inspEnd = inspirationEndS;
        period = periodS;
        nextFrame = start;
        nextRead = 0;
        lastT = sim.time();
        afterStep(sim);
    }

    @Override
    public void afterStep(Simulation sim) {
        double t = sim.time();
        double half = t > lastT ? 0.5 * (t - lastT) : 1e-9; // half a step: an instant is the step nearest it
        lastT = t;
        double[] x = sim.state().x;
        if (t >= nextRead - half) {
            nextRead += READ_S;
            for (int i = 0; i < terms.size(); i++) {
                worstPen[i] = Math.max(worstPen[i], terms.get(i).maxPenetrationM(x));
                worstSep[i] = Math.max(worstSep[i], terms.get(i).maxSeparationM(x));
            }
            if (organs.liver() != null && t >= start - half && t <= start + period + half) {
                double z = meanZ(x, organs.liver().firstNode(), organs.liver().nodeCount());
                liverMin = Math.min(liverMin, z);
                liverMax = Math.max(liverMax, z);
            }
        }
        if (t >= nextFrame - half && nextFrame <= start + period + 1e-9) {
            double[] p = new double[3 * organs.points().pointCount()];
            organs.points().apply(x, p);
            times.add(nextFrame);
            frames.add(p);
            if (eePoints == null) {
                eePoints = p;
            }
            if (eiPoints == null && nextFrame >= inspEnd - half) {
                eiPoints = p;
            }
            nextFrame = start + EVERY_S * times.size();
        }
    }

    @Override
    public List<String> files() {
        return List.of(FILE);
    }

    @Override
    public void finish(Map<String, Object> summary, Path folder) throws IOException {
        int[] lung = organs.pointLung();
        try (CsvWriter w = new CsvWriter(folder.resolve(FILE), List.of("t_s", "point", "lung", "x_mm",
                "y_mm", "z_mm"), 1000)) {
            for (int f = 0; f < frames.size(); f++) {
                double[] p = frames.get(f);
                for (int i = 0; i < lung.length; i++) {
                    w.rowText(fmt(times.get(f)), Integer.toString(i), lung[i] == 0 ? "right" : "left",
                            fmt(1e3 * p[3 * i]), fmt(1e3 * p[3 * i + 1]), fmt(1e3 * p[3 * i + 2]));
                }
            }
        }
        Map<String, Object> lp = new LinkedHashMap<>();
        lp.put("end_exhale_s", start);
        lp.put("end_inhale_s", inspEnd);
        lp.put("period_s", period);
        lp.put("superior", List.of(0, 0, 1));
        summary.put("lung_points", lp);
        Map<String, Object> o = new LinkedHashMap<>();
        o.put("lung_nodes", organs.lungs().stream().mapToInt(l -> l.body().nodeCount()).sum());
        o.put("liver_nodes", organs.liver() == null ? 0 : organs.liver().nodeCount());
        o.put("points", lung.length);
        for (int i = 0; i < terms.size(); i++) {
            Map<String, Object> c = new LinkedHashMap<>();
            c.put("followers", terms.get(i).pairCount());
            c.put("max_penetration_mm", round(1e3 * worstPen[i], 3));
            c.put("max_separation_mm", round(1e3 * worstSep[i], 3));
            o.put(organs.couplings().get(i).name(), c);
        }
        if (organs.liver() != null && liverMax >= liverMin) {
            double si = 1e3 * (liverMax - liverMin);
            o.put("liver_si_mm", round(si, 2));
            Object dome = summary.get("right_dome_descent_mm");
            if (dome instanceof Number n && n.doubleValue() != 0) {
                o.put("liver_si_to_right_dome", round(si / n.doubleValue(), 3));
            }
        }
        if (eePoints != null && eiPoints != null) {
            for (int which = -1; which <= 1; which++) {
                List<Integer> subset = new ArrayList<>();
                for (int i = 0; i < lung.length; i++) {
                    if (which < 0 || lung[i] == which) {
                        subset.add(i);
                    }
                }
                double[] d = new double[eePoints.length];
                for (int k = 0; k < d.length; k++) {
                    d[k] = eiPoints[k] - eePoints[k];
                }
                Map<String, Object> m = new LinkedHashMap<>();
                try {
                    SiProfile s = SiProfile.of(eePoints, d, new double[] {0, 0, 1},
                            subset.stream().mapToInt(Integer::intValue).toArray());
                    m.put("basal_si_mm", round(1e3 * s.basalSiM(), 2));
                    m.put("mean_3d_mm", round(1e3 * s.mean3dM(), 2));
                    // An empty bin's ratio is NaN: null in the JSON.
                    m.put("si_profile_ratio", java.util.Arrays.stream(s.ratio()).mapToObj(r -> Double.isNaN(r)
                            ? null : (Object) round(r, 3)).toList());
                } catch (IllegalArgumentException e) {
                    m.put("not_measured", e.getMessage());
                }
                o.put(which < 0 ? "lungs" : which == 0 ? "right_lung" : "left_lung", m);
            }
        }
        summary.put("organs", o);
    }

    private static String fmt(double v) {
        return String.format(java.util.Locale.ROOT, "%.4f", v);
    }

    private static double meanZ(double[] x, int first, int n) {
        double s = 0;
        for (int i = first; i < first + n; i++) {
            s += x[3 * i + 2];
        }
        return s / n;
    }

    private static double round(double v, int digits) {
        double f = Math.pow(10, digits);
        return Double.isFinite(v) ? Math.round(v * f) / f : v;
    }
}
