package org.tensim.io.mesh;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What {@link MeshCleaner} found in a mesh and what it did.
 *
 * @param file                 the source (file name, or a description)
 * @param rawVertices          vertices in the file
 * @param rawTriangles         triangles in the file (polygons split into triangles)
 * @param weldedVertices       vertices merged into another within the weld tolerance
 * @param degenerateTriangles  triangles dropped: two equal corners after welding, or zero area
 * @param vertices             distinct vertices used by triangles after welding (before dropping components)
 * @param triangles            triangles after welding and dropping degenerate ones
 * @param components           connected components (triangles joined through shared edges)
 * @param boundaryLoops        connected chains of boundary edges (edges used by one triangle): holes and rims
 * @param boundaryEdges        edges used by exactly one triangle
 * @param nonManifoldEdges     edges used by three or more triangles
 * @param droppedComponents    small components removed (see {@link MeshCleaner.Options})
 * @param droppedTriangles     triangles in the dropped components
 * @param keptVertices         vertices of the cleaned mesh
 * @param keptTriangles        triangles of the cleaned mesh
 */
public record MeshReport(String file, int rawVertices, int rawTriangles, int weldedVertices, int degenerateTriangles,
        int vertices, int triangles, int components, int boundaryLoops, int boundaryEdges, int nonManifoldEdges,
        int droppedComponents, int droppedTriangles, int keptVertices, int keptTriangles) {

    /** The report as an ordered map (for summary.json). */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("file", file);
        m.put("raw_vertices", rawVertices);
        m.put("raw_triangles", rawTriangles);
        m.put("welded_vertices", weldedVertices);
        m.put("degenerate_triangles", degenerateTriangles);
        m.put("vertices", vertices);
        m.put("triangles", triangles);
        m.put("components", components);
        m.put("boundary_loops", boundaryLoops);
        m.put("boundary_edges", boundaryEdges);
        m.put("non_manifold_edges", nonManifoldEdges);
        m.put("dropped_components", droppedComponents);
        m.put("dropped_triangles", droppedTriangles);
        m.put("kept_vertices", keptVertices);
        m.put("kept_triangles", keptTriangles);
        return m;
    }

    /** One line for a console. */
    public String describe() {
        return file + ": " + vertices + " vertices, " + triangles + " triangles, " + components + " components, "
                + boundaryLoops + " boundary loops, " + nonManifoldEdges + " non-manifold edges; welded "
                + weldedVertices + " vertices, dropped " + degenerateTriangles + " degenerate triangles and "
                + droppedComponents + " small components (" + droppedTriangles + " triangles); kept " + keptVertices
                + " vertices, " + keptTriangles + " triangles";
    }
}
