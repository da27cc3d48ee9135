package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.thorax.DistanceGrid;
import org.tensim.scene.thorax.TubeSweep;

/**
 * The parametric cage's bones as closed surfaces ({@code --cage surfaces}; package-private): each rib, costal
 * cartilage, the sternum, the xiphoid and the lumbar vertebrae L1-L3 a tube swept along the cage's own lines
 * ({@link TubeSweep}), in the cage's frame (BodyParts3D's: +x left, +y posterior, +z superior) and units (metres),
 * so that the diaphragm is attached at its origins and slides on the cage by the same code as in a thorax of bone
 * surfaces ({@link OriginAttachment}, {@link BoneContact}). The lines are those {@link RibCage#build} makes from the
 * boxes (the parametric cage's or a boxes file's), so the surfaces and the cage's segments are one geometry.
 *
 * <p><b>Cross-sections</b> (semi-axes are half these):
 * <ul>
 * <li>ribs: an ellipse {@link #RIB_HEIGHT_MM} high (its first axis, the vertical made perpendicular to the rib) and
 *     {@link #RIB_THICKNESS_MM} thick (across the chest wall). Gray (<i>Anatomy</i>, 1918, II.4b) describes the
 *     shaft as thin and flat, with external and internal surfaces and superior and inferior borders; an adult rib's
 *     shaft is about 1-1.5 cm high and 0.5-0.8 cm thick (total cross-sectional areas of adult ribs 2-11 by CT:
 *     Holcombe and Huang, Front Bioeng Biotechnol 11:1158242, 2023); 12 x 6 mm is an area of 57 mm^2;</li>
 * <li>costal cartilages, which prolong the ribs forwards (Gray): a round section of the rib's area, radius
 *     {@code sqrt(RIB_HEIGHT * RIB_THICKNESS) / 2} = 4.2 mm, along the cage's cartilage segment (from the rib's end to
 *     the nearest sternum node for 1-7, to the end of the rib above for 8-10);</li>
 * <li>sternum (manubrium and body, the cage's sternum line but its last segment): the cage's sternum width (54 mm)
 *     by {@link #STERNUM_THICKNESS_MM}; the xiphoid (the line's last segment, 24 mm): {@link #XIPHOID_WIDTH_MM} by
 *     {@link #XIPHOID_THICKNESS_MM} (Gray: the smallest piece of the sternum, thin and elongated);</li>
 * <li>lumbar vertebral bodies L1-L3: elliptic cylinders {@link #VERTEBRA_WIDTH_MM} wide and
 *     {@link #VERTEBRA_DEPTH_MM} deep (upper lumbar endplates about 40-48 mm wide and 33-36 mm deep: Panjabi et al.,
 *     Spine 17:299, 1992) centred on the cage's spine segment, each one level high, {@link #LUMBAR_LEVEL_MM} (a body
 *     of about 26 mm and a disc of about 10 mm), stacked without gaps (the crura arise from the bodies and the discs
 *     between them), T12's level centred on rib 12's head.</li>
 * </ul>
 *
 * <p><b>Motion</b> ({@link #motions}): a rib's surface moves with its rib's helical axis (the same law as its driven
 * line); a cartilage's surface with its rib (as in a thorax); the sternum and the xiphoid by the mean displacement of
 * the true ribs' anterior ends ({@link FollowingMotion}; the cage's own sternum is a free stiff chain that follows
 * them nearly so); the vertebrae are fixed, as the spine segment is.
 */
final class ParametricBones {
    /** A rib's section height, mm. */
    static final double RIB_HEIGHT_MM = 12;
    /** A rib's section thickness, mm. */
    static final double RIB_THICKNESS_MM = 6;
    /** The sternum's thickness, mm (its width is the cage's). */
    static final double STERNUM_THICKNESS_MM = 10;
    /** The xiphoid's width, mm. */
    static final double XIPHOID_WIDTH_MM = 20;
    /** The xiphoid's thickness, mm. */
    static final double XIPHOID_THICKNESS_MM = 6;
    /** A lumbar vertebral body's width, mm. */
    static final double VERTEBRA_WIDTH_MM = 44;
    /** A lumbar vertebral body's depth, mm. */
    static final double VERTEBRA_DEPTH_MM = 34;
    /** Height of one lumbar level (body and disc), mm. */
    static final double LUMBAR_LEVEL_MM = 36;
    /** Vertices around a section. */
    static final int AROUND = 16;
    /** Ribs 1-7 reach the sternum. */
    private static final int TRUE_RIBS = 7;
    private static final Vec3 UP = new Vec3(0, 0, 1);
    private static final Vec3 LEFT = new Vec3(1, 0, 0);
    private static final double MM = 1e-3;

    private ParametricBones() {
    }

    /** The bones of the cage {@link RibCage#build} makes from these boxes (m, by name), as swept surfaces. */
    static Bones forBoxes(Map<String, double[]> boxes) {
        Topology t = new Topology();
        RibCage cage = RibCage.build(t, new SpringList(), boxes, DiaphragmParameters.defaults(),
                BreathingCycle.quiet(), new DiaphragmControls(1, 0));
        double[] sb = null;
        for (Map.Entry<String, double[]> e : boxes.entrySet()) {
            if (e.getKey().startsWith("sternum")) {
                sb = e.getValue();
            }
        }
        return of(cage, t, sb[3] - sb[0], AROUND, DistanceGrid::build);
    }

    /**
     * The bones of a built cage at rest, swept with {@code around} vertices a section.
     *
     * @param sternumWidthM the sternum's width, m
     * @param fields        makes a bone's signed distance from its surface (a {@link DistanceGrid} at its default
     *                      cells in a scene)
     */
    static Bones of(RibCage cage, Topology t, double sternumWidthM, int around,
            Function<TriangleMesh, SignedDistance> fields) {
        List<Bones.Bone> out = new ArrayList<>();
        double r = RIB_HEIGHT_MM * MM / 2;
        double s = RIB_THICKNESS_MM * MM / 2;
        double round = Math.sqrt(r * s);
        // The sternum, xiphoid and vertebrae first: a node inside two bones is credited to the first.
        Vec3[] sternum = points(t, cage.sternumNodes());
        int n = sternum.length;
        out.add(new Bones.Bone("sternum", Bones.Kind.STERNUM, Bones.Side.NONE, 0, TubeSweep.sweep(
                java.util.Arrays.copyOf(sternum, n - 1), LEFT, sternumWidthM / 2, STERNUM_THICKNESS_MM * MM / 2,
                around)));
        out.add(new Bones.Bone("xiphoid", Bones.Kind.XIPHOID, Bones.Side.NONE, 0, TubeSweep.sweep(
                new Vec3[] {sternum[n - 2], sternum[n - 1]}, LEFT, XIPHOID_WIDTH_MM * MM / 2,
                XIPHOID_THICKNESS_MM * MM / 2, around)));
        int[] spine = cage.spineNodes();
        Vec3 top = t.node(spine[0]).position(); // at rib 12's head: T12's level
        for (int level = 1; level <= 3; level++) {
            double zTop = top.z() - (level - 0.5) * LUMBAR_LEVEL_MM * MM;
            Vec3[] axis = {new Vec3(top.x(), top.y(), zTop), new Vec3(top.x(), top.y(), zTop - LUMBAR_LEVEL_MM * MM)};
            out.add(new Bones.Bone("vertebra-L" + level, Bones.Kind.VERTEBRA, Bones.Side.NONE, 12 + level,
                    TubeSweep.sweep(axis, LEFT, VERTEBRA_WIDTH_MM * MM / 2, VERTEBRA_DEPTH_MM * MM / 2, around)));
        }
        for (String side : new String[] {"r", "l"}) {
            Bones.Side sd = side.equals("r") ? Bones.Side.RIGHT : Bones.Side.LEFT;
            for (int i = 1; i <= ParametricRibCage.RIB_PAIRS; i++) {
                Vec3[] rib = points(t, line(cage, RibCage.Kind.RIB, "rib-" + side + i));
                out.add(new Bones.Bone("rib-" + side + i, Bones.Kind.RIB, sd, i,
                        TubeSweep.sweep(rib, UP, r, s, around)));
                int[] c = line(cage, RibCage.Kind.CARTILAGE, "cartilage-" + side + i);
                if (c.length > 0) {
                    Vec3[] p = points(t, new int[] {c[0], c[1]});
                    out.add(new Bones.Bone("cartilage-" + side + i, Bones.Kind.CARTILAGE, sd, i,
                            TubeSweep.sweep(p, across(p), round, round, around)));
                }
            }
        }
        return new Bones(out, "parametric rib cage as bone surfaces", fields);
    }

    /**
     * Each bone's rigid motion (by index in {@code bones}) in a built cage (class comment): a rib's helical axis, a
     * cartilage's rib's, the sternum's and the xiphoid's the true ribs' anterior ends' mean displacement, a
     * vertebra fixed.
     */
    static RigidMotion[] motions(Bones bones, RibCage cage, Topology t) {
        List<HelicalAxisMotion> trueRibs = new ArrayList<>();
        List<Vec3> ends = new ArrayList<>();
        for (Map.Entry<String, HelicalAxisMotion> e : cage.motions().entrySet()) {
            int rib = Integer.parseInt(e.getKey().substring("rib-r".length()));
            if (rib <= TRUE_RIBS) {
                int[] line = line(cage, RibCage.Kind.RIB, e.getKey());
                trueRibs.add(e.getValue());
                ends.add(t.node(line[line.length - 1]).position());
            }
        }
        RigidMotion sternum = new FollowingMotion(trueRibs, ends);
        RigidMotion[] out = new RigidMotion[bones.all().size()];
        for (int i = 0; i < out.length; i++) {
            Bones.Bone b = bones.all().get(i);
            String rib = "rib-" + (b.side() == Bones.Side.LEFT ? "l" : "r") + b.index();
            out[i] = switch (b.kind()) {
                case RIB, CARTILAGE -> require(cage.motions().get(rib), rib);
                case STERNUM, XIPHOID -> sternum;
                default -> RigidMotion.FIXED;
            };
        }
        return out;
    }

    private static HelicalAxisMotion require(HelicalAxisMotion m, String rib) {
        if (m == null) {
            throw new IllegalArgumentException("the cage has no motion for " + rib + "; expected rib-r1..rib-r12 and"
                    + " rib-l1..rib-l12");
        }
        return m;
    }

    /**
     * The nodes of a cage line by name, in order: a rib's polyline from its head, or a cartilage's first segment
     * (its rib's end, then the nearest sternum node or the end of the rib above); empty when there is none.
     */
    static int[] line(RibCage cage, RibCage.Kind kind, String name) {
        List<Integer> ids = new ArrayList<>();
        for (RibCage.Segment g : cage.segments()) {
            if (g.kind() == kind && g.name().equals(name)) {
                if (ids.isEmpty()) {
                    ids.add(g.a());
                } else if (kind == RibCage.Kind.CARTILAGE) {
                    break;
                }
                ids.add(g.b());
            }
        }
        return ids.stream().mapToInt(Integer::intValue).toArray();
    }

    private static Vec3[] points(Topology t, int[] ids) {
        Vec3[] p = new Vec3[ids.length];
        for (int i = 0; i < ids.length; i++) {
            p[i] = t.node(ids[i]).position();
        }
        return p;
    }

    /** Of the vertical and the transverse axis, the one further from the line's direction. */
    private static Vec3 across(Vec3[] p) {
        Vec3 d = p[p.length - 1].minus(p[0]).normalized();
        return Math.abs(d.z()) < Math.abs(d.x()) ? UP : LEFT;
    }
}
