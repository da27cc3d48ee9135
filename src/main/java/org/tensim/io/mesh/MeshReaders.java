package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** Chooses the reader by file extension: {@code .obj}, {@code .stl}, {@code .off}. */
public final class MeshReaders {
    private MeshReaders() {
    }

    /**
     * Reads a mesh file as it is (no welding or cleaning), in metres.
     *
     * @throws MeshFormatException for a missing, unknown or malformed file (the message names the file,
     *                             the line or byte and what was expected)
     */
    public static TriangleMesh read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        if (!Files.isRegularFile(file)) {
            throw new MeshFormatException(file, "open", "no such file; expected a readable .obj, .stl or .off mesh");
        }
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".obj")) {
            return ObjReader.read(file, units);
        } else if (name.endsWith(".stl")) {
            return StlReader.read(file, units);
        } else if (name.endsWith(".off")) {
            return OffReader.read(file, units);
        }
        throw new MeshFormatException(file, "name", "unknown mesh format; expected a file name ending in .obj, .stl"
                + " or .off");
    }
}
