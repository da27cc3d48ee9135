package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import org.tensim.scene.conditions.DistanceAttachment;

/**
 * The paper's attachment ({@link BoundaryConditions.Attachment#PAPER_THRESHOLD}; package-private):
 * "attachment points ... such that the distance to the group ribs, sternum, cartilage is under a
 * given threshold". Each such node is driven rigidly with its rib, fixed to the spine, or tied by
 * two springs of the attachment stiffness (N/m) to the ends of the cartilage or sternum segment.
 */
final class ThresholdAttachment {
    private ThresholdAttachment() {
    }

    /**
     * The paper's attachment: every node within the threshold of a cage segment (see Attachment), by the generic
     * {@link DistanceAttachment}, each segment a target held as its kind says.
     */
    static void attach(DiaphragmSceneBuilder b) {
        List<RibCage.Segment> segs = b.cage.segments();
        List<DistanceAttachment.Target> targets = new ArrayList<>(segs.size());
        for (RibCage.Segment s : segs) {
            DistanceAttachment.Hold hold = switch (s.kind()) {
                case RIB -> DistanceAttachment.drive(s.motion());
                case SPINE -> DistanceAttachment.fix();
                default -> DistanceAttachment.tie(b.springs::add, b.p.attachStiffness(), s.a(), s.b());
            };
            targets.add(new DistanceAttachment.Target(s.name(), q -> RibCage.distance(b.t, s, q), hold));
        }
        BitSet diaphragm = new BitSet(b.nv);
        diaphragm.set(0, b.nv);
        int[] to = DistanceAttachment.attach(b.t, diaphragm, targets, b.p.attachThresholdM()).target();
        for (int v = 0; v < b.nv; v++) {
            if (to[v] < 0) {
                continue;
            }
            b.attached[v] = true;
            switch (segs.get(to[v]).kind()) {
                case RIB -> b.attachedRibs++;
                case SPINE -> b.attachedSpine++;
                default -> b.attachedCartilage++;
            }
        }
        if (b.attachedSpine == 0) {
            crura(b);
        }
    }

    /**
     * When no node is near the spine segment (a real mesh whose crura reach lower and further
     * forward than the segment placed from the rib boxes), the crura are taken from the mesh:
     * they are the diaphragm's lowest insertion (on the lumbar vertebrae L1-L3), so the free
     * nodes within the attachment threshold above the mesh's lowest point are fixed.
     */
    private static void crura(DiaphragmSceneBuilder b) {
        double low = Double.POSITIVE_INFINITY;
        for (int v = 0; v < b.nv; v++) {
            low = Math.min(low, b.mesh.coord(v, 2));
        }
        for (int v = 0; v < b.nv; v++) {
            if (!b.attached[v] && b.mesh.coord(v, 2) <= low + b.p.attachThresholdM()) {
                b.attached[v] = true;
                b.t.node(v).fix();
                b.attachedSpine++;
            }
        }
    }
}
