package org.tensim.io.mesh;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/** Writes a {@link TriangleMesh} as Wavefront OBJ, in the given units, atomically (temporary file, then rename). */
public final class ObjWriter {
    private ObjWriter() {
    }

    /**
     * @param header comment lines written first (without the leading '#')
     * @param digits decimals per coordinate (in file units)
     */
    public static void write(Path path, TriangleMesh mesh, MeshUnits units, List<String> header, int digits)
            throws IOException {
        double s = 1 / units.metresPerUnit();
        String fmt = "v %." + digits + "f %." + digits + "f %." + digits + "f\n";
        org.tensim.io.OutputFiles.writeAtomically(path, out -> {
            BufferedWriter w = new BufferedWriter(new java.io.OutputStreamWriter(out, StandardCharsets.US_ASCII));
            for (String h : header) {
                w.write("# " + h + "\n");
            }
            for (int v = 0; v < mesh.vertexCount(); v++) {
                w.write(String.format(Locale.ROOT, fmt, mesh.coord(v, 0) * s, mesh.coord(v, 1) * s,
                        mesh.coord(v, 2) * s));
            }
            for (int t = 0; t < mesh.triangleCount(); t++) {
                w.write("f " + (mesh.corner(t, 0) + 1) + " " + (mesh.corner(t, 1) + 1) + " "
                        + (mesh.corner(t, 2) + 1) + "\n");
            }
            w.flush();
        });
    }
}
