package org.tensim.scene.file;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;

/**
 * A surface a body carries on its nodes (a volume's fine surface on its lattice): what is drawn, and what surface
 * probes read. Vertex v sits at {@code sum_k w_vk x_{n(v,k)}} ({@link LinearMapping#apply}).
 *
 * @param mesh    the surface at rest, m
 * @param mapping its vertices on the body's nodes, one row a vertex
 */
public record EmbeddedSurface(TriangleMesh mesh, LinearMapping mapping) {
}
