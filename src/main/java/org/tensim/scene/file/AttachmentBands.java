package org.tensim.scene.file;

import java.util.BitSet;
import java.util.List;
import org.tensim.model.Motion;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.scene.conditions.BandAttachment;
import org.tensim.scene.conditions.DistanceAttachment;

/**
 * A scene file's {@code attachment} with {@code mode: band}: the generic {@link BandAttachment} with one rigid body
 * as its target, the band the diaphragm's origins are by default. Each free node of the region that carries a share
 * A_i of the body's surface area ({@link SurfaceFaces#nodeAreas}) and lies within the threshold W of the rigid
 * surface at rest is tied by a zero-length spring of stiffness
 * <pre>
 *   k_i = k_b A_i taper(d_i)   (N/m; k_b the {@code stiffness}, Pa/m; taper 1 to W - T, cos^2 to 0 at W)
 * </pre>
 * to an anchor the rigid body carries from the node's rest point ({@link DistanceAttachment#anchored}, undamped:
 * the body's own damping acts on the node). The band's total stiffness is k_b times the area it covers, whatever the
 * mesh's resolution: a tie per node ({@code mode: tie}) adds stiffness with every node. A body without a surface
 * (nothing carries an area) is refused, as is a band that ties no node.
 */
final class AttachmentBands {
    private AttachmentBands() {
    }

    static void attach(MapReader r, RigidBody rigid, SceneBody b, BitSet nodes, SceneUnits u, Motion follow,
            double threshold) {
        if (r.has("damping")) {
            throw SceneException.at(r.node().get("damping"), "damping goes with mode: tie; a band's ties are"
                    + " undamped (the body's damping acts on its nodes)");
        }
        double kb = r.positive("stiffness", QuantityKind.AREAL_STIFFNESS, u, Double.NaN);
        double taper = r.nonNegative("taper", QuantityKind.LENGTH, u, 0);
        if (taper > threshold) {
            throw SceneException.at(r.node().get("taper"), String.format(java.util.Locale.ROOT, "the band's taper"
                    + " %.6g m is wider than its threshold %.6g m: expected 0 <= taper <= threshold", taper,
                    threshold));
        }
        if (b.surface() == null) {
            throw SceneException.at(r.node().get("mode"), "mode: band ties each node by its share of the body's"
                    + " surface area, and body '" + b.name() + "' (type " + b.type() + ") carries no surface: use"
                    + " mode: tie (a stiffness per node)");
        }
        Topology t = b.topology();
        double[] area = SurfaceFaces.nodeAreas(b.surface());
        BitSet candidates = new BitSet();
        for (int i = nodes.nextSetBit(0); i >= 0; i = nodes.nextSetBit(i + 1)) {
            Node n = t.node(i);
            if (i < area.length && area[i] > 0 && !n.isFixed() && !n.isDriven() && n.heldAxes() == 0) {
                candidates.set(i);
            }
        }
        List<BandAttachment.Target> target = List.of(new BandAttachment.Target(rigid.name(),
                q -> rigid.restDistance(q.x(), q.y(), q.z()),
                (top, v, k) -> DistanceAttachment.anchored(follow, k, 0).attach(top, v)));
        BandAttachment.Weights w = BandAttachment.weigh(t, candidates, target, threshold, taper);
        int tied = 0;
        double nearest = Double.POSITIVE_INFINITY;
        for (int v = candidates.nextSetBit(0); v >= 0; v = candidates.nextSetBit(v + 1)) {
            nearest = Math.min(nearest, w.distance()[v]);
            if (w.weight()[v] > 0) {
                BandAttachment.tie(t, w, v, kb * area[v] * w.weight()[v], target);
                tied++;
            }
        }
        if (tied == 0) {
            throw SceneException.at(r.node().get("threshold"), String.format(java.util.Locale.ROOT, "no node of the"
                    + " region on body '%s' carrying its surface lies within %.6g m of rigid body '%s' (the nearest"
                    + " is %.6g m from it): widen the threshold or the region", b.name(), threshold, rigid.name(),
                    nearest));
        }
    }
}
