package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Reads STL, binary or ASCII. A file whose size is exactly {@code 84 + 50 n}
 * bytes, n being the little-endian count at byte 80, is binary; otherwise a file
 * that starts with {@code solid} is ASCII; anything else is read as binary, so a
 * truncated binary file is reported as such with the byte offset where data runs
 * out. STL stores every triangle with its own three corners: vertices are welded
 * afterwards by {@link MeshCleaner}.
 */
public final class StlReader {
    private static final int HEADER = 80;
    private static final int RECORD = 50;

    private StlReader() {
    }

    /** Reads {@code file}, converting coordinates to metres. */
    public static TriangleMesh read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        byte[] data = Files.readAllBytes(file);
        if (data.length == 0) {
            throw new MeshFormatException(file, "byte 0", "the file is empty; expected an ASCII ('solid ...') or"
                    + " binary STL");
        }
        if (data.length >= HEADER + 4) {
            long n = ByteBuffer.wrap(data, HEADER, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xffffffffL;
            if (HEADER + 4 + RECORD * n == data.length) {
                return binary(file, data, n, units);
            }
        }
        if (startsWithSolid(data)) {
            return ascii(file, units);
        }
        if (data.length < HEADER + 4) {
            throw new MeshFormatException(file, "byte " + data.length, "truncated binary STL: the file has "
                    + data.length + " bytes; expected at least 84 (80-byte header and a triangle count)");
        }
        long n = ByteBuffer.wrap(data, HEADER, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xffffffffL;
        return binary(file, data, n, units);
    }

    private static boolean startsWithSolid(byte[] data) {
        int i = 0;
        while (i < data.length && Character.isWhitespace(data[i])) {
            i++;
        }
        return data.length - i >= 5 && new String(data, i, 5, StandardCharsets.US_ASCII).equalsIgnoreCase("solid");
    }

    private static TriangleMesh binary(Path file, byte[] data, long n, MeshUnits units) throws MeshFormatException {
        long expected = HEADER + 4 + RECORD * n;
        if (n == 0) {
            throw new MeshFormatException(file, "byte 80", "binary STL declares 0 triangles; expected at least 1");
        }
        if (data.length < expected) {
            long complete = (data.length - HEADER - 4) / RECORD;
            throw new MeshFormatException(file, "byte " + (HEADER + 4 + RECORD * complete),
                    "truncated binary STL: the header declares " + n + " triangles (" + expected
                            + " bytes) but the file has " + data.length + " bytes; triangle " + complete
                            + " is incomplete");
        }
        // Bytes after the declared triangles (some writers pad) are ignored.
        ByteBuffer buf = ByteBuffer.wrap(data).order(ByteOrder.LITTLE_ENDIAN);
        MeshBuilder b = new MeshBuilder();
        for (int t = 0; t < n; t++) {
            int base = HEADER + 4 + RECORD * t + 12; // skip the stored normal
            for (int k = 0; k < 3; k++) {
                int o = base + 12 * k;
                float x = buf.getFloat(o);
                float y = buf.getFloat(o + 4);
                float z = buf.getFloat(o + 8);
                if (!Float.isFinite(x) || !Float.isFinite(y) || !Float.isFinite(z)) {
                    throw new MeshFormatException(file, "byte " + o, "triangle " + t + " corner " + k
                            + " has coordinate (" + x + ", " + y + ", " + z + "); expected finite numbers");
                }
                b.vertex(x, y, z);
            }
            b.triangle(3 * t, 3 * t + 1, 3 * t + 2);
        }
        return b.build(units.metresPerUnit());
    }

    private static TriangleMesh ascii(Path file, MeshUnits units) throws IOException, MeshFormatException {
        MeshBuilder b = new MeshBuilder();
        try (TextLines in = new TextLines(file)) {
            int inLoop = -1; // vertices read in the current loop, -1 outside a loop
            int first = 0;
            for (String s = in.next(); s != null; s = in.next()) {
                String t = s.trim();
                if (t.isEmpty()) {
                    continue;
                }
                String[] tok = t.split("\\s+");
                switch (tok[0].toLowerCase(java.util.Locale.ROOT)) {
                    case "outer":
                        inLoop = 0;
                        first = b.vertexCount();
                        break;
                    case "vertex":
                        if (inLoop < 0) {
                            throw in.error("'vertex' outside 'outer loop ... endloop'");
                        }
                        if (tok.length < 4) {
                            throw in.error("vertex has " + (tok.length - 1) + " coordinates; expected 'vertex x y z'");
                        }
                        b.vertex(in.number(tok[1], "vertex x coordinate"), in.number(tok[2], "vertex y coordinate"),
                                in.number(tok[3], "vertex z coordinate"));
                        inLoop++;
                        break;
                    case "endloop":
                        if (inLoop < 3) {
                            throw in.error("loop with " + Math.max(inLoop, 0) + " vertices; expected 3");
                        }
                        for (int k = 1; k + 1 < inLoop; k++) {
                            b.triangle(first, first + k, first + k + 1);
                        }
                        inLoop = -1;
                        break;
                    case "solid":
                    case "facet":
                    case "endfacet":
                    case "endsolid":
                        break;
                    default:
                        throw in.error("unexpected '" + tok[0] + "'; expected solid, facet, outer loop, vertex,"
                                + " endloop, endfacet or endsolid");
                }
            }
            if (inLoop >= 0) {
                throw in.error("end of file inside a facet; expected 'endloop'");
            }
            if (b.triangleCount() == 0) {
                throw in.error("end of file with no facet; expected 'facet normal ... endfacet' blocks");
            }
        }
        return b.build(units.metresPerUnit());
    }
}
