package org.tensim.scene.diaphragm;

import java.util.BitSet;
import java.util.List;
import org.tensim.model.Node;
import org.tensim.model.Vec3;
import org.tensim.scene.conditions.BandAttachment;

/**
 * The diaphragm's origins as a band with a stiffness per unit area
 * ({@link BoundaryConditions.Attachment#BAND}; package-private, called by the scene builder): the generic
 * {@link BandAttachment} with the cage's segments as its targets, and the diaphragm's own two rules, the origins
 * among the segments ({@link #origins}) and the crura where no node lies near the spine segment.
 *
 * <p>Each diaphragm node i within the attachment threshold W of the cage (distance d_i to its
 * nearest segment) is tied with
 * <pre>
 *   k_i = k_b (A_i / 2) taper(d_i),   taper = 1 for d &lt;= W - T,  cos^2(pi (d - W + T) / (2 T)) up to W
 * </pre>
 * (A_i its share of its face's area, half per face as the node masses; k_b in Pa/m), shared among the
 * segments within W in proportion to their own tapers, {@code taper(d_is) / sum_s taper(d_is)}: a node
 * between two ribs follows both, so that the displacement the band imposes varies continuously along
 * the rim (tied to its nearest segment alone, a node jumped from one rib's motion to the next rib's
 * where the nearest segment changed, and each mesh sampled that jump differently). Measured with the
 * muscle off (ribs only, one inspiration, 2026-11-23): 88 % of the squared difference between the 20-
 * and 28-ring fields lies within 0.2 of the rim; sharing the ties lowered the 14- and 20-ring
 * differences from 28 rings' from 0.126 and 0.066 to 0.119 and 0.061, a small part of it. A tie to a rib is a
 * zero-length spring to an anchor at the node's rest point driven by that rib's helical-axis motion;
 * to the spine, to a fixed anchor; to a cartilage or sternum segment, two springs to the segment's
 * ends, split by the node's projection on the segment ({@code (1 - s) k} and {@code s k}). The
 * attachment counts go by the nearest segment. The band's
 * total stiffness, {@code k_b} times its area, and the stiffness per unit area at any point converge
 * as the mesh is refined; the smooth taper keeps nodes entering the band from adding stiffness in
 * steps. A node's tie frequency {@code sqrt(2 k_b / (rho t))} does not depend on the element size.
 */
final class AttachmentBand {
    private AttachmentBand() {
    }

    static void attach(DiaphragmSceneBuilder b, BoundaryConditions bc) {
        double w = b.p.attachThresholdM();
        double taper = bc.bandTaperM();
        if (taper > w) {
            throw new IllegalArgumentException("attachment band taper (" + taper * 1e3 + " mm) must not exceed the"
                    + " attachment threshold (" + w * 1e3 + " mm)");
        }
        List<RibCage.Segment> segs = bc.costalOriginsOnly() ? origins(b.cage.segments()) : b.cage.segments();
        List<BandAttachment.Target> targets = new java.util.ArrayList<>();
        for (RibCage.Segment s : segs) {
            targets.add(new BandAttachment.Target(s.name(), q -> RibCage.distance(b.t, s, q),
                    (t, v, k) -> tie(b, v, s, k)));
        }
        BitSet diaphragm = new BitSet();
        diaphragm.set(0, b.nv);
        BandAttachment.Weights wts = BandAttachment.weigh(b.t, diaphragm, targets, w, taper);
        double[] weight = wts.weight();
        int[] nearest = wts.nearest();
        b.originDistance = java.util.Arrays.copyOf(wts.distance(), b.nv);
        boolean spineFound = false;
        for (int v = 0; v < b.nv; v++) {
            spineFound |= weight[v] > 0 && segs.get(nearest[v]).kind() == RibCage.Kind.SPINE;
        }
        if (!spineFound) {
            crura(b, weight, nearest, w, taper);
        }
        b.markFirstAnchor();
        for (int v = 0; v < b.nv; v++) {
            if (weight[v] == 0) {
                continue;
            }
            b.attached[v] = true;
            double k = bc.bandStiffnessPaPerM() * b.area[v] / 2 * weight[v];
            RibCage.Segment s = nearest[v] < 0 ? null : segs.get(nearest[v]);
            if (s == null || s.kind() == RibCage.Kind.SPINE) {
                b.attachedSpine++;
            } else if (s.kind() == RibCage.Kind.RIB) {
                b.attachedRibs++;
            } else {
                b.attachedCartilage++;
            }
            if (s == null) { // the crura's rule: a fixed anchor
                b.tie(v, b.t.addNode(b.t.node(v).position(), b.t.node(v).mass()).fix().id(), k);
                continue;
            }
            BandAttachment.tie(b.t, wts, v, k, targets);
        }
    }

    /** Node v's tie of stiffness k (N/m) to segment s, as the class comment says for the segment's kind. */
    private static void tie(DiaphragmSceneBuilder b, int v, RibCage.Segment s, double k) {
        Node n = b.t.node(v);
        switch (s.kind()) {
            case SPINE -> b.tie(v, b.t.addNode(n.position(), n.mass()).fix().id(), k);
            case RIB -> b.tie(v, b.t.addNode(n.position(), n.mass()).drive(s.motion()).id(), k);
            default -> {
                double f = projection(b, s, n.position());
                if (f < 1) {
                    b.springs.add(v, s.a(), k * (1 - f));
                }
                if (f > 0) {
                    b.springs.add(v, s.b(), k * f);
                }
            }
        }
    }

    /**
     * When no node is near the spine segment (a real mesh whose crura reach lower and further
     * forward than the segment placed from the rib boxes), the crura are the diaphragm's lowest
     * insertion: the nodes within the threshold above the mesh's lowest point, tapered the same way.
     */
    private static void crura(DiaphragmSceneBuilder b, double[] weight, int[] nearest, double w, double taper) {
        double low = Double.POSITIVE_INFINITY;
        for (int v = 0; v < b.nv; v++) {
            low = Math.min(low, b.mesh.coord(v, 2));
        }
        for (int v = 0; v < b.nv; v++) {
            double c = BandAttachment.taper(b.mesh.coord(v, 2) - low, w, taper);
            if (c > weight[v]) {
                weight[v] = c;
                nearest[v] = -1;
            }
        }
    }

    /**
     * The diaphragm's origins among the cage's segments (Gray's Anatomy): the costal part arises from
     * the inner surfaces of the lower six ribs and their cartilages (ribs 7-12), the sternal part from
     * the back of the xiphoid process (the sternum's lowest segment), the lumbar part (crura) from the
     * spine. Ribs 1-6 and their cartilages lie against the dome (the zone of apposition is apposed, not
     * attached) and are left out.
     */
    static List<RibCage.Segment> origins(List<RibCage.Segment> all) {
        List<RibCage.Segment> out = new java.util.ArrayList<>();
        RibCage.Segment xiphoid = null;
        for (RibCage.Segment s : all) {
            switch (s.kind()) {
                case RIB, CARTILAGE -> {
                    if (ribNumber(s.name()) >= 7) {
                        out.add(s);
                    }
                }
                case STERNUM -> xiphoid = s; // segments run from the manubrium down: the last is the lowest
                case SPINE -> out.add(s);
                default -> throw new IllegalStateException("unknown cage segment kind " + s.kind());
            }
        }
        if (xiphoid != null) {
            out.add(xiphoid);
        }
        return out;
    }

    /** The rib number at the end of a segment name such as {@code rib-r7} or {@code cartilage-l10}. */
    private static int ribNumber(String name) {
        int i = name.length();
        while (i > 0 && Character.isDigit(name.charAt(i - 1))) {
            i--;
        }
        if (i == name.length()) {
            throw new IllegalStateException("cage segment '" + name + "' has no rib number");
        }
        return Integer.parseInt(name.substring(i));
    }

    /** Parameter in [0, 1] of the point of segment s nearest to q. */
    private static double projection(DiaphragmSceneBuilder b, RibCage.Segment s, Vec3 q) {
        Vec3 a = b.t.node(s.a()).position();
        Vec3 e = b.t.node(s.b()).position().minus(a);
        double l2 = e.dot(e);
        return l2 == 0 ? 0.5 : Math.max(0, Math.min(1, q.minus(a).dot(e) / l2));
    }
}
