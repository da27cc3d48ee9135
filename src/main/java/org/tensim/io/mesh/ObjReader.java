package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Path;

/**
 * Reads the geometry of a Wavefront OBJ file: {@code v x y z [w]} vertices and
 * {@code f} faces ({@code i}, {@code i/t}, {@code i//n}, {@code i/t/n}; 1-based,
 * negative indices count back from the last vertex read). Polygons with more than
 * three corners are split into a fan of triangles. Other records (vt, vn, g, o, s,
 * usemtl, mtllib, l, comments) are ignored.
 */
public final class ObjReader {
    private ObjReader() {
    }

    /** Reads {@code file}, converting coordinates to metres. Nothing is welded or dropped here. */
    public static TriangleMesh read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        MeshBuilder b = new MeshBuilder();
        // Faces may name vertices defined later in the file: indices are checked at the end,
        // each with the line of its face.
        int[] pending = new int[64];
        int nPending = 0;
        int[] corners = new int[16];
        try (TextLines in = new TextLines(file)) {
            for (String s = in.next(); s != null; s = in.next()) {
                String t = s.trim();
                if (t.isEmpty() || t.charAt(0) == '#') {
                    continue;
                }
                String[] tok = t.split("\\s+");
                if (tok[0].equals("v")) {
                    if (tok.length < 4) {
                        throw in.error("vertex has " + (tok.length - 1) + " coordinates; expected 'v x y z'");
                    }
                    b.vertex(in.number(tok[1], "vertex x coordinate"), in.number(tok[2], "vertex y coordinate"),
                            in.number(tok[3], "vertex z coordinate"));
                } else if (tok[0].equals("f")) {
                    int n = tok.length - 1;
                    if (n < 3) {
                        throw in.error("face has " + n + " corners; expected at least 3");
                    }
                    if (n > corners.length) {
                        corners = new int[n];
                    }
                    for (int k = 0; k < n; k++) {
                        String c = tok[k + 1];
                        int slash = c.indexOf('/');
                        int idx = in.integer(slash < 0 ? c : c.substring(0, slash), "a vertex index in a face");
                        if (idx == 0) {
                            throw in.error("vertex index 0 in a face; OBJ indices start at 1 (or are negative)");
                        }
                        corners[k] = idx > 0 ? idx - 1 : b.vertexCount() + idx;
                        if (corners[k] < 0) {
                            throw in.error("relative vertex index " + idx + " points before the first vertex ("
                                    + b.vertexCount() + " read so far)");
                        }
                    }
                    for (int k = 1; k + 1 < n; k++) {
                        if (nPending + 4 > pending.length) {
                            pending = java.util.Arrays.copyOf(pending, 2 * pending.length);
                        }
                        pending[nPending++] = corners[0];
                        pending[nPending++] = corners[k];
                        pending[nPending++] = corners[k + 1];
                        pending[nPending++] = in.line();
                    }
                }
            }
            if (b.vertexCount() == 0) {
                throw in.error("end of file with no vertex; expected 'v x y z' lines (empty or not an OBJ file)");
            }
            if (nPending == 0) {
                throw in.error("end of file with no face; expected 'f i j k' lines");
            }
        }
        int nv = b.vertexCount();
        for (int i = 0; i < nPending; i += 4) {
            for (int k = 0; k < 3; k++) {
                if (pending[i + k] >= nv) {
                    throw MeshFormatException.atLine(file, pending[i + 3], "face refers to vertex "
                            + (pending[i + k] + 1) + "; expected 1.." + nv + " (the file has " + nv + " vertices)");
                }
            }
            b.triangle(pending[i], pending[i + 1], pending[i + 2]);
        }
        return b.build(units.metresPerUnit());
    }
}
