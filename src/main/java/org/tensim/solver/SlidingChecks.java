package org.tensim.solver;

import org.tensim.model.LinearMapping;

/**
 * The refusals of a {@link SurfaceSliding}'s arguments, each naming the follower and the value: what a term needs
 * before it pairs anything.
 */
final class SlidingChecks {
    private SlidingChecks() {
    }

    /**
     * Node followers as a mapping of one node each (weight 1), refusing a node out of range or listed twice.
     *
     * @param nodes the state's node count
     */
    static LinearMapping nodeFollowers(int[] followers, int nodes) {
        boolean[] seen = new boolean[nodes];
        LinearMapping.Builder b = new LinearMapping.Builder(Math.max(1, nodes));
        int[] one = new int[1];
        double[] unit = {1};
        for (int e = 0; e < followers.length; e++) {
            int j = followers[e];
            if (j < 0 || j >= nodes) {
                throw new IllegalArgumentException("follower " + e + " is node " + j + ": expected a node id in [0, "
                        + nodes + ")");
            }
            if (seen[j]) {
                throw new IllegalArgumentException("follower " + e + " (node " + j + ") is listed twice");
            }
            seen[j] = true;
            one[0] = j;
            b.add(one, unit);
        }
        return b.build();
    }

    /**
     * Refuses: mappings over more nodes than the state has; counts that differ; no mode; a follower one of whose
     * nodes carries a point of the surface (the follower would push the surface it is held on); a stiffness not
     * positive and finite; a gap not finite.
     */
    static void refuse(LinearMapping followers, LinearMapping surface, double[] stiffness, double[] gapsM,
            SurfaceSliding.Mode mode, int nodes) {
        for (LinearMapping m : new LinearMapping[] {surface, followers}) {
            if (m.nodeCount() > nodes) {
                throw new IllegalArgumentException("the sliding " + (m == surface ? "surface's" : "followers'")
                        + " mapping refers to " + m.nodeCount() + " nodes but the positions have " + nodes);
            }
        }
        int n = followers.pointCount();
        if (n == 0 || stiffness.length != n || gapsM.length != n) {
            throw new IllegalArgumentException("a sliding term needs followers and one stiffness and gap each: got "
                    + n + " followers, " + stiffness.length + " stiffnesses, " + gapsM.length + " gaps");
        }
        if (mode == null) {
            throw new IllegalArgumentException("a sliding term needs a mode: SLIDING or CONTACT");
        }
        boolean[] carries = new boolean[nodes];
        for (int i = 0; i < surface.pointCount(); i++) {
            for (int k = 0; k < surface.entries(i); k++) {
                carries[surface.node(i, k)] = true;
            }
        }
        for (int e = 0; e < n; e++) {
            for (int k = 0; k < followers.entries(e); k++) {
                int j = followers.node(e, k);
                if (carries[j]) {
                    throw new IllegalArgumentException("follower " + e + " (node " + j + ") carries a point of the"
                            + " surface it slides on");
                }
            }
            if (!(stiffness[e] > 0) || Double.isInfinite(stiffness[e])) {
                throw new IllegalArgumentException("follower " + e + " (" + name(followers, e) + ") has stiffness "
                        + stiffness[e] + " N/m: expected a positive finite value");
            }
            if (!Double.isFinite(gapsM[e])) {
                throw new IllegalArgumentException("follower " + e + " (" + name(followers, e) + ") has gap "
                        + gapsM[e] + " m: expected a finite length");
            }
        }
    }

    private static String name(LinearMapping followers, int e) {
        return followers.entries(e) == 1 ? "node " + followers.node(e, 0)
                : "a point on " + followers.entries(e) + " nodes";
    }
}
