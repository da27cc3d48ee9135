package org.tensim.scene.conditions;

import java.util.BitSet;
import java.util.List;
import org.tensim.model.Motion;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * Attachment by a distance threshold, the paper's rule (Villard, Bourne and Bello 2008, section 3.2: "attachment
 * points ... such that the distance to the group ribs, sternum, cartilage is under a given threshold"), on any
 * topology and any targets. Each candidate node is attached to its nearest target (the first of equally near
 * ones) when its rest distance to it is within the threshold, {@code d <= W} (a node inside a solid, {@code d < 0},
 * included), and what attaching does is the target's {@link Hold}:
 * <ul>
 * <li>{@link #drive}: the node moves with a prescribed motion (a rigid body's, a rib's helical axis);</li>
 * <li>{@link #fix}: the node is held at its rest point (the spine);</li>
 * <li>{@link #tie}: springs of a given stiffness (N/m) from the node to given nodes (the ends of a cartilage or
 * sternum segment), handed to a sink, so that a builder which damps its springs once all are known collects
 * them;</li>
 * <li>{@link #anchored}: a zero-length spring from the node to an anchor node the target carries from the node's
 * rest point (a scene file's {@code attachment} with {@code mode: tie}).</li>
 * </ul>
 * A scene file's {@code attachment} condition attaches a region to one rigid body this way, and the diaphragm's
 * paper-threshold attachment its nodes to the rib cage's segments. The count of attached nodes, hence the total
 * stiffness, grows with the mesh's resolution (the reason the diaphragm's default is a band of ties with a
 * stiffness per unit area instead).
 */
public final class DistanceAttachment {
    private DistanceAttachment() {
    }

    /** A target's distance from a rest point, m (negative inside a solid; NaN never attaches). */
    @FunctionalInterface
    public interface Distance {
        double at(Vec3 restPoint);
    }

    /** What attaching node {@code node} of t to a target does. */
    @FunctionalInterface
    public interface Hold {
        void attach(Topology t, int node);
    }

    /** Receives a spring of stiffness k (N/m) between nodes a and b. */
    @FunctionalInterface
    public interface SpringSink {
        void add(int a, int b, double stiffnessNPerM);
    }

    /**
     * Something nodes can be attached to.
     *
     * @param name     for messages
     * @param distance its distance from a node's rest point, m
     * @param hold     what attaching a node to it does
     */
    public record Target(String name, Distance distance, Hold hold) {
        public Target {
            if (name == null || distance == null || hold == null) {
                throw new IllegalArgumentException("an attachment target needs a name, a distance and a hold, got "
                        + name + ", " + distance + ", " + hold);
            }
        }
    }

    /**
     * What an attachment did.
     *
     * @param target   per node of the topology, the index of the target it was attached to, or -1
     * @param attached the number of nodes attached
     * @param nearest  the smallest distance of a candidate to its nearest target, m (infinite when none)
     */
    public record Result(int[] target, int attached, double nearest) {
    }

    /** The node moves with m. */
    public static Hold drive(Motion m) {
        if (m == null) {
            throw new IllegalArgumentException("a driven attachment needs a motion");
        }
        return (t, node) -> t.node(node).drive(m);
    }

    /** The node is fixed at its rest point. */
    public static Hold fix() {
        return (t, node) -> t.node(node).fix();
    }

    /** One spring of stiffness k (N/m, &gt; 0) from the node to each of {@code to}, handed to the sink in order. */
    public static Hold tie(SpringSink sink, double stiffnessNPerM, int... to) {
        if (!(stiffnessNPerM > 0) || Double.isInfinite(stiffnessNPerM)) {
            throw new IllegalArgumentException("attachment tie stiffness must be positive and finite (N/m), got "
                    + stiffnessNPerM);
        }
        int[] ends = to.clone();
        return (t, node) -> {
            for (int e : ends) {
                sink.add(node, e, stiffnessNPerM);
            }
        };
    }

    /**
     * A spring of stiffness k (N/m, &gt; 0), damping c (N s/m, &gt;= 0) and rest length zero from the node to its
     * anchor: a new node of t at the node's rest point, driven by m (the point of the target that lies there at
     * rest, carried as the target moves). The spring pulls the node towards the anchor with {@code k (a - x)}
     * along any direction, so that a node loaded by F keeps within |F| / k of where the target carries its rest
     * point once it has settled. The anchor takes the node's mass (it is driven: its mass moves nothing, but a
     * node needs one).
     */
    public static Hold anchored(Motion m, double stiffnessNPerM, double dampingNsPerM) {
        if (m == null) {
            throw new IllegalArgumentException("an anchored attachment needs the motion that carries its anchors");
        }
        if (!(stiffnessNPerM > 0) || Double.isInfinite(stiffnessNPerM)) {
            throw new IllegalArgumentException("attachment tie stiffness must be positive and finite (N/m), got "
                    + stiffnessNPerM);
        }
        if (!(dampingNsPerM >= 0) || Double.isInfinite(dampingNsPerM)) {
            throw new IllegalArgumentException("attachment tie damping must be >= 0 and finite (N s/m), got "
                    + dampingNsPerM);
        }
        return (t, node) -> {
            org.tensim.model.Node n = t.node(node);
            org.tensim.model.Node anchor = t.addNode(n.position(), n.mass());
            anchor.drive(m);
            t.addSpring(node, anchor.id(), stiffnessNPerM, 0, dampingNsPerM);
        };
    }

    /**
     * Attaches every candidate node of t within {@code thresholdM} of its nearest target (at the nodes' current, rest
     * positions), in increasing node order. A hold may add nodes to t (an anchor): they are never candidates.
     *
     * @param thresholdM W, m (finite)
     */
    public static Result attach(Topology t, BitSet candidates, List<Target> targets, double thresholdM) {
        if (Double.isNaN(thresholdM) || Double.isInfinite(thresholdM)) {
            throw new IllegalArgumentException("attachment threshold must be finite (m), got " + thresholdM);
        }
        int[] to = new int[t.nodeCount()];
        java.util.Arrays.fill(to, -1);
        int attached = 0;
        double nearest = Double.POSITIVE_INFINITY;
        for (int v = candidates.nextSetBit(0); v >= 0; v = candidates.nextSetBit(v + 1)) {
            Vec3 q = t.node(v).position();
            int best = -1;
            double bestD = Double.POSITIVE_INFINITY;
            for (int i = 0; i < targets.size(); i++) {
                double d = targets.get(i).distance().at(q);
                if (d < bestD) {
                    bestD = d;
                    best = i;
                }
            }
            nearest = Math.min(nearest, bestD);
            if (best < 0 || bestD > thresholdM) {
                continue;
            }
            targets.get(best).hold().attach(t, v);
            to[v] = best;
            attached++;
        }
        return new Result(to, attached, nearest);
    }
}
