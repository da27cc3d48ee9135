package org.tensim.scene.tunable;

import java.util.ArrayList;
import java.util.List;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.MeasuringSites;
import org.tensim.solver.ContactForces;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * The diaphragm's running state for the window ({@link LiveState}): the nodes touching a bone at this step (an
 * active contact pair: closer to the bone than the pair's gap) marked in their own colour, and the readouts: the
 * descent of each dome's top from rest (the highest free upper-surface node within
 * {@link MeasuringSites#DOME_TOP_RADIUS_M} of the top at rest, as the run's summary measures it), the 3rd-5th costal
 * cartilages' cranial and ventral motion, the area in contact (the nodes in contact by their lumped area, each once),
 * the deepest penetration below a bone's surface now and so far, the attached area and the tendon's share. Figures a
 * scene does not have (contact without bone surfaces, markers without cartilage) are left out.
 *
 * <p>Measured on the simulation thread after every step, from the state the step left, with
 * {@link ContactForces#distances} into arrays allocated here once: nothing is allocated per step and the model is
 * not locked.
 */
public final class DiaphragmLiveState implements LiveState {
    /** Mark of a node in contact with a bone. */
    public static final byte IN_CONTACT = 1;

    private final int nodes;
    private final int body;
    /** How each dome's top (right, left) is read. */
    private final org.tensim.scene.diaphragm.DomeHeights domeHeights;
    private final double[] restTop = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
    private final int[] markers;
    private final double[] restMarker = new double[3];
    private final double[] nodeArea;
    private final double[] distances;
    /** Per contact pair, whether its body is a bone (not the liver's support). */
    private final boolean[] bonePair;
    private final List<Readout> readouts = new ArrayList<>();
    private final List<Legend> legend = new ArrayList<>();
    private final int right;
    private final int left;
    private final int cranial;
    private final int ventral;
    private final int contactArea;
    private final int penetration;
    private final int deepest;
    private final int attached;
    private final int tendon;
    private final double attachedMm2;
    private final double tendonPercent;
    private double deepestSoFar;

    /**
     * @param scene the scene
     * @param rest  the diaphragm's and cage's positions at rest, m (3 per node; the simulation's {@code x0})
     */
    public DiaphragmLiveState(DiaphragmScene scene, double[] rest) {
        this(scene, rest, 0);
    }

    /**
     * As {@link #DiaphragmLiveState(DiaphragmScene, double[])} for the scene's nodes in body {@code body} of the view
     * (a mapped scene's carried nodes: the scene's node ids, their positions the mapping's).
     */
    public DiaphragmLiveState(DiaphragmScene scene, double[] rest, int body) {
        this.body = body;
        this.nodes = scene.diaphragmNodes();
        this.domeHeights = MeasuringSites.domeHeights(scene, MeasuringSites.DOME_TOP_RADIUS_M);
        for (int d = 0; d < 2; d++) {
            restTop[d] = domeHeights.top(rest, d);
        }
        this.markers = MeasuringSites.cartilageMarkerNodes(scene);
        mean(rest, restMarker);
        this.nodeArea = scene.nodeAreasM2();
        this.attachedMm2 = 1e6 * scene.attachedAreaM2();
        this.tendonPercent = 100 * scene.tendonAreaFraction();
        boolean contact = !scene.topology().contacts().isEmpty();
        this.distances = new double[scene.topology().contacts().size()];
        this.bonePair = new boolean[distances.length];
        for (int e = 0; e < bonePair.length; e++) {
            bonePair[e] = scene.isBoneContact(scene.topology().contacts().get(e).body());
        }
        right = add("Right dome descent", "mm", "right_dome_descent_mm");
        left = add("Left dome descent", "mm", "left_dome_descent_mm");
        cranial = markers.length > 0 ? add("Cartilage 3-5 cranial", "mm", "cartilage_marker_cranial_mm") : -1;
        ventral = markers.length > 0 ? add("Cartilage 3-5 ventral", "mm", "cartilage_marker_ventral_mm") : -1;
        contactArea = contact ? add("Contact area", "mm^2", "contact_area_mm2") : -1;
        penetration = contact ? add("Bone penetration now", "mm", "bone_penetration_mm") : -1;
        deepest = contact ? add("Max bone penetration", "mm", "max_bone_penetration_mm") : -1;
        attached = scene.bones() != null ? add("Attached area", "mm^2", "attached_area_mm2") : -1;
        tendon = add("Tendon share of upper surface", "%", "tendon_area_percent");
        legend.add(new Legend("muscle", DiaphragmViewScene.MUSCLE_COLOUR));
        legend.add(new Legend("central tendon", DiaphragmViewScene.TENDON_COLOUR));
        legend.add(new Legend("attached (origins)", DiaphragmViewScene.ATTACHED));
        if (contact) {
            legend.add(new Legend("touching a bone now", DiaphragmViewScene.IN_CONTACT_COLOUR));
        }
    }

    private int add(String label, String unit, String key) {
        readouts.add(new Readout(label, unit, key));
        return readouts.size() - 1;
    }

    private void mean(double[] x, double[] out) {
        for (int a = 0; a < 3; a++) {
            out[a] = 0;
        }
        for (int i : markers) {
            for (int a = 0; a < 3; a++) {
                out[a] += x[3 * i + a] / markers.length;
            }
        }
    }

    @Override
    public int body() {
        return body;
    }

    @Override
    public float[][] markColours() {
        return new float[][] {null, DiaphragmViewScene.IN_CONTACT_COLOUR};
    }

    @Override
    public List<Legend> legend() {
        return List.copyOf(legend);
    }

    @Override
    public List<Readout> readouts() {
        return List.copyOf(readouts);
    }

    @Override
    public void measure(Simulation sim, byte[] marks, double[] out) {
        SystemState s = sim.state();
        out[right] = 1e3 * (restTop[0] - domeHeights.top(s.x, 0));
        out[left] = 1e3 * (restTop[1] - domeHeights.top(s.x, 1));
        if (cranial >= 0) {
            double z = 0;
            double y = 0;
            for (int i : markers) {
                z += s.x[3 * i + 2] / markers.length;
                y += s.x[3 * i + 1] / markers.length;
            }
            out[cranial] = 1e3 * (z - restMarker[2]);
            out[ventral] = -1e3 * (y - restMarker[1]); // +y is posterior
        }
        ContactForces c = s.contacts;
        if (contactArea >= 0 && c.count() == distances.length) {
            java.util.Arrays.fill(marks, (byte) 0);
            c.distances(sim.time(), s.x, distances);
            double area = 0;
            double deepestNow = 0;
            for (int e = 0; e < distances.length; e++) {
                if (!bonePair[e]) {
                    continue; // the liver's support: pressed in by design, no bone
                }
                deepestNow = Math.max(deepestNow, -distances[e]);
                int v = c.node(e);
                if (c.gap(e) - distances[e] > 0 && v < marks.length && marks[v] != IN_CONTACT) {
                    marks[v] = IN_CONTACT;
                    area += v < nodes ? nodeArea[v] : 0;
                }
            }
            deepestSoFar = Math.max(deepestSoFar, deepestNow);
            out[contactArea] = 1e6 * area;
            out[penetration] = 1e3 * deepestNow;
            out[deepest] = 1e3 * deepestSoFar;
        } else if (contactArea >= 0) {
            // The tendon as springs drops the contacts (RigidLinksAsSprings): nothing to read.
            out[contactArea] = Double.NaN;
            out[penetration] = Double.NaN;
            out[deepest] = Double.NaN;
        }
        if (attached >= 0) {
            out[attached] = attachedMm2;
        }
        out[tendon] = tendonPercent;
    }

    /** Index of a readout by its label, or -1 (for tests and tools). */
    public int readout(String label) {
        for (int i = 0; i < readouts.size(); i++) {
            if (readouts.get(i).label().equals(label)) {
                return i;
            }
        }
        return -1;
    }
}
