package org.tensim.experiment.diaphragm;

import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.StepListener;
import org.tensim.solver.SystemState;

/**
 * Measures one breathing cycle of a running diaphragm (a {@link StepListener}):
 * the dome apex's superior-inferior travel, and extents (max - min of node
 * coordinates: transverse x, antero-posterior y, vertical z) at end-expiration (the
 * cycle's start) and at end-inspiration (start + Ti), of two node sets: the
 * attached nodes (the diaphragm's origins on ribs, cartilage, sternum and spine:
 * the thorax's dimensions at the diaphragm's level, which the paper's claim is
 * about) and all diaphragm nodes (the organ's own extents). The measured cycle is the last complete one of the run
 * ({@link #measuredCycleStart}), so that earlier cycles serve as warm-up.
 */
public final class BreathingMetrics implements StepListener {
    private final DiaphragmScene scene;
    private final double start;
    private final double inspirationEnd;
    private final double end;
    private final int nodes;
    private final int apex;
    private double[] extentsExp;
    private double[] extentsInsp;
    private double[] originsExp;
    private double[] originsInsp;
    private final boolean[] origin;
    private double apexMin = Double.POSITIVE_INFINITY;
    private double apexMax = Double.NEGATIVE_INFINITY;
    private double apexAtExp = Double.NaN;
    private double apexAtInsp = Double.NaN;
    private double[] heightsExp;
    private double largestDescent = Double.NaN;
    /** How each half's top is read ({@link org.tensim.scene.diaphragm.MeasuringSites#domeHeights}). */
    private final org.tensim.scene.diaphragm.DomeHeights domeHeights;
    /** Where each half's top is measured (right, left), for the summary. */
    private final String[] site;
    private double[] domeTopsExp;
    private double[] domeTopsInsp;
    /** Nodes of the 3rd-5th costal cartilages (marker: their mean), empty when the cage has none. */
    private final int[] cartilageMarkers;
    private double[] markerExp;
    private double[] markerInsp;
    /** Per contact pair, its signed distance at the last step, m (scratch). */
    private final double[] distances;
    /** Per diaphragm node, whether it was counted in the contact area of this step (scratch, cleared after). */
    private final boolean[] contactNodes;
    /** Per diaphragm node, its lumped area, m^2. */
    private final double[] nodeArea;
    private double contactArea;
    private double contactAreaExp = Double.NaN;
    private double contactAreaInsp = Double.NaN;
    private double maxContactArea;
    private double maxPenetration;
    private double maxPastGap;
    /** Per contact pair, whether its body is a bone (the penetration and contact figures); false for the liver. */
    private final boolean[] bonePair;
    /** Deepest a node pressed into the liver's support below its rest distance over the run, m. */
    private double maxSupportDeflection;
    private int worstPair = -1;
    private double worstPairT;

    /**
     * @param runSeconds length of the run, s (> 0); the breathing is measured only when the run reaches
     *                   end-inspiration, at the inspiration time Ti ({@link #complete()})
     */
    public BreathingMetrics(DiaphragmScene scene, double runSeconds) {
        this.scene = scene;
        double period = scene.cycle().periodS();
        org.tensim.model.Check.positive("run length", "s", runSeconds);
        this.start = measuredCycleStart(runSeconds, period);
        this.inspirationEnd = start + scene.cycle().inspirationS();
        this.end = start + period;
        this.nodes = scene.diaphragmNodes();
        this.apex = scene.apexNode();
        this.origin = new boolean[nodes];
        for (int v = 0; v < nodes; v++) {
            origin[v] = scene.isAttached(v);
        }
        this.domeHeights = org.tensim.scene.diaphragm.MeasuringSites.domeHeights(scene, DOME_RADIUS_M);
        this.site = org.tensim.scene.diaphragm.MeasuringSites.domeTopSites(scene, DOME_RADIUS_M);
        this.cartilageMarkers = org.tensim.scene.diaphragm.MeasuringSites.cartilageMarkerNodes(scene);
        this.distances = new double[scene.topology().contacts().size()];
        this.bonePair = new boolean[distances.length];
        for (int e = 0; e < bonePair.length; e++) {
            bonePair[e] = scene.isBoneContact(scene.topology().contacts().get(e).body());
        }
        this.contactNodes = new boolean[nodes];
        this.nodeArea = scene.nodeAreasM2();
    }

    /** Horizontal radius about each dome's rest top within which its top is sought at every moment, m. */
    public static final double DOME_RADIUS_M = org.tensim.scene.diaphragm.MeasuringSites.DOME_TOP_RADIUS_M;

    /**
     * The height of each dome's top (right, left), m ({@link org.tensim.scene.diaphragm.MeasuringSites#domeHeights}):
     * within {@link #DOME_RADIUS_M} of its top at rest, the local highest point (the mesh's highest node may lie on
     * the other dome, or on the chest wall the ribs lift), or, for a half without a dome top of its own, the highest
     * point of the upper surface on its midclavicular line.
     */
    private double[] domeTops(SystemState s) {
        return new double[] {domeHeights.top(s.x, 0), domeHeights.top(s.x, 1)};
    }

    /** The mean position of the cartilage markers, m; null without markers. */
    private double[] marker(SystemState s) {
        if (cartilageMarkers.length == 0) {
            return null;
        }
        double[] m = new double[3];
        for (int i : cartilageMarkers) {
            for (int a = 0; a < 3; a++) {
                m[a] += s.x[3 * i + a] / cartilageMarkers.length;
            }
        }
        return m;
    }

    /** Start of the last complete cycle in [0, runSeconds] (0 when there is none), s. */
    public static double measuredCycleStart(double runSeconds, double periodS) {
        return Math.max(0, (Math.floor(runSeconds / periodS + 1e-9) - 1) * periodS);
    }

    /** Call once before the first step (captures the state at t = 0 when the cycle starts there). */
    public void begin(Simulation sim) {
        afterStep(sim);
    }

    @Override
    public void afterStep(Simulation sim) {
        double t = sim.time();
        SystemState s = sim.state();
        if (s.contacts.count() > 0) {
            contacts(s, t);
        }
        if (extentsExp == null && t >= start - 1e-12) {
            extentsExp = extents(s, null);
            originsExp = extents(s, origin);
            apexAtExp = s.x[3 * apex + 2];
            domeTopsExp = domeTops(s);
            markerExp = marker(s);
            contactAreaExp = contactArea;
            heightsExp = new double[nodes]; // once per run, at the measured cycle's start
            for (int i = 0; i < nodes; i++) {
                heightsExp[i] = s.x[3 * i + 2];
            }
        }
        if (extentsInsp == null && t >= inspirationEnd - 1e-12) {
            extentsInsp = extents(s, null);
            originsInsp = extents(s, origin);
            apexAtInsp = s.x[3 * apex + 2];
            domeTopsInsp = domeTops(s);
            markerInsp = marker(s);
            contactAreaInsp = contactArea;
            largestDescent = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < nodes; i++) {
                largestDescent = Math.max(largestDescent, heightsExp[i] - s.x[3 * i + 2]);
            }
        }
        if (t >= start - 1e-12 && t <= end + 1e-12) {
            double z = s.x[3 * apex + 2];
            apexMin = Math.min(apexMin, z);
            apexMax = Math.max(apexMax, z);
        }
    }

    /**
     * One pass over the contact pairs at the state after a step, without allocating: both penetration depths, where
     * the deepest past its start is, and the area of the diaphragm nodes in contact (each node once, by its lumped
     * area, however many bones it touches).
     */
    private void contacts(SystemState s, double t) {
        org.tensim.solver.ContactForces c = s.contacts;
        c.distances(t, s.x, distances);
        double area = 0;
        for (int e = 0; e < distances.length; e++) {
            if (!bonePair[e]) {
                maxSupportDeflection = Math.max(maxSupportDeflection, c.gap(e) - distances[e]);
                continue;
            }
            double past = c.gap(e) - distances[e];
            if (past > maxPastGap) {
                maxPastGap = past;
                worstPair = e;
                worstPairT = t;
            }
            maxPenetration = Math.max(maxPenetration, -distances[e]);
            int v = c.node(e);
            if (past > 0 && v < nodes && !contactNodes[v]) {
                contactNodes[v] = true;
                area += nodeArea[v];
            }
        }
        for (int e = 0; e < distances.length; e++) {
            int v = c.node(e);
            if (v < nodes) {
                contactNodes[v] = false;
            }
        }
        contactArea = area;
        maxContactArea = Math.max(maxContactArea, area);
    }

    private double[] extents(SystemState s, boolean[] only) {
        double[] e = new double[3];
        for (int a = 0; a < 3; a++) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < nodes; i++) {
                if (only != null && !only[i]) {
                    continue;
                }
                double v = s.x[3 * i + a];
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
            }
            e[a] = hi - lo;
        }
        return e;
    }

    /** Where each hemidiaphragm's descent is measured: {right, left} ({@link org.tensim.scene.diaphragm.MeasuringSites#domeTopSites}). */
    public String[] domeSites() {
        return site.clone();
    }

    public double measuredCycleStart() {
        return start;
    }

    public double inspirationEnd() {
        return inspirationEnd;
    }

    /** Whether end-inspiration of the measured cycle was reached. */
    public boolean complete() {
        return extentsInsp != null;
    }

    /** Superior-inferior travel of the dome apex over the measured cycle, m. */
    public double domeExcursionM() {
        return apexMax - apexMin;
    }

    /** Apex z at end-inspiration minus at end-expiration, m (negative: the dome descends). */
    public double apexDescentM() {
        return apexAtInsp - apexAtExp;
    }

    /** Change of the transverse (x) extent of the attached nodes (origins), end-expiration to end-inspiration, m. */
    public double transverseChangeM() {
        return originsInsp[0] - originsExp[0];
    }

    /** Change of the antero-posterior (y) extent of the attached nodes (origins), m. */
    public double apChangeM() {
        return originsInsp[1] - originsExp[1];
    }

    /** Change of the transverse extent of all diaphragm nodes, m. */
    public double transverseChangeAllM() {
        return extentsInsp[0] - extentsExp[0];
    }

    /** Change of the antero-posterior extent of all diaphragm nodes, m. */
    public double apChangeAllM() {
        return extentsInsp[1] - extentsExp[1];
    }

    /** Change of the diaphragm's own vertical (z) extent, m (negative when the domes flatten). */
    public double verticalChangeM() {
        return extentsInsp[2] - extentsExp[2];
    }

    /**
     * The largest descent of any diaphragm node from end-expiration to end-inspiration, m (positive
     * down). On the 10-ring double dome it is 1.76 times the dome excursion;
     * far more means that a region has snapped through (inverted) under the muscle's load.
     */
    public double largestDescentM() {
        return largestDescent;
    }

    /**
     * The measured cycle's figures as summary fields, in millimetres, unrounded, under the names
     * of the diaphragm's summary.json (docs/diaphragm.md); empty when end-inspiration was not reached.
     */
    public java.util.Map<String, Double> fields() {
        java.util.Map<String, Double> f = new java.util.LinkedHashMap<>();
        if (complete()) {
            f.put("dome_excursion_mm", 1e3 * domeExcursionM());
            f.put("apex_descent_mm", -1e3 * apexDescentM());
            f.put("ap_extent_change_mm", 1e3 * apChangeM());
            f.put("transverse_extent_change_mm", 1e3 * transverseChangeM());
            f.put("vertical_extent_change_mm", 1e3 * verticalChangeM());
            f.put("largest_descent_mm", 1e3 * largestDescentM());
            f.put("ap_extent_change_all_nodes_mm", 1e3 * apChangeAllM());
            f.put("transverse_extent_change_all_nodes_mm", 1e3 * transverseChangeAllM());
            f.put("thorax_vertical_change_mm", -1e3 * apexDescentM());
            String[] names = {"right_dome_descent_mm", "left_dome_descent_mm"};
            for (int d = 0; d < 2; d++) {
                double descent = domeTopsExp[d] - domeTopsInsp[d];
                if (Double.isFinite(descent)) {
                    f.put(names[d], 1e3 * descent);
                }
            }
            if (markerExp != null) {
                f.put("cartilage_marker_cranial_mm", 1e3 * (markerInsp[2] - markerExp[2]));
                // +Y is posterior: ventral motion is -y.
                f.put("cartilage_marker_ventral_mm", -1e3 * (markerInsp[1] - markerExp[1]));
            }
        }
        if (scene.topology().contacts().size() > 0) {
            if (complete()) {
                f.put("contact_area_mm2", 1e6 * contactAreaInsp);
            }
            if (!Double.isNaN(contactAreaExp)) {
                f.put("contact_area_expiration_mm2", 1e6 * contactAreaExp);
            }
            f.put("max_contact_area_mm2", 1e6 * maxContactArea);
            f.put("max_bone_penetration_mm", 1e3 * maxPenetration);
            f.put("max_penetration_past_rest_mm", 1e3 * maxPastGap);
            for (boolean bone : bonePair) {
                if (!bone) {
                    f.put("max_liver_deflection_mm", 1e3 * maxSupportDeflection);
                    break;
                }
            }
        }
        return f;
    }

    /**
     * Where the deepest penetration past a node's rest depth happened: the node, the bone and the time; null
     * without contact.
     */
    public String worstPenetration() {
        if (worstPair < 0) {
            return null;
        }
        org.tensim.model.ContactPair p = scene.topology().contacts().get(worstPair);
        return "node " + p.node() + " in " + scene.topology().contactBodies().get(p.body()).name() + " at t = "
                + worstPairT + " s";
    }

    public DiaphragmScene scene() {
        return scene;
    }
}
