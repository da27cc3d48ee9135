package org.tensim.scene.file;

import org.tensim.model.Node;
import org.tensim.model.Topology;

/**
 * One body of a loaded scene: its name, its type, its own topology (each body is simulated on its own, stepped
 * in lockstep with the others) and the node of each of its vertices (index lists and label files select
 * vertices; null when the vertices are the nodes in order), the surface it carries on its nodes (null when none:
 * its nodes are what is drawn), its type's lines for {@code tensim check} and what its type built besides the
 * topology (a diaphragm's scene, which runs it; null for most types).
 */
public record SceneBody(String name, String type, Topology topology, int[] vertexNodes, SceneNode node,
        EmbeddedSurface surface, java.util.List<String> report, Object built) {
    /** A body whose type built nothing besides its topology. */
    public SceneBody(String name, String type, Topology topology, int[] vertexNodes, SceneNode node,
            EmbeddedSurface surface, java.util.List<String> report) {
        this(name, type, topology, vertexNodes, node, surface, report, null);
    }

    /** A body that carries no surface and reports nothing beyond its counts. */
    public SceneBody(String name, String type, Topology topology, int[] vertexNodes, SceneNode node) {
        this(name, type, topology, vertexNodes, node, null, java.util.List.of());
    }

    /** Vertices index lists and label files may name. */
    public int vertexCount() {
        return vertexNodes == null ? topology.nodeCount() : vertexNodes.length;
    }

    /** The node of vertex v. */
    public int nodeOfVertex(int v) {
        return vertexNodes == null ? v : vertexNodes[v];
    }

    /** The bounding box of the nodes' initial positions: {xmin, ymin, zmin, xmax, ymax, zmax}, m. */
    public double[] bounds() {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE,
            -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (Node n : topology.nodes()) {
            double[] p = {n.position().x(), n.position().y(), n.position().z()};
            for (int a = 0; a < 3; a++) {
                b[a] = Math.min(b[a], p[a]);
                b[a + 3] = Math.max(b[a + 3], p[a]);
            }
        }
        return b;
    }
}
