package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Map;
import org.tensim.model.Node;

/**
 * A {@code contact} or {@code sliding} condition whose {@code with:} names a deformable body: the region's free nodes
 * (the followers, on another body) touch or slide on the surface that body carries ({@link EmbeddedSurface}), both
 * bodies moving ({@link org.tensim.solver.SurfaceSliding}). The two bodies then share one state
 * ({@link CoupledBodies}). Keys as with a rigid body: {@code stiffness} (N/m a node, required), {@code gap} (length,
 * contact only, 0); {@code hard} is for rigid bodies only. As with a rigid body, a sliding node keeps its rest
 * distance d0 to the surface from both sides, and a contact node that starts closer than the gap keeps d0 as its
 * gap.
 *
 * @param type           {@code contact} (one-sided) or {@code sliding} (bilateral)
 * @param body           the followers' body
 * @param followers      the followers' node ids in that body
 * @param with           the body carrying the surface
 * @param stiffnessNPerM k per follower, N/m
 * @param gapM           the contact's gap g, m (0 for sliding, whose gaps are the rest distances)
 * @param node           the condition in the file, for messages
 */
public record BodyCoupling(String type, String body, int[] followers, String with, double stiffnessNPerM,
        double gapM, SceneNode node) {
    /** True when the condition's {@code with:} names one of the deformable {@code bodies}. */
    static boolean withDeformable(String type, MapReader r, Map<String, SceneBody> bodies) {
        return (type.equals("contact") || type.equals("sliding")) && r.has("with")
                && bodies.containsKey(r.scalar("with").text());
    }

    /** One coupling per body the region has nodes on; refused with the file's line when it cannot hold. */
    static List<BodyCoupling> read(String type, MapReader r, Map<String, SceneBody> bodies,
            SceneRegions.Region region, SceneUnits u) {
        SceneNode w = r.scalar("with");
        SceneBody surface = bodies.get(w.text());
        if (surface.surface() == null) {
            throw SceneException.at(w, "body '" + w.text() + "' (type " + surface.type() + ") carries no surface to "
                    + (type.equals("contact") ? "touch" : "slide on") + ": with: names a rigid body or a deformable"
                    + " body with a surface (type volume)");
        }
        if (r.has("hard") && r.bool("hard", false)) {
            throw SceneException.at(r.node().get("hard"), "hard: true puts nodes back on a rigid body's surface;"
                    + " with a deformable body ('" + w.text() + "') leave it out (the penalty holds)");
        }
        double k = r.positive("stiffness", QuantityKind.STIFFNESS, u, Double.NaN);
        double gap = type.equals("contact") ? r.quantity("gap", QuantityKind.LENGTH, u, 0) : 0;
        List<BodyCoupling> out = new ArrayList<>();
        for (Map.Entry<String, BitSet> e : region.nodes().entrySet()) {
            if (e.getKey().equals(w.text())) {
                throw SceneException.at(r.node().get("region"), "region '" + region.name() + "' has nodes on body '"
                        + w.text() + "' itself: a body does not " + type + " with its own surface");
            }
            List<Node> nodes = bodies.get(e.getKey()).topology().nodes();
            int[] free = e.getValue().stream().filter(i -> !nodes.get(i).isFixed() && !nodes.get(i).isDriven())
                    .toArray();
            if (free.length == 0) {
                throw SceneException.at(r.node(), "no free node of the region on body '" + e.getKey() + "' (its "
                        + e.getValue().cardinality() + " nodes are fixed or driven)");
            }
            out.add(new BodyCoupling(type, e.getKey(), free, w.text(), k, gap, r.node()));
        }
        return out;
    }
}
