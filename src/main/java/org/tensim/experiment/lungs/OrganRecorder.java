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
 * superior-inferior motion (its nodes' mean z, peak to peak over the measured cycle), each lung's own surface against
 * its pleura ({@link LungSurfaceGap}, every {@link #EVERY_S}), the lung points at every end-inspiration of the run
 * (each breath's mean 3D and basal SI displacement from the start, and the largest change from one breath to the
 * next) and, in {@code summary.json}, {@code lung_points} (end-exhale and end-inhale instants, the period, the
 * superior axis) and {@code organs}.
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
    /** Per term, for its penetration (0) and separation (1): the time and the follower's place, {t, x, y, z}. */
    private final double[][][] worstAt;
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
    private final List<LungSurfaceGap> gaps = new ArrayList<>();
    private double nextGap;
    private double[] startPoints;
    private double nextInhale;
    private final List<double[]> inhales = new ArrayList<>(); // {t, mean 3D m, basal SI m}

    /** @param terms the organs' installed terms ({@link ThoraxOrgans#install}), in the order of its couplings */
    public OrganRecorder(ThoraxOrgans organs, List<SurfaceSliding> terms) {
        this.organs = organs;
        this.terms = terms;
        this.worstPen = new double[terms.size()];
        this.worstSep = new double[terms.size()];
        this.worstAt = new double[terms.size()][2][];
        for (double[][] w : worstAt) {
            w[0] = new double[] {Double.NaN, 0, 0, 0};
            w[1] = new double[] {Double.NaN, 0, 0, 0};
        }
        for (int i = 0; i < organs.lungs().size(); i++) {
            ThoraxOrgans.Coupling c = organs.couplings().get(i);
            gaps.add(new LungSurfaceGap(c.followers(), c.surface(), c.triangles()));
        }
    }

    @Override
    public void begin(Simulation sim, double measuredStartS, double inspirationEndS, double periodS) {
        start = measuredStartS;
        inspEnd = inspirationEndS;
        period = periodS;
        nextFrame = start;
        nextRead = 0;
        nextGap = 0;
        nextInhale = inspirationEndS - periodS * Math.floor(inspirationEndS / periodS);
        startPoints = null;
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
                keepWorst(i, 0, t, terms.get(i).extremeAt(x, 1));
                keepWorst(i, 1, t, terms.get(i).extremeAt(x, -1));
            }
            if (organs.liver() != null && t >= start - half && t <= start + period + half) {
                double z = meanZ(x, organs.liver().firstNode(), organs.liver().nodeCount());
                liverMin = Math.min(liverMin, z);
                liverMax = Math.max(liverMax, z);
            }
        }
        if (t >= nextGap - half) {
            nextGap += EVERY_S;
            for (LungSurfaceGap g : gaps) {
                g.read(x, t);
            }
        }
        if (startPoints == null) {
            startPoints = new double[3 * organs.points().pointCount()];
            organs.points().apply(x, startPoints);
        }
        if (t >= nextInhale - half) {
            nextInhale += period;
            inhales.add(breath(t, x));
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

    /** The points' mean 3D and basal SI displacement from the run's start at an end-inspiration. */
    private double[] breath(double t, double[] x) {
        double[] p = new double[startPoints.length];
        organs.points().apply(x, p);
        double[] d = new double[p.length];
        for (int k = 0; k < d.length; k++) {
            d[k] = p[k] - startPoints[k];
        }
        int[] all = new int[p.length / 3];
        for (int i = 0; i < all.length; i++) {
            all[i] = i;
        }
        try {
            SiProfile s = SiProfile.of(startPoints, d, new double[] {0, 0, 1}, all);
            return new double[] {t, s.mean3dM(), s.basalSiM()};
        } catch (IllegalArgumentException e) {
            return new double[] {t, Double.NaN, Double.NaN};
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
        o.put("liver_held_nodes", organs.liverHeld().length);
        o.put("liver_abdomen_nodes", organs.liverSupported().length);
        o.put("points", lung.length);
        for (int i = 0; i < terms.size(); i++) {
            Map<String, Object> c = new LinkedHashMap<>();
            c.put("followers", terms.get(i).pairCount());
            c.put("max_penetration_mm", round(1e3 * worstPen[i], 3));
            c.put("max_penetration_at", where(worstAt[i][0][0], java.util.Arrays.copyOfRange(worstAt[i][0], 1, 4)));
            c.put("max_separation_mm", round(1e3 * worstSep[i], 3));
            c.put("max_separation_at", where(worstAt[i][1][0], java.util.Arrays.copyOfRange(worstAt[i][1], 1, 4)));
            if (i < gaps.size()) {
                LungSurfaceGap g = gaps.get(i);
                c.put("lung_surface_max_penetration_mm", round(1e3 * g.maxPenetrationM(), 3));
                c.put("lung_surface_max_penetration_at", where(g.penetrationTimeS(), g.penetrationAtM()));
                c.put("lung_surface_max_separation_mm", round(1e3 * g.maxSeparationM(), 3));
                c.put("lung_surface_max_separation_at", where(g.separationTimeS(), g.separationAtM()));
            }
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
        List<Map<String, Object>> breaths = new ArrayList<>();
        double change = 0;
        for (int k = 0; k < inhales.size(); k++) {
            double[] b = inhales.get(k);
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("end_inhale_s", round(b[0], 4));
            // Not measured (a cloud SiProfile refuses) is null in the JSON, not NaN.
            m.put("mean_3d_mm", Double.isNaN(b[1]) ? null : round(1e3 * b[1], 3));
            m.put("basal_si_mm", Double.isNaN(b[2]) ? null : round(1e3 * b[2], 3));
            breaths.add(m);
            if (k > 0 && !Double.isNaN(b[1]) && !Double.isNaN(inhales.get(k - 1)[1])) {
                double[] a = inhales.get(k - 1);
                change = Math.max(change, Math.max(Math.abs(b[1] - a[1]) / Math.abs(b[1]),
                        Math.abs(b[2] - a[2]) / Math.abs(b[2])));
            }
        }
        o.put("breaths", breaths);
        if (inhales.size() > 1) {
            // The largest relative change of a breath's figures from the breath before.
            o.put("breath_to_breath_change", round(change, 4));
        }
        summary.put("organs", o);
    }

    /** Keeps term i's largest penetration (kind 0) or separation (1) so far, with its time and place. */
    private void keepWorst(int i, int kind, double t, double[] m) {
        double[] worst = kind == 0 ? worstPen : worstSep;
        if (m[0] > worst[i]) {
            worst[i] = m[0];
            worstAt[i][kind] = new double[] {t, m[1], m[2], m[3]};
        }
    }

    private static Map<String, Object> where(double t, double[] at) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("t_s", Double.isNaN(t) ? null : round(t, 3));
        m.put("point_mm", Double.isNaN(t) ? null : List.of(round(1e3 * at[0], 1), round(1e3 * at[1], 1),
                round(1e3 * at[2], 1)));
        return m;
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
