package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Path;

/** Reads a mesh file (OBJ, STL, OFF) in the given units and cleans it: the one call scenes use. */
public final class MeshLoader {
    private MeshLoader() {
    }

    /**
     * Reads and cleans {@code file}; coordinates in metres. A vertex far from all the
     * others is refused ({@link MeshExtent#refuseOutliers}), never dropped silently.
     */
    public static MeshCleaner.Result load(Path file, MeshUnits units, MeshCleaner.Options options)
            throws IOException, MeshFormatException {
        TriangleMesh raw = MeshReaders.read(file, units);
        MeshExtent.refuseOutliers(raw, file);
        return MeshCleaner.clean(raw, options, file.getFileName().toString());
    }

    /** Reads and cleans {@code file} with {@link MeshCleaner.Options#defaults()}. */
    public static MeshCleaner.Result load(Path file, MeshUnits units) throws IOException, MeshFormatException {
        return load(file, units, MeshCleaner.Options.defaults());
    }
}
