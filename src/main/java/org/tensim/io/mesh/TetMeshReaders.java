package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;

/** Chooses the volume mesh reader by file extension: {@code .msh} (Gmsh), {@code .vtk} (legacy VTK). */
public final class TetMeshReaders {
    /**
     * A volume mesh as read.
     *
     * @param mesh        the tetrahedra and the nodes they use, m
     * @param skipped     elements of other types than the 4-node tetrahedron, counted by type ("type 2" for Gmsh's
     *                    triangles, "VTK type 5" for VTK's); empty when there were none
     * @param unusedNodes nodes of the file no tetrahedron uses (dropped)
     */
    public record Result(TetMesh mesh, Map<String, Integer> skipped, int unusedNodes) {
    }

    private TetMeshReaders() {
    }

    /**
     * Reads a tetrahedral mesh, in metres.
     *
     * @throws MeshFormatException for a missing, unknown, binary or malformed file, or an inverted or degenerate tet
     *                             (the message names the file, the line and what was expected)
     */
    public static Result read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        if (!Files.isRegularFile(file)) {
            throw new MeshFormatException(file, "open", "no such file; expected a readable .msh or .vtk volume mesh");
        }
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".msh")) {
            return GmshReader.read(file, units);
        } else if (name.endsWith(".vtk")) {
            return VtkUnstructuredReader.read(file, units);
        }
        throw new MeshFormatException(file, "name", "unknown volume mesh format; expected a file name ending in .msh"
                + " (Gmsh, ASCII 2.2 or 4.1) or .vtk (legacy VTK, ASCII UNSTRUCTURED_GRID)");
    }
}
