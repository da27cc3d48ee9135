package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * Simplified ribs, costal cartilage and sternum placed with axis-aligned boxes
 * (BodyParts3D frame: x = patient's left, y = posterior, z = superior; metres): the
 * project's own ({@link ParametricRibCage}, the default) or BodyParts3D's.
 *
 * <p><b>Ribs</b> are rigid: each is a polyline of {@link #NODES_PER_RIB} driven
 * nodes along an arc inside its box, from the head (medial, posterior, top of the
 * box) sweeping laterally and forwards while descending to the anterior end (front,
 * bottom of the box): with {@code phi} from 0 to {@code phiEnd},
 * {@code |x| = medial + (lateral - medial) sin(phi)},
 * {@code y = yMax - (yMax - yMin) (1 - cos phi) / (1 - cos phiEnd)} and
 * {@code z = zMax - (zMax - zMin) sin(pi phi / (2 phiEnd))} ({@code phiEnd} = 0.8 pi;
 * 0.55 pi for the floating ribs 11 and 12). Every rib node follows its rib's {@link HelicalAxisMotion}.
 *
 * <p><b>Finite helical axis per rib.</b> Wilson et al. (J Appl Physiol 1987)
 * measured from relaxed expiration to full inspiration a pump-handle rotation
 * (about a transverse axis through the rib head: raises the anterior end, which
 * moves forwards) of 11 degrees at rib 3 falling to 7 at rib 7, and a bucket-handle
 * rotation (about an axis through the head along the rib: raises the lateral part,
 * which moves outwards) of 13 falling to 10 degrees. Both are interpolated
 * linearly in the rib number (ribs 1-2 as rib 3; extrapolated below rib 7, at
 * least 2 and 4 degrees) and scaled by {@code ribQuietFraction} for quiet
 * breathing. The two small rotations compose into one helical axis through the
 * head, of direction {@code (a_p e_p + a_b e_b) / |...|} and angle
 * {@code sqrt(a_p^2 + a_b^2)}, each unit axis signed so that its target rises;
 * plus a small translation along the axis.
 *
 * <p><b>Cartilage and sternum</b> follow the ribs as a very stiff mass-spring (the
 * paper): the sternum is a chain of {@link #STERNUM_NODES} free nodes (springs to
 * the next and the next-but-one node); costal cartilage is a spring from the
 * anterior end of each of ribs 1-7 to the two nearest sternum nodes, and from ribs
 * 8-10 to the anterior end of the rib above (the costal margin).
 *
 * <p><b>Spine.</b> A fixed vertical segment in front of the boxes of ribs 9-12 (the
 * paper's Fig. 4 shows the spine's influence): diaphragm nodes near it (the crura)
 * are fixed.
 */
public final class RibCage {
    /** Nodes per simplified rib. */
    public static final int NODES_PER_RIB = 10;
    /** Nodes along the sternum. */
    public static final int STERNUM_NODES = 8;
    /** The sternum's top node lies this fraction of its box's depth in front of the box's back face. */
    public static final double STERNUM_TOP_DEPTH_FRACTION = 0.25;
    /** The sternum's bottom node (xiphoid) lies this fraction of its box's depth behind the box's front face. */
    public static final double STERNUM_BOTTOM_DEPTH_FRACTION = 0.1;

    /** What a segment of the cage is. */
    public enum Kind { RIB, CARTILAGE, STERNUM, SPINE }

    /**
     * A segment between two cage nodes; diaphragm nodes are attached to the nearest one.
     *
     * @param motion the rib's motion for {@link Kind#RIB}, null otherwise
     */
    public record Segment(int a, int b, Kind kind, HelicalAxisMotion motion, String name) {
    }

    private final List<Segment> segments;
    private final int[] ribNodes;
    private final int[] sternumNodes;
    private final Map<String, HelicalAxisMotion> motions;

    private final int[] spineNodes;

    private RibCage(List<Segment> segments, int[] ribNodes, int[] sternumNodes, Map<String, HelicalAxisMotion> m,
            int[] spineNodes) {
        this.spineNodes = spineNodes;
        this.segments = segments;
        this.ribNodes = ribNodes;
        this.sternumNodes = sternumNodes;
        this.motions = m;
    }

    /** A cage from its parts (the thorax's, {@link ThoraxCage}). */
    static RibCage of(List<Segment> segments, int[] ribNodes, int[] sternumNodes, Map<String, HelicalAxisMotion> m,
            int[] spineNodes) {
        return new RibCage(List.copyOf(segments), ribNodes, sternumNodes, m, spineNodes);
    }

    public List<Segment> segments() {
        return segments;
    }

    public int[] ribNodes() {
        return ribNodes.clone();
    }

    /** The two fixed nodes of the spine segment. */
    public int[] spineNodes() {
        return spineNodes.clone();
    }

    public int[] sternumNodes() {
        return sternumNodes.clone();
    }

    /** The helical axis motion of each rib, by name ({@code rib-r7}, {@code rib-l3}, ...). */
    public Map<String, HelicalAxisMotion> motions() {
        return motions;
    }

    /**
     * Builds the cage into topology t; its springs go to {@code springs}.
     *
     * @param boxes {min x, min y, min z, max x, max y, max z} in metres, by name: {@code rib-r1..rib-r12},
     *              {@code rib-l1..rib-l12} and one name starting with {@code sternum}
     */
    static RibCage build(Topology t, SpringList springs, Map<String, double[]> boxes, DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls) {
        List<Segment> segs = new ArrayList<>();
        List<Integer> ribs = new ArrayList<>();
        int[] spineNodes = new int[2];
        Map<String, HelicalAxisMotion> motions = new LinkedHashMap<>();
        double[] sb = null;
        for (Map.Entry<String, double[]> e : boxes.entrySet()) {
            if (e.getKey().startsWith("sternum")) {
                sb = e.getValue();
            }
        }
        if (sb == null) {
            throw new IllegalArgumentException("rib and sternum bounds have no entry named 'sternum...'; expected"
                    + " the sternum's box next to rib-r1..rib-r12 and rib-l1..rib-l12");
        }
        // Sternum: from the manubrium (top, towards the back of its box) to the xiphoid (bottom, front).
        int[] sternum = new int[STERNUM_NODES];
        double sx = 0.5 * (sb[0] + sb[3]);
        for (int i = 0; i < STERNUM_NODES; i++) {
            double f = (double) i / (STERNUM_NODES - 1);
            double y = (sb[4] - STERNUM_TOP_DEPTH_FRACTION * (sb[4] - sb[1])) * (1 - f)
                    + (sb[1] + STERNUM_BOTTOM_DEPTH_FRACTION * (sb[4] - sb[1])) * f;
            double z = sb[5] * (1 - f) + sb[2] * f;
            sternum[i] = t.addNode(sx, y, z, p.structureNodeMassKg()).id();
        }
        for (int i = 0; i < STERNUM_NODES; i++) {
            for (int d = 1; d <= 2 && i + d < STERNUM_NODES; d++) {
                springs.add(sternum[i], sternum[i + d], p.structureStiffness());
            }
            if (i + 1 < STERNUM_NODES) {
                segs.add(new Segment(sternum[i], sternum[i + 1], Kind.STERNUM, null, "sternum"));
            }
        }
        for (String side : new String[] {"r", "l"}) {
            int prevEnd = -1;
            for (int r = 1; r <= 12; r++) {
                String name = "rib-" + side + r;
                double[] b = boxes.get(name);
                if (b == null) {
                    throw new IllegalArgumentException("rib and sternum bounds have no entry '" + name
                            + "'; expected rib-r1..rib-r12 and rib-l1..rib-l12");
                }
                int[] nodes = ribNodes(t, b, r, side.equals("r") ? -1 : 1, p.structureNodeMassKg());
                // True ribs turn (bucket handle) about the chord from the head to their anterior end,
                // which keeps that end (and the sternum) in place; lower ribs about a horizontal line.
                Vec3 head = t.node(nodes[0]).position();
                Vec3 chord = t.node(nodes[nodes.length - 1]).position().minus(head);
                Vec3 bucket = r <= 7 ? chord.normalized() : new Vec3(chord.x(), chord.y(), 0).normalized();
                HelicalAxisMotion m = motion(t, nodes, bucket, r, p, cycle, controls);
                motions.put(name, m);
                for (int k = 0; k < nodes.length; k++) {
                    t.node(nodes[k]).drive(m);
                    ribs.add(nodes[k]);
                    if (k + 1 < nodes.length) {
                        segs.add(new Segment(nodes[k], nodes[k + 1], Kind.RIB, m, name));
                    }
                }
                int end = nodes[nodes.length - 1];
                if (r <= 7) {
                    int[] two = nearestTwo(t, sternum, t.node(end).position());
                    for (int s : two) {
                        springs.add(end, s, p.structureStiffness());
                        segs.add(new Segment(end, s, Kind.CARTILAGE, null, "cartilage-" + side + r));
                    }
                } else if (r <= 10 && prevEnd >= 0) {
                    springs.add(end, prevEnd, p.structureStiffness());
                    segs.add(new Segment(end, prevEnd, Kind.CARTILAGE, null, "cartilage-" + side + r));
                }
                prevEnd = end;
            }
        }
        // The spine: a fixed vertical segment 20 mm in front of the mean posterior extent of the boxes
        // of ribs 9-12 (their angles: the heads, on the vertebral bodies, lie further forward), from
        // their tops down to 100 mm below the lowest rib. A mesh whose crura are not near it gets them
        // from its lowest nodes (DiaphragmSceneBuilder.attachCrura).
        double headY = 0;
        double headZ = Double.POSITIVE_INFINITY;
        double lowZ = Double.POSITIVE_INFINITY;
        for (String side : new String[] {"r", "l"}) {
            for (int r = 9; r <= 12; r++) {
                double[] b = boxes.get("rib-" + side + r);
                headY += b[4] / 8;
                headZ = Math.min(headZ, b[5]);
                lowZ = Math.min(lowZ, b[2]);
            }
        }
        int top = t.addNode(0, headY - 0.02, headZ, p.structureNodeMassKg()).fix().id();
        int bottom = t.addNode(0, headY - 0.02, lowZ - 0.1, p.structureNodeMassKg()).fix().id();
        segs.add(new Segment(top, bottom, Kind.SPINE, null, "spine"));
        spineNodes[0] = top;
        spineNodes[1] = bottom;
        return new RibCage(List.copyOf(segs), ribs.stream().mapToInt(Integer::intValue).toArray(), sternum, motions,
                spineNodes);
    }

    private static int[] ribNodes(Topology t, double[] b, int rib, int sign, double mass) {
        double medial = Math.min(Math.abs(b[0]), Math.abs(b[3]));
        double lateral = Math.max(Math.abs(b[0]), Math.abs(b[3]));
        double phiEnd = rib >= 11 ? 0.55 * Math.PI : 0.8 * Math.PI;
        double norm = 1 - Math.cos(phiEnd);
        int[] ids = new int[NODES_PER_RIB];
        for (int k = 0; k < NODES_PER_RIB; k++) {
            double phi = phiEnd * k / (NODES_PER_RIB - 1);
            double x = sign * (medial + (lateral - medial) * Math.sin(phi));
            double f = (1 - Math.cos(phi)) / norm;
            double y = b[4] - (b[4] - b[1]) * f;
            double z = b[5] - (b[5] - b[2]) * Math.sin(0.5 * Math.PI * phi / phiEnd);
            ids[k] = t.addNode(x, y, z, mass).id();
        }
        return ids;
    }

    /** Pump-handle and bucket-handle amplitudes (degrees, full inspiration) of rib r, Wilson et al. 1987. */
    static double[] wilsonDegrees(int rib) {
        int r = Math.max(rib, 3);
        double pump = Math.max(2, 11 - (r - 3));
        double bucket = Math.max(4, 13 - 0.75 * (r - 3));
        return new double[] {pump, bucket};
    }

    private static HelicalAxisMotion motion(Topology t, int[] nodes, Vec3 bucketDirection, int rib,
            DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls) {
        Vec3 head = t.node(nodes[0]).position();
        Vec3 end = t.node(nodes[nodes.length - 1]).position();
        Vec3 mid = t.node(nodes[nodes.length / 2]).position();
        Vec3 pumpAxis = signedToRaise(new Vec3(1, 0, 0), head, end);
        Vec3 bucketAxis = signedToRaise(bucketDirection, head, mid);
        double[] deg = wilsonDegrees(rib);
        double ap = Math.toRadians(deg[0]) * p.ribQuietFraction();
        double ab = Math.toRadians(deg[1]) * p.ribQuietFraction();
        Vec3 axis = pumpAxis.times(ap).plus(bucketAxis.times(ab));
        double angle = Math.hypot(ap, ab);
        if (angle == 0) {
            return new HelicalAxisMotion(new Vec3(1, 0, 0), head, 0, 0, cycle, controls);
        }
        return new HelicalAxisMotion(axis, head, angle, p.ribTranslationM(), cycle, controls);
    }

    /** The axis, or its opposite, such that a small positive rotation about it through p raises target. */
    private static Vec3 signedToRaise(Vec3 axis, Vec3 p, Vec3 target) {
        Vec3 r = target.minus(p);
        // d(target)/d(theta) = axis x r; its z component must be positive.
        double dz = axis.x() * r.y() - axis.y() * r.x();
        return dz >= 0 ? axis : axis.times(-1);
    }

    static int[] nearestTwo(Topology t, int[] ids, Vec3 p) {
        int best = -1;
        int second = -1;
        double d1 = Double.POSITIVE_INFINITY;
        double d2 = Double.POSITIVE_INFINITY;
        for (int id : ids) {
            double d = t.node(id).position().distance(p);
            if (d < d1) {
                second = best;
                d2 = d1;
                best = id;
                d1 = d;
            } else if (d < d2) {
                second = id;
                d2 = d;
            }
        }
        return new int[] {best, second};
    }

    /** Distance from point q to segment s, m. */
    static double distance(Topology t, Segment s, Vec3 q) {
        Node na = t.node(s.a());
        Node nb = t.node(s.b());
        Vec3 a = na.position();
        Vec3 ab = nb.position().minus(a);
        double l2 = ab.dot(ab);
        double f = l2 == 0 ? 0 : Math.max(0, Math.min(1, q.minus(a).dot(ab) / l2));
        return a.plus(ab.times(f)).distance(q);
    }
}
