package org.tensim.io.mesh;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A label per mesh vertex ({@link VertexLabel}) in a plain text file:
 * <pre>
 * # any number of comment lines, starting with '#'
 * tensim-labels 1 vertices=11354
 * 0 muscle
 * 1 tendon
 * 2 origin-costal
 * ...
 * </pre>
 * The header gives the format's version (1) and the vertex count of the mesh the labels
 * belong to; then one line {@code index label} per vertex, in any order, each index
 * once. Blank lines and '#' lines are ignored anywhere.
 *
 * <p><b>Which vertices.</b> The index is the 0-based vertex index of the mesh <em>as read
 * and cleaned by {@link MeshLoader}</em> (welded, small pieces dropped: its
 * {@link MeshCleaner.Result#mesh()}), not the raw file's order, which cleaning changes.
 * A label file made for a mesh with another cleaning, or for another mesh, is refused when
 * its vertex count differs; one with the same count cannot be told apart, so keep the
 * labels beside the mesh and the cleaning settings they were made with.
 *
 * <p>Errors are {@link MeshFormatException}s naming the file, the 1-based line, the
 * offending text and what was expected; no partial labelling is ever returned.
 */
public final class VertexLabelsFile {
    /** First word of the header line. */
    public static final String MAGIC = "tensim-labels";
    /** The format version this class writes and reads. */
    public static final int VERSION = 1;

    private VertexLabelsFile() {
    }

    /**
     * Writes one label per vertex, in index order, after a comment saying what the indices
     * refer to and how many vertices carry each label.
     *
     * @param labels the label of vertex v at [v]; no null entry
     * @throws IllegalArgumentException naming the first vertex without a label
     */
    public static void write(Path file, VertexLabel[] labels) throws IOException {
        if (labels.length == 0) {
            throw new IllegalArgumentException("no vertex to label for " + file + "; expected one label per vertex");
        }
        int[] count = new int[VertexLabel.values().length];
        for (int v = 0; v < labels.length; v++) {
            if (labels[v] == null) {
                throw new IllegalArgumentException("vertex " + v + " of " + labels.length + " has no label (null)"
                        + " writing " + file + "; expected one of " + VertexLabel.knownNames());
            }
            count[labels[v].ordinal()]++;
        }
        try (BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.US_ASCII)) {
            w.write("# tensim vertex labels: 'index label' per vertex; the index is the vertex's 0-based index in\n");
            w.write("# the mesh as read and cleaned by tensim's MeshLoader (not the raw file's order).\n");
            StringBuilder counts = new StringBuilder("#");
            for (VertexLabel l : VertexLabel.values()) {
                counts.append(' ').append(l.fileName()).append('=').append(count[l.ordinal()]);
            }
            w.write(counts.append('\n').toString());
            w.write(MAGIC + " " + VERSION + " vertices=" + labels.length + "\n");
            for (int v = 0; v < labels.length; v++) {
                w.write(v + " " + labels[v].fileName() + "\n");
            }
        }
    }

    /**
     * Reads the labels of a mesh of {@code expectedVertices} vertices.
     *
     * @return the label of vertex v at [v], every entry set
     * @throws MeshFormatException when the header is missing or malformed, its vertex count is
     *                             not {@code expectedVertices}, a line is not {@code index label},
     *                             an index is out of range or repeated, a label is unknown, or a
     *                             vertex has no line
     */
    public static VertexLabel[] read(Path file, int expectedVertices) throws IOException, MeshFormatException {
        if (expectedVertices < 1) {
            throw new IllegalArgumentException("expected vertex count " + expectedVertices + " reading " + file
                    + "; expected a mesh with at least one vertex");
        }
        VertexLabel[] labels = new VertexLabel[expectedVertices];
        int[] lineOf = new int[expectedVertices];
        boolean header = false;
        try (TextLines in = new TextLines(file)) {
            for (String s = in.next(); s != null; s = in.next()) {
                String t = s.trim();
                if (t.isEmpty() || t.charAt(0) == '#') {
                    continue;
                }
                String[] tok = t.split("\\s+");
                if (!header) {
                    header(in, t, tok, expectedVertices);
                    header = true;
                    continue;
                }
                if (tok.length != 2) {
                    throw in.error("'" + t + "' has " + tok.length + " fields; expected 'index label'"
                            + " (e.g. '0 muscle')");
                }
                int v = in.integer(tok[0], "a vertex index (0-based) before the label in '" + t + "'");
                if (v < 0 || v >= expectedVertices) {
                    throw in.error("vertex index " + v + " in '" + t + "' is outside 0.." + (expectedVertices - 1)
                            + "; expected an index of the header's " + expectedVertices + " vertices");
                }
                if (labels[v] != null) {
                    throw in.error("vertex " + v + " in '" + t + "' is labelled again (first on line " + lineOf[v]
                            + "); expected each index once");
                }
                try {
                    labels[v] = VertexLabel.parse(tok[1]);
                } catch (IllegalArgumentException e) {
                    throw in.error("'" + t + "': " + e.getMessage());
                }
                lineOf[v] = in.line();
            }
            if (!header) {
                throw in.error("end of file without the header; expected '" + MAGIC + " " + VERSION
                        + " vertices=N' before the labels");
            }
            List<Integer> missing = new ArrayList<>();
            int nMissing = 0;
            for (int v = 0; v < expectedVertices; v++) {
                if (labels[v] == null) {
                    if (missing.size() < 10) {
                        missing.add(v);
                    }
                    nMissing++;
                }
            }
            if (nMissing > 0) {
                throw in.error("end of file with " + nMissing + " of " + expectedVertices + " vertices unlabelled"
                        + " (vertex " + joined(missing) + (nMissing > missing.size() ? ", ..." : "")
                        + "); expected one 'index label' line per vertex");
            }
        }
        return labels;
    }

    /** Checks the header line {@code tensim-labels 1 vertices=N} against the mesh. */
    private static void header(TextLines in, String t, String[] tok, int expectedVertices)
            throws MeshFormatException {
        String expected = "expected the header '" + MAGIC + " " + VERSION + " vertices=" + expectedVertices + "'";
        if (!tok[0].equals(MAGIC)) {
            throw in.error("'" + t + "' is not a labels header; " + expected
                    + " as the first line that is not a comment");
        }
        if (tok.length != 3 || !tok[2].startsWith("vertices=")) {
            throw in.error("malformed header '" + t + "'; " + expected);
        }
        if (!tok[1].equals(Integer.toString(VERSION))) {
            throw in.error("labels format version '" + tok[1] + "' in '" + t + "' is not supported; " + expected);
        }
        int n = in.integer(tok[2].substring("vertices=".length()), "the mesh's vertex count after 'vertices=' in '"
                + t + "'; " + expected);
        if (n != expectedVertices) {
            throw in.error("the labels are for a mesh of " + n + " vertices ('" + t + "') but the mesh has "
                    + expectedVertices + " (as read and cleaned by MeshLoader); " + expected
                    + ": a label file made for another mesh or another cleaning");
        }
    }

    private static String joined(List<Integer> v) {
        return Arrays.toString(v.toArray()).replaceAll("[\\[\\]]", "");
    }
}
