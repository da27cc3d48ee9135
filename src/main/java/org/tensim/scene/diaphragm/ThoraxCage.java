package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.RigidMotion;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * The cage of a thorax made of bone surfaces ({@link Bones}; package-private, built by the scene
 * builder): each rib rigid and moved by its own finite-helical-axis law, the sternum following the
 * ribs, the costal cartilage a very stiff mass-spring between them (the paper), the vertebrae fixed.
 *
 * <p><b>Each rib's rotation.</b> Wilson et al. (J Appl Physiol 62:1872, 1987) measured by CT from relaxed
 * expiration (FRC) to full inspiration (TLC) that each rib's plane turns about an axis through the spine, with a
 * pump-handle component (about the mediolateral axis) of 11 degrees at rib 3 falling to 7 at rib 7 and a
 * bucket-handle component (about the antero-posterior axis) of 13 falling to 10 ({@link RibCage#wilsonDegrees}).
 * Here each rib turns through its head (the vertex nearest the midline) by the two components added as rotation
 * vectors, each times {@link #TIDAL_FRACTION} (a tidal breath's share), signed to raise the rib: the pump handle
 * about the mediolateral axis raises the anterior end and carries it forwards (the ribs slope down to the front);
 * the bucket handle of a true rib (1-7) turns about the chord from its head to its anterior end, the rib's two
 * fixed points in the classic description (De Troyer, Kirkwood and Wilson, Physiol Rev 85:717, 2005), so that it
 * lifts and everts the rib's lateral part without pulling the anterior end sideways away from the sternum (a
 * rotation of a true rib about an oblique axis through its head, such as its neck, would move the costochondral
 * junction some 6 mm laterally per breath and stretch the nearly inextensible cartilage, whose chain then
 * straightens and rises instead of following the rib); that of a false or floating rib (8-12), whose end is free,
 * about the antero-posterior axis, widening the costal margin.
 *
 * <p><b>Sternum.</b> It follows the ribs: it is carried by the mean displacement of the anterior ends
 * of the true ribs 1-7 (a translation; the sternum's own small rotation is left out).
 *
 * <p><b>Cartilage.</b> Each costal cartilage is a chain of {@link #CARTILAGE_NODES} nodes along it
 * (the centroids of equal slices along its length), joined by springs to the next and next-but-one
 * node of stiffness {@code structureStiffness}; its lateral end is driven with its rib, its medial
 * end with the sternum (cartilages 1-7) or tied to the cartilage above (8-10, the costal margin).
 * For contact and attachment the cartilage's surface moves with its rib.
 *
 * <p>The ribs, sternum and cartilage also appear as segments (polylines through slice centroids), for
 * the viewer and the breathing metrics' cartilage markers.
 */
final class ThoraxCage {
    /** Polyline nodes per rib (slice centroids). */
    static final int RIB_NODES = 10;
    /** Chain nodes per costal cartilage. */
    static final int CARTILAGE_NODES = 5;
    /** Polyline nodes along the sternum (manubrium, body and xiphoid together). */
    static final int STERNUM_NODES = 8;

    /** A built cage: the cage's segments and nodes, and the rigid motion of every bone (by index in Bones). */
    record Built(RibCage cage, RigidMotion[] motions) {
    }

    private ThoraxCage() {
    }

    static Built build(Topology t, SpringList springs, Bones bones, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls) {
        List<Bones.Bone> all = bones.all();
        RigidMotion[] motions = new RigidMotion[all.size()];
        double[] centre = ribCentre(bones);
        List<RibCage.Segment> segs = new ArrayList<>();
        List<Integer> ribIds = new ArrayList<>();
        Map<String, HelicalAxisMotion> ribMotions = new LinkedHashMap<>();
        Map<String, int[]> ribPolylines = new LinkedHashMap<>();
        List<Vec3> trueRibEnds = new ArrayList<>();
        List<HelicalAxisMotion> trueRibMotions = new ArrayList<>();
        for (Bones.Bone b : bones.of(Bones.Kind.RIB)) {
            HelicalAxisMotion m = ribMotion(b, centre[0], p, cycle, controls);
            motions[bones.indexOf(b)] = m;
            ribMotions.put(b.name(), m);
            int[] nodes = polyline(t, b.mesh(), centre, RIB_NODES, p.structureNodeMassKg());
            for (int k = 0; k < nodes.length; k++) {
                t.node(nodes[k]).drive(m);
                ribIds.add(nodes[k]);
                if (k + 1 < nodes.length) {
                    segs.add(new RibCage.Segment(nodes[k], nodes[k + 1], RibCage.Kind.RIB, m, b.name()));
                }
            }
            ribPolylines.put(key(b.side(), b.index()), nodes);
            if (b.index() <= TRUE_RIBS) {
                trueRibEnds.add(t.node(nodes[nodes.length - 1]).position());
                trueRibMotions.add(m);
            }
        }
        RigidMotion sternumMotion = trueRibMotions.isEmpty() ? RigidMotion.FIXED
                : new FollowingMotion(trueRibMotions, trueRibEnds);
        List<Bones.Bone> sternumParts = new ArrayList<>(bones.of(Bones.Kind.STERNUM));
        sternumParts.addAll(bones.of(Bones.Kind.XIPHOID));
        for (Bones.Bone b : sternumParts) {
            motions[bones.indexOf(b)] = sternumMotion;
        }
        int[] sternum = sternumParts.isEmpty() ? new int[0] : sternumLine(t, sternumParts, p.structureNodeMassKg());
        for (int k = 0; k < sternum.length; k++) {
            t.node(sternum[k]).drive(sternumMotion);
            if (k + 1 < sternum.length) {
                segs.add(new RibCage.Segment(sternum[k], sternum[k + 1], RibCage.Kind.STERNUM, null, "sternum"));
            }
        }
        // Cartilage: a stiff chain from its rib's anterior end to the sternum or the cartilage above.
        Map<String, int[]> chains = new LinkedHashMap<>();
        List<Bones.Bone> cartilages = new ArrayList<>(bones.of(Bones.Kind.CARTILAGE));
        cartilages.sort((a, c) -> Integer.compare(a.index(), c.index()));
        for (Bones.Bone b : cartilages) {
            int[] rib = ribPolylines.get(key(b.side(), b.index()));
            HelicalAxisMotion rm = rib == null ? null : ribMotions.get(ribName(b));
            motions[bones.indexOf(b)] = rm != null ? rm : sternumMotion;
            int[] chain = polyline(t, b.mesh(), centre, CARTILAGE_NODES, p.structureNodeMassKg());
            if (rib != null) {
                // Orient the chain from the rib's end (lateral) to the sternum (medial).
                Vec3 ribEnd = t.node(rib[rib.length - 1]).position();
                if (t.node(chain[0]).position().distance(ribEnd) > t.node(chain[chain.length - 1]).position()
                        .distance(ribEnd)) {
                    reverse(chain);
                }
                t.node(chain[0]).drive(rm);
            }
            for (int k = 0; k < chain.length; k++) {
                for (int d = 1; d <= 2 && k + d < chain.length; d++) {
                    springs.add(chain[k], chain[k + d], p.structureStiffness());
                }
                if (k + 1 < chain.length) {
                    segs.add(new RibCage.Segment(chain[k], chain[k + 1], RibCage.Kind.CARTILAGE, null, b.name()));
                }
            }
            int medial = chain[chain.length - 1];
            int[] above = chains.get(key(b.side(), b.index() - 1));
            int[] held = null; // the nodes the cartilage's medial end joins
            if (b.index() <= TRUE_RIBS && sternum.length > 0) {
                t.node(medial).drive(sternumMotion);
                held = sternum;
            } else if (above != null) {
                int[] two = RibCage.nearestTwo(t, above, t.node(medial).position());
                for (int s : two) {
                    springs.add(medial, s, p.structureStiffness());
                }
                held = above;
            }
            brace(t, springs, chain, rib, held, p.structureStiffness());
            chains.put(key(b.side(), b.index()), chain);
        }
        for (Bones.Bone b : bones.all()) {
            if (motions[bones.indexOf(b)] == null) {
                motions[bones.indexOf(b)] = RigidMotion.FIXED; // vertebrae, liver
            }
        }
        int[] spine = spine(t, bones, p.structureNodeMassKg(), segs);
        int[] ribArray = ribIds.stream().mapToInt(Integer::intValue).toArray();
        return new Built(RibCage.of(segs, ribArray, sternum, ribMotions, spine), motions);
    }

    /**
     * Braces a cartilage chain's free nodes to the bones it joins: each to the last two nodes of its rib's polyline
     * and to the two nearest nodes of what its medial end joins (the sternum's line, or the cartilage above), by
     * springs of the chain's stiffness. A chain of springs to the next and next-but-one node alone is a mechanism (3
     * free nodes, 9 degrees of freedom, 7 springs): its middle nodes' place is not set by its ends, and the least
     * mismatch between the rib's end and the sternum moves them by more than the mismatch (they rose 15 mm where
     * their ends rose 10). Braced, each free node is held by at least four non-collinear points.
     */
    private static void brace(Topology t, SpringList springs, int[] chain, int[] rib, int[] held, double k) {
        for (int c : chain) {
            if (t.node(c).isDriven()) {
                continue;
            }
            if (rib != null && rib.length >= 2) {
                springs.add(c, rib[rib.length - 1], k);
                springs.add(c, rib[rib.length - 2], k);
            }
            // (The medial end of a false rib's cartilage is tied to the cartilage above already.)
            if (held != null && held.length >= 2 && c != chain[chain.length - 1]) {
                for (int s : RibCage.nearestTwo(t, held, t.node(c).position())) {
                    springs.add(c, s, k);
                }
            }
        }
    }

    /**
     * Share of Wilson et al.'s FRC-to-TLC rotations a tidal breath takes: the tidal volume (about 0.5 L) over the
     * inspiratory capacity (about 3 L), the rib cage's displacement being nearly linear in its volume. The
     * parametric cage keeps its own {@code ribQuietFraction} (0.3); {@code --rib-amplitude} scales both.
     */
    static final double TIDAL_FRACTION = 0.17;
    /** Ribs 1-7 reach the sternum through their own cartilage. */
    static final int TRUE_RIBS = 7;

    /**
     * A rib's rotation per tidal breath (class comment): through its head, Wilson et al.'s pump-handle component
     * about the mediolateral axis and bucket-handle component about the chord from the head to the rib's anterior
     * end (the costochondral junction; for ribs 8-12 the antero-posterior axis), each times
     * {@link #TIDAL_FRACTION}, signed to raise the anterior end and the rib's lateral part (the two components add
     * as rotation vectors); plus the parametric cage's small translation along the axis.
     */
    static HelicalAxisMotion ribMotion(Bones.Bone rib, double midX, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls) {
        TriangleMesh m = rib.mesh();
        // midX: the body's midline (x, m); the rib's head is the vertex nearest it.
        int head = -1;
        double bestMedial = Double.POSITIVE_INFINITY;
        for (int v = 0; v < m.vertexCount(); v++) {
            double medial = Math.abs(m.coord(v, 0) - midX);
            if (medial < bestMedial) {
                bestMedial = medial;
                head = v;
            }
        }
        Vec3 h = vertex(m, head);
        Vec3 end = anteriorEnd(m, h);
        Vec3 chord = end.minus(h);
        if (!(chord.norm() > 1e-3)) {
            throw new IllegalArgumentException("rib " + rib.name() + ": its head and anterior end coincide (" + h
                    + "); cannot place its axes");
        }
        int lateral = head;
        for (int v = 0; v < m.vertexCount(); v++) {
            if (Math.abs(m.coord(v, 0) - midX) > Math.abs(m.coord(lateral, 0) - midX)) {
                lateral = v;
            }
        }
        Vec3 pump = raising(new Vec3(1, 0, 0), chord);
        // A true rib's anterior end is held by the sternum: its bucket handle turns about the chord. A false or
        // floating rib's end is free, and its plane tilts about the antero-posterior axis, as Wilson et al. measured.
        Vec3 bucket = raising(rib.index() <= TRUE_RIBS ? chord.normalized() : new Vec3(0, 1, 0),
                vertex(m, lateral).minus(h));
        double[] deg = RibCage.wilsonDegrees(rib.index());
        double ap = Math.toRadians(deg[0]) * TIDAL_FRACTION;
        double ab = Math.toRadians(deg[1]) * TIDAL_FRACTION;
        Vec3 axis = pump.times(ap).plus(bucket.times(ab));
        return new HelicalAxisMotion(axis, h, axis.norm(), p.ribTranslationM(), cycle, controls);
    }

    /** The axis, or its opposite, about which a small positive rotation raises the point at r (from the axis). */
    static Vec3 raising(Vec3 axis, Vec3 r) {
        return axis.x() * r.y() - axis.y() * r.x() < 0 ? axis.times(-1) : axis;
    }

    /**
     * The rib's anterior end: the centroid of its vertices farther than 0.9 times the farthest one's distance from
     * the head along the horizontal direction of the farthest vertex (its tip, where the cartilage begins).
     */
    static Vec3 anteriorEnd(TriangleMesh m, Vec3 head) {
        double far = 0;
        int tip = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            double d = vertex(m, v).distance(head);
            if (d > far) {
                far = d;
                tip = v;
            }
        }
        Vec3 sum = Vec3.ZERO;
        int n = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            if (vertex(m, v).distance(head) >= 0.9 * far && vertex(m, v).distance(vertex(m, tip)) < 0.5 * far) {
                sum = sum.plus(vertex(m, v));
                n++;
            }
        }
        return sum.times(1.0 / n);
    }

    private static Vec3 vertex(TriangleMesh m, int v) {
        return new Vec3(m.coord(v, 0), m.coord(v, 1), m.coord(v, 2));
    }

    /** The centre of the ribs' vertices in the horizontal plane: the origin of the slices' angle. */
    private static double[] ribCentre(Bones bones) {
        double x = 0;
        double y = 0;
        int n = 0;
        for (Bones.Bone b : bones.of(Bones.Kind.RIB)) {
            TriangleMesh m = b.mesh();
            for (int v = 0; v < m.vertexCount(); v++) {
                x += m.coord(v, 0);
                y += m.coord(v, 1);
                n++;
            }
        }
        return n == 0 ? new double[] {0, 0} : new double[] {x / n, y / n};
    }

    /**
     * Nodes at the centroids of equal slices of a bone along its sweep about the thorax's vertical axis
     * (angle from the posterior midline), ordered from posterior (the head) to anterior.
     */
    private static int[] polyline(Topology t, TriangleMesh m, double[] centre, int count, double mass) {
        int nv = m.vertexCount();
        double[] angle = new double[nv];
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < nv; v++) {
            // 0 at the back (+Y), pi at the front, the same on both sides.
            angle[v] = Math.atan2(Math.abs(m.coord(v, 0) - centre[0]), m.coord(v, 1) - centre[1]);
            lo = Math.min(lo, angle[v]);
            hi = Math.max(hi, angle[v]);
        }
        double[][] sum = new double[count][4];
        for (int v = 0; v < nv; v++) {
            int k = hi > lo ? (int) Math.min(count - 1, Math.floor(count * (angle[v] - lo) / (hi - lo))) : 0;
            for (int a = 0; a < 3; a++) {
                sum[k][a] += m.coord(v, a);
            }
            sum[k][3]++;
        }
        List<Integer> ids = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            if (sum[k][3] > 0) {
                ids.add(t.addNode(sum[k][0] / sum[k][3], sum[k][1] / sum[k][3], sum[k][2] / sum[k][3], mass).id());
            }
        }
        return ids.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The sternum's polyline, top to bottom: slice centroids of its parts' vertices by height. */
    private static int[] sternumLine(Topology t, List<Bones.Bone> parts, double mass) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Bones.Bone b : parts) {
            lo = Math.min(lo, b.mesh().bounds()[2]);
            hi = Math.max(hi, b.mesh().bounds()[5]);
        }
        double[][] sum = new double[STERNUM_NODES][4];
        for (Bones.Bone b : parts) {
            TriangleMesh m = b.mesh();
            for (int v = 0; v < m.vertexCount(); v++) {
                int k = (int) Math.min(STERNUM_NODES - 1, Math.floor(STERNUM_NODES * (hi - m.coord(v, 2)) / (hi - lo)));
                for (int a = 0; a < 3; a++) {
                    sum[k][a] += m.coord(v, a);
                }
                sum[k][3]++;
            }
        }
        List<Integer> ids = new ArrayList<>();
        for (double[] s : sum) {
            if (s[3] > 0) {
                ids.add(t.addNode(s[0] / s[3], s[1] / s[3], s[2] / s[3], mass).id());
            }
        }
        return ids.stream().mapToInt(Integer::intValue).toArray();
    }

    /** A fixed segment through the vertebral bodies' centres, top to bottom; two fixed nodes. */
    private static int[] spine(Topology t, Bones bones, double mass, List<RibCage.Segment> segs) {
        List<Bones.Bone> v = new ArrayList<>(bones.of(Bones.Kind.VERTEBRA));
        if (v.isEmpty()) {
            return new int[0];
        }
        v.sort((a, b) -> Integer.compare(a.index(), b.index()));
        double[] top = v.get(0).mesh().bounds();
        double[] bottom = v.get(v.size() - 1).mesh().bounds();
        int a = t.addNode(0.5 * (top[0] + top[3]), 0.5 * (top[1] + top[4]), top[5], mass).fix().id();
        int b = t.addNode(0.5 * (bottom[0] + bottom[3]), 0.5 * (bottom[1] + bottom[4]), bottom[2], mass).fix().id();
        segs.add(new RibCage.Segment(a, b, RibCage.Kind.SPINE, null, "spine"));
        return new int[] {a, b};
    }

    private static String key(Bones.Side side, int index) {
        return side + "-" + index;
    }

    private static String ribName(Bones.Bone cartilage) {
        return "rib-" + (cartilage.side() == Bones.Side.LEFT ? "l" : "r") + cartilage.index();
    }

    private static void reverse(int[] a) {
        for (int i = 0, j = a.length - 1; i < j; i++, j--) {
            int x = a[i];
            a[i] = a[j];
            a[j] = x;
        }
    }
}
