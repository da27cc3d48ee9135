package org.tensim.testsupport;

import java.io.IOException;
import java.nio.file.Path;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.ObjWriter;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.shell.TwoSurfaces;

/** Coarse copies of a thin-shell mesh for tests that must run in seconds. */
public final class CoarseMeshes {
    private CoarseMeshes() {
    }

    /**
     * The shell {@code mesh} (mm) decimated face by face by vertex clustering with cells of {@code cellM}, written
     * as {@code out} (mm). The faces are clustered apart: a single group would fold a 3 mm shell's two faces
     * into one non-manifold sheet that barely moves. The file keeps the coarse mesh only: read back, its free rim is
     * its own, with the holes the clustering opens ({@link TwoSurfaces#decimated} carries the source's).
     */
    public static Path faceByFace(Path mesh, double cellM, Path out) throws IOException, MeshFormatException {
        TriangleMesh given = MeshLoader.load(mesh, MeshUnits.parse("mm")).mesh();
        TwoSurfaces faces = DiaphragmSetup.surfaces(given, 0.003).surfaces();
        TriangleMesh coarse = faces.decimated(cellM).mesh();
        ObjWriter.write(out, coarse, MeshUnits.parse("mm"), java.util.List.of(), 4);
        return out;
    }
}
