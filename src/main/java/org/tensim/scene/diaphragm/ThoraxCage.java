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
 * <p><b>Each rib's axis from its own geometry.</b> A rib turns about the axis of its neck, through
 * the costovertebral joint (its head, on the vertebral bodies) and the costotransverse joint (its
 * tubercle, on the transverse process) (De Troyer, Kirkwood and Wilson, Physiol Rev 85:717-756, 2005).
 * On the surface: the head is the rib's most medial vertex, the tubercle its most posterior vertex;
 * the axis runs from the head to the tubercle. The upper ribs' necks point mostly laterally (a pump
 * handle: the anterior end rises and moves forwards), the lower ribs' backwards and laterally (a
 * bucket handle: the lateral part rises and moves outwards). The rotation per quiet breath is that of
 * the parametric cage: Wilson et al. (J Appl Physiol 1987) measured from relaxed expiration to full
 * inspiration a pump-handle rotation of 11 degrees at rib 3 falling to 7 at rib 7 and a bucket-handle
 * rotation of 13 falling to 10; the rib turns by their quadratic sum ({@link RibCage#wilsonDegrees})
 * times the quiet-breathing fraction, in the sense that raises its far end.
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
            HelicalAxisMotion m = neckAxisMotion(b, centre[0], p, cycle, controls);
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
            if (b.index() <= 7) {
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
            if (b.index() <= 7 && sternum.length > 0) {
                t.node(medial).drive(sternumMotion);
            } else if (above != null) {
                int[] two = RibCage.nearestTwo(t, above, t.node(medial).position());
                for (int s : two) {
                    springs.add(medial, s, p.structureStiffness());
                }
            }
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
     * A rib's rotation about its neck (head to tubercle; class comment), signed to raise its far end,
     * through its head, plus the small translation along the axis of the parametric cage.
     */
    static HelicalAxisMotion neckAxisMotion(Bones.Bone rib, double midX, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls) {
        TriangleMesh m = rib.mesh();
        // midX: the body's midline (x, m); the rib's head is the vertex nearest it.
        int head = -1;
        int tubercle = -1;
        double bestMedial = Double.POSITIVE_INFINITY;
        for (int v = 0; v < m.vertexCount(); v++) {
            double medial = Math.abs(m.coord(v, 0) - midX);
            if (medial < bestMedial) {
                bestMedial = medial;
                head = v;
            }
        }
        Vec3 h = vertex(m, head);
        // Tubercle: the most posterior vertex (+Y posterior) within the rib's posterior fifth along x from the head.
        double width = m.bounds()[3] - m.bounds()[0];
        double bestY = Double.NEGATIVE_INFINITY;
        int far = head;
        double farD = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            double lateral = Math.abs(m.coord(v, 0) - h.x());
            if (lateral < 0.4 * width && m.coord(v, 1) > bestY) {
                bestY = m.coord(v, 1);
                tubercle = v;
            }
            double d = vertex(m, v).distance(h);
            if (d > farD) {
                farD = d;
                far = v;
            }
        }
        Vec3 axis = vertex(m, tubercle).minus(h);
        if (!(axis.norm() > 1e-3)) {
            throw new IllegalArgumentException("rib " + rib.name() + ": its head and tubercle coincide ("
                    + h + "); cannot place its neck axis");
        }
        Vec3 r = vertex(m, far).minus(h);
        Vec3 n = axis.normalized();
        // d(far)/d(theta) = n x r must rise.
        if (n.x() * r.y() - n.y() * r.x() < 0) {
            n = n.times(-1);
        }
        double[] deg = RibCage.wilsonDegrees(rib.index());
        double angle = Math.toRadians(Math.hypot(deg[0], deg[1])) * p.ribQuietFraction();
        return new HelicalAxisMotion(n, h, angle, p.ribTranslationM(), cycle, controls);
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
