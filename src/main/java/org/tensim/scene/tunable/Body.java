package org.tensim.scene.tunable;

import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;

/**
 * One simulated object of a {@link ViewScene} and what to draw of it. Springs and
 * rigid links are drawn from the simulation's own state; a surface is drawn from
 * {@code triangles} when there are any.
 *
 * @param name          shown in the chart legend and in warnings
 * @param simulation    the simulation that moves this body's nodes
 * @param triangles     node ids, three per triangle (may be empty: no surface)
 * @param vertexColours RGB in [0, 1] per node (3 per node), or null for one colour
 * @param offset        where the body is drawn relative to the scene origin, m (e.g. side by side)
 * @param probeNode     the node whose displacement is charted
 * @param visibleNodes  nodes {@code 0 .. visibleNodes-1} are drawn, with the springs and links between them;
 *                      the others (helpers such as fixed anchors) are simulated but not drawn
 * @param structureEdges node id pairs drawn as a separate layer of bone-coloured lines (ribs, sternum,
 *                      cartilage); may be empty
 */
public record Body(String name, Simulation simulation, int[] triangles, float[] vertexColours, Vec3 offset,
        int probeNode, int visibleNodes, int[] structureEdges) {
    /** A body whose nodes are all drawn, without structure lines. */
    public Body(String name, Simulation simulation, int[] triangles, float[] vertexColours, Vec3 offset,
            int probeNode) {
        this(name, simulation, triangles, vertexColours, offset, probeNode, simulation.state().nodeCount,
                new int[0]);
    }

    public Body {
        int n = simulation.state().nodeCount;
        if (visibleNodes < 1 || visibleNodes > n) {
            throw new IllegalArgumentException(name + ": visible node count " + visibleNodes + " is out of range 1.."
                    + n);
        }
        if (triangles.length % 3 != 0) {
            throw new IllegalArgumentException(name + ": triangle index count " + triangles.length
                    + " is not a multiple of 3");
        }
        for (int i : triangles) {
            if (i < 0 || i >= n) {
                throw new IllegalArgumentException(name + ": triangle node " + i + " is out of range 0.." + (n - 1));
            }
        }
        if (vertexColours != null && vertexColours.length != 3 * n) {
            throw new IllegalArgumentException(name + ": " + vertexColours.length + " vertex colour values, expected "
                    + 3 * n + " (3 per node)");
        }
        if (structureEdges.length % 2 != 0) {
            throw new IllegalArgumentException(name + ": structure edge index count " + structureEdges.length
                    + " is not even (two nodes per edge)");
        }
        for (int i : structureEdges) {
            if (i < 0 || i >= visibleNodes) {
                throw new IllegalArgumentException(name + ": structure edge node " + i + " is out of range 0.."
                        + (visibleNodes - 1));
            }
        }
        if (probeNode < 0 || probeNode >= n) {
            throw new IllegalArgumentException(name + ": probe node " + probeNode + " is out of range 0.." + (n - 1));
        }
    }

    /** Number of nodes. */
    public int nodeCount() {
        return simulation.state().nodeCount;
    }
}
