package org.tensim.scene.file;

import java.util.BitSet;
import java.util.List;
import java.util.Map;
import org.tensim.model.ContactBody;
import org.tensim.model.Motion;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.scene.conditions.DistanceAttachment;

/**
 * The conditions that tie a deformable body's region to a rigid body ({@link RigidBody}), named by {@code with:}:
 * <ul>
 * <li>{@code contact} ({@code stiffness} N/m per node, {@code gap} length 0, {@code hard} false): frictionless
 * one-sided contact, {@code f = k max(0, g - d) n} on each free node of the region ({@link
 * org.tensim.model.ContactPair}), d its signed distance to the rigid solid; a node that starts deeper than g keeps
 * its rest distance as its gap (it is held from going deeper, not thrown out), as the diaphragm's bones do. With
 * {@code hard: true} a node that went deeper is also put back on its gap after each step (the solver's contact
 * projection), so that penetration is a round-off, not the load over k.</li>
 * <li>{@code attachment} ({@code threshold} length, {@code mode} drive): the paper's attachment, every node of the
 * region within the threshold of the rigid surface at rest ({@code d <= threshold}, inside included) is attached
 * (the generic {@link DistanceAttachment}, as the diaphragm's paper-threshold attachment). {@code mode: drive}: it
 * moves with the body, {@code x(t) = a(t) = R(t) R(0)^T (x0 - c(0)) + c(t)}; {@code fix}: it is held at its rest
 * point x0 whatever the body does (the diaphragm's spine); {@code tie} ({@code stiffness} N/m, required,
 * {@code damping} N s/m, 0): a zero-length spring pulls it towards a(t), the point the body carries from its rest
 * point, through an anchor node driven along a(t) ({@link DistanceAttachment#anchored}; one anchor node a tied
 * node, added to the body's topology); {@code band} ({@code stiffness} Pa/m, required, {@code taper} length, 0):
 * the same springs, each of stiffness {@code k_b A_i taper(d_i)} by the node's share A_i of the body's surface area,
 * so that the total converges with the mesh ({@link AttachmentBands}, the diaphragm's default attachment).</li>
 * <li>{@code sliding} ({@code stiffness}, {@code hard}): the region kept on the rigid surface, frictionless, neither
 * penetrating nor separating: each free node keeps its rest distance d0 from both sides, by one contact pair on the
 * solid (gap d0) and one on its complement (gap -d0), a bilateral normal spring {@code k (d0 - d) n} that leaves the
 * tangential motion free (the pleura; docs/scenes.md says why bilateral).</li>
 * </ul>
 */
final class RigidConditions {
    /** The condition types of this class. */
    static final List<String> TYPES = List.of("contact", "attachment", "sliding");
    /** The attachment's modes: what attaching a node does. */
    static final List<String> MODES = List.of("drive", "fix", "tie", "band");
    /** The keys of each. */
    static final Map<String, List<String>> KEYS = Map.of(
            "contact", List.of("type", "region", "with", "stiffness", "gap", "hard"),
            "attachment", List.of("type", "region", "with", "threshold", "mode", "stiffness", "damping", "taper"),
            "sliding", List.of("type", "region", "with", "stiffness", "hard"));

    private RigidConditions() {
    }

    /** The rigid body named by {@code with:}; refused with what the scene has when it names none. */
    static RigidBody rigid(MapReader r, Map<String, SceneBody> bodies, Map<String, RigidBody> rigids) {
        SceneNode w = r.scalar("with");
        RigidBody b = rigids.get(w.text());
        if (b != null) {
            return b;
        }
        String list = rigids.isEmpty() ? " (it has none: add a body of type rigid)"
                : " (rigid bodies: " + String.join(", ", rigids.keySet()) + ")";
        if (bodies.containsKey(w.text())) {
            throw SceneException.at(w, "body '" + w.text() + "' is of type " + bodies.get(w.text()).type()
                    + ", not rigid: a " + r.string("type", "probe") + " is with a rigid body" + list);
        }
        throw SceneException.at(w, w.describe() + " is not a rigid body of this file"
                + DidYouMean.suggest(w.text(), rigids.keySet()) + list);
    }

    /** Applies a condition of {@link #TYPES} to the region's nodes of one body. */
    static void apply(String type, MapReader r, RigidBody rigid, SceneBody b, BitSet nodes, SceneUnits u) {
        Topology t = b.topology();
        if (type.equals("attachment")) {
            attach(r, rigid, b, nodes, u);
            return;
        }
        double k = r.positive("stiffness", QuantityKind.STIFFNESS, u, Double.NaN);
        boolean hard = r.bool("hard", false);
        double gap = type.equals("contact") ? r.quantity("gap", QuantityKind.LENGTH, u, 0) : 0;
        int solid = bodyIndex(t, rigid, hard, false);
        int other = type.equals("sliding") ? bodyIndex(t, rigid, hard, true) : -1;
        int pairs = 0;
        for (int i = nodes.nextSetBit(0); i >= 0; i = nodes.nextSetBit(i + 1)) {
            Node n = t.node(i);
            if (n.isFixed() || n.isDriven()) {
                continue;
            }
            double d0 = rigid.restDistance(n.position().x(), n.position().y(), n.position().z());
            if (other < 0) {
                t.addContact(i, solid, k, Math.min(gap, d0));
            } else {
                t.addContact(i, solid, k, d0);
                t.addContact(i, other, k, -d0);
            }
            pairs++;
        }
        if (pairs == 0) {
            throw SceneException.at(r.node(), "no free node of the region on body '" + b.name() + "' (its "
                    + nodes.cardinality() + " nodes are fixed or driven)");
        }
    }

    /** The index of the rigid body's contact body (its complement's) in t, added the first time. */
    private static int bodyIndex(Topology t, RigidBody rigid, boolean hard, boolean complement) {
        String name = complement ? rigid.name() + "~" : rigid.name();
        List<ContactBody> all = t.contactBodies();
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).name().equals(name) && all.get(i).hard() == hard) {
                return i;
            }
        }
        return t.addContactBody(complement ? rigid.complementBody(hard) : rigid.contactBody(hard));
    }

    /** What the attachment's {@code mode} does to a node, {@code follow} the body's motion of its rest point. */
    private static DistanceAttachment.Hold hold(MapReader r, Motion follow, SceneUnits u) {
        String mode = r.choice("mode", MODES, "drive");
        if (!mode.equals("tie")) {
            for (String key : List.of("stiffness", "damping")) {
                if (r.has(key) && !(mode.equals("band") && key.equals("stiffness"))) {
                    throw SceneException.at(r.node().get(key), key + " goes with mode: tie (a spring to the rigid"
                            + " body); mode " + mode + " has none");
                }
            }
        }
        if (r.has("taper")) {
            throw SceneException.at(r.node().get("taper"), "taper goes with mode: band (ties fading to 0 at the"
                    + " threshold); mode " + mode + " has none");
        }
        return switch (mode) {
            case "fix" -> DistanceAttachment.fix();
            case "tie" -> DistanceAttachment.anchored(follow, r.positive("stiffness", QuantityKind.STIFFNESS, u,
                    Double.NaN), r.nonNegative("damping", QuantityKind.DAMPING, u, 0));
            default -> DistanceAttachment.drive(follow);
        };
    }

    private static void attach(MapReader r, RigidBody rigid, SceneBody b, BitSet nodes, SceneUnits u) {
        double threshold = r.positive("threshold", QuantityKind.LENGTH, u, Double.NaN);
        Motion follow = follow(rigid);
        if (r.choice("mode", MODES, "drive").equals("band")) {
            AttachmentBands.attach(r, rigid, b, nodes, u, follow, threshold);
            return;
        }
        DistanceAttachment.Result done = DistanceAttachment.attach(b.topology(), nodes, List.of(
                new DistanceAttachment.Target(rigid.name(), q -> rigid.restDistance(q.x(), q.y(), q.z()),
                        hold(r, follow, u))), threshold);
        int attached = done.attached();
        double nearest = done.nearest();
        if (attached == 0) {
            throw SceneException.at(r.node().get("threshold"), String.format(java.util.Locale.ROOT, "no node of the"
                    + " region on body '%s' lies within %.6g m of rigid body '%s' (the nearest is %.6g m from it):"
                    + " widen the threshold or the region", b.name(), threshold, rigid.name(), nearest));
        }
    }

    /**
     * The rigid body's motion of a point by its rest position: {@code a(t) = R(t) R(0)^T (x0 - c(0)) + c(t)}, the
     * point of the body that lies at x0 at rest.
     */
    static Motion follow(RigidBody rigid) {
        double[] r0 = new double[9];
        double[] c0 = new double[3];
        rigid.motion().pose(0, r0, 0, c0, 0);
        // Per attachment, one scratch pose: the nodes of a body are driven one after the other on its thread.
        double[] rt = new double[9];
        double[] ct = new double[3];
        return (time, rest, out, o) -> {
            double dx = rest.x() - c0[0];
            double dy = rest.y() - c0[1];
            double dz = rest.z() - c0[2];
            double yx = r0[0] * dx + r0[3] * dy + r0[6] * dz;
            double yy = r0[1] * dx + r0[4] * dy + r0[7] * dz;
            double yz = r0[2] * dx + r0[5] * dy + r0[8] * dz;
            rigid.motion().pose(time, rt, 0, ct, 0);
            out[o] = rt[0] * yx + rt[1] * yy + rt[2] * yz + ct[0];
            out[o + 1] = rt[3] * yx + rt[4] * yy + rt[5] * yz + ct[1];
            out[o + 2] = rt[6] * yx + rt[7] * yy + rt[8] * yz + ct[2];
        };
    }
}
