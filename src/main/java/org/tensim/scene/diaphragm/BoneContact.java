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
 * with its rib.
 */
final class BoneContact {
    /** Nodes within this distance of a bone at rest may touch it, m (the breath moves the wall some 5-10 mm). */
    static final double RANGE_M = 0.015;

    private BoneContact() {
    }

    /** Adds the contact bodies and pairs to the builder's topology; returns the pair count per bone. */
    static Map<String, Integer> add(DiaphragmSceneBuilder b, Bones bones, RigidMotion[] motions,
            double stiffnessPaPerM) {
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
                if (bone.kind() == Bones.Kind.LIVER || !OriginAttachment.near(bone.mesh().bounds(), x, y, z, RANGE_M)) {
                    continue;
                }
                double d = bones.field(i).distance(x, y, z, g, 0);
                if (d >= RANGE_M) {
                    continue;
                }
                if (bodyOf[i] < 0) {
                    bodyOf[i] = b.t.addContactBody(new ContactBody(bone.name(), bones.field(i), motions[i],
                            bone.mesh().bounds()));
                }
                b.t.addContact(v, bodyOf[i], stiffnessPaPerM * b.area[v] / 2, Math.min(0, d));
                pairs.merge(bone.name(), 1, Integer::sum);
            }
        }
        return pairs;
    }
}
