package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Path;

/**
 * Reads an ASCII OFF file: the keyword {@code OFF} (alone or followed by the
 * counts on the same line), then {@code nVertices nFaces nEdges}, the vertices
 * ({@code x y z}) and the faces ({@code n i1 .. in}, 0-based; optional colour
 * values after the indices are ignored). Comments start with {@code #}. Polygons
 * are split into fans of triangles.
 */
public final class OffReader {
    private OffReader() {
    }

    /** Reads {@code file}, converting coordinates to metres. */
    public static TriangleMesh read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        MeshBuilder b = new MeshBuilder();
        try (TextLines in = new TextLines(file)) {
            String[] tok = nextTokens(in);
            if (tok == null) {
                throw in.error("the file is empty; expected the keyword OFF");
            }
            if (!tok[0].equalsIgnoreCase("OFF") && !tok[0].toUpperCase(java.util.Locale.ROOT).startsWith("OFF")) {
                throw in.error("found '" + tok[0] + "'; expected the keyword OFF on the first line");
            }
            String[] counts = tok.length >= 3 ? java.util.Arrays.copyOfRange(tok, 1, tok.length) : nextTokens(in);
            if (counts == null || counts.length < 2) {
                throw in.error("expected the counts 'nVertices nFaces nEdges'");
            }
            int nv = in.integer(counts[0], "the number of vertices");
            int nf = in.integer(counts[1], "the number of faces");
            if (nv <= 0 || nf <= 0) {
                throw in.error("counts " + nv + " vertices and " + nf + " faces; expected both > 0");
            }
            for (int i = 0; i < nv; i++) {
                String[] v = nextTokens(in);
                if (v == null) {
                    throw in.error("end of file after " + i + " vertices; expected " + nv);
                }
                if (v.length < 3) {
                    throw in.error("vertex " + i + " has " + v.length + " values; expected 'x y z'");
                }
                b.vertex(in.number(v[0], "vertex x coordinate"), in.number(v[1], "vertex y coordinate"),
                        in.number(v[2], "vertex z coordinate"));
            }
            for (int i = 0; i < nf; i++) {
                String[] f = nextTokens(in);
                if (f == null) {
                    throw in.error("end of file after " + i + " faces; expected " + nf);
                }
                int n = in.integer(f[0], "the number of corners of face " + i);
                if (n < 3 || f.length < n + 1) {
                    throw in.error("face " + i + " declares " + n + " corners and lists " + (f.length - 1)
                            + " values; expected at least 3 corners, all listed");
                }
                int[] c = new int[n];
                for (int k = 0; k < n; k++) {
                    c[k] = in.integer(f[k + 1], "a vertex index");
                    if (c[k] < 0 || c[k] >= nv) {
                        throw in.error("face " + i + " refers to vertex " + c[k] + "; expected 0.." + (nv - 1));
                    }
                }
                for (int k = 1; k + 1 < n; k++) {
                    b.triangle(c[0], c[k], c[k + 1]);
                }
            }
        }
        return b.build(units.metresPerUnit());
    }

    /** The tokens of the next line that is neither blank nor a comment, or null at the end. */
    private static String[] nextTokens(TextLines in) throws IOException {
        for (String s = in.next(); s != null; s = in.next()) {
            int hash = s.indexOf('#');
            String t = (hash >= 0 ? s.substring(0, hash) : s).trim();
            if (!t.isEmpty()) {
                return t.split("\\s+");
            }
        }
        return null;
    }
}
