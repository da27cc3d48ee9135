package org.tensim.scene.diaphragm;

import java.util.List;
import org.tensim.model.Vec3;

/**
 * The paper's attachment ({@link BoundaryConditions.Attachment#PAPER_THRESHOLD}; package-private):
 * "attachment points ... such that the distance to the group ribs, sternum, cartilage is under a
 * given threshold". Each such node is driven rigidly with its rib, fixed to the spine, or tied by
 * two springs of the attachment stiffness (N/m) to the ends of the cartilage or sternum segment.
 */
final class ThresholdAttachment {
    private ThresholdAttachment() {
    }

    /** The paper's attachment: every node within the threshold of a cage segment (see Attachment). */
    static void attach(DiaphragmSceneBuilder b) {
        List<RibCage.Segment> segs = b.cage.segments();
        for (int v = 0; v < b.nv; v++) {
            Vec3 q = b.t.node(v).position();
            RibCage.Segment best = null;
            double bestD = Double.POSITIVE_INFINITY;
            for (RibCage.Segment s : segs) {
                double d = RibCage.distance(b.t, s, q);
                if (d < bestD) {
                    bestD = d;
                    best = s;
                }
            }
            if (best == null || bestD > b.p.attachThresholdM()) {
                continue;
            }
            b.attached[v] = true;
            if (best.kind() == RibCage.Kind.RIB) {
                b.t.node(v).drive(best.motion());
                b.attachedRibs++;
            } else if (best.kind() == RibCage.Kind.SPINE) {
                b.t.node(v).fix();
                b.attachedSpine++;
            } else {
                b.springs.add(v, best.a(), b.p.attachStiffness());
                b.springs.add(v, best.b(), b.p.attachStiffness());
                b.attachedCartilage++;
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
