package org.tensim.scene.diaphragm;

import java.util.Map;
import java.util.TreeMap;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.ContactBody;
import org.tensim.model.RigidMotion;

/**
 * Sliding contact of the diaphragm on the bones (package-private, called by the scene builder after
 * the attachment): above its origins the muscle lies against the inner chest wall (the zone of
 * apposition), where it slides, frictionless and one-sided. Every diaphragm node that is not attached
 * and lies within {@link #RANGE_M} of a bone at rest may touch it: a penalty
 * {@code k_c (A_i / 2) (g - d)} along the bone's normal when its signed distance d falls below g
 * ({@link org.tensim.model.ContactPair}), with {@code k_c} the contact stiffness per unit area (Pa/m).
 *
 * <p>g is 0, or the node's rest distance where a registered mesh starts inside a bone (the shared
 * thorax was registered to the diaphragm within a few millimetres, and some of the diaphragm's
 * vertices start up to 4 mm inside a rib or cartilage): such a node is kept from going deeper, not
 * thrown out at the first step. The bones move by their own rigid motions; a cartilage's surface moves
 * with its rib. The bones are hard ({@link ContactBody#hard()}): after every step a node that went deeper than
 * its gap is put back on it (the solver's contact projection, with the rigid links).
 *
 * <p><b>The liver</b> (a thorax with a liver part, {@code liverSupportPaPerM > 0}) is no bone: it is the compliant
 * support under the right hemidiaphragm, a one-sided elastic foundation on the same machinery. Every free
 * lower-surface node within {@link #LIVER_RANGE_M} of the liver at rest rests on it at end-expiration (g is its rest
 * distance, the registration's gap or overlap) and is pushed back by {@code K_l (A_i / 2) (g - d)} along the liver's
 * normal as it descends into it, {@code K_l} the liver's stiffness per unit area: a penetration of the pressure over
 * {@code K_l}, which is the liver's deflection, not an error, and is not projected away. The liver is fixed.
 */
final class BoneContact {
    /** Nodes within this distance of a bone at rest may touch it, m (the breath moves the wall some 5-10 mm). */
    static final double RANGE_M = 0.015;
    /** Lower-surface nodes within this distance of the liver at rest rest on it, m. */
    static final double LIVER_RANGE_M = 0.010;

    private BoneContact() {
    }

    /** Adds the contact bodies and pairs to the builder's topology; returns the pair count per bone. */
    static Map<String, Integer> add(DiaphragmSceneBuilder b, Bones bones, RigidMotion[] motions,
            double stiffnessPaPerM, double liverPaPerM) {
        TriangleMesh m = b.mesh;
        int[] bodyOf = new int[bones.all().size()];
        java.util.Arrays.fill(bodyOf, -1);
        Map<String, Integer> pairs = new TreeMap<>();
        double[] g = new double[3];
        for (int v = 0; v < b.nv; v++) {
            if (b.attached[v] || b.t.node(v).isFixed() || b.t.node(v).isDriven()) {
                continue;
            }
            double x = m.coord(v, 0);
            double y = m.coord(v, 1);
            double z = m.coord(v, 2);
            for (int i = 0; i < bones.all().size(); i++) {
                Bones.Bone bone = bones.all().get(i);
                boolean liver = bone.kind() == Bones.Kind.LIVER;
                double range = liver ? LIVER_RANGE_M : RANGE_M;
                if (liver && (liverPaPerM == 0 || b.surfaces.isUpper(v))
                        || !OriginAttachment.near(bone.mesh().bounds(), x, y, z, range)) {
                    continue;
                }
                double d = bones.field(i).distance(x, y, z, g, 0);
                if (d >= range) {
                    continue;
                }
                if (bodyOf[i] < 0) {
                    bodyOf[i] = b.t.addContactBody(new ContactBody(bone.name(), bones.field(i), motions[i],
                            bone.mesh().bounds(), !liver));
                }
                b.t.addContact(v, bodyOf[i], (liver ? liverPaPerM : stiffnessPaPerM) * b.area[v] / 2,
                        liver ? d : Math.min(0, d));
                pairs.merge(bone.name(), 1, Integer::sum);
            }
        }
        return pairs;
    }
}
