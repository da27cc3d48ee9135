package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Path;

/**
 * Reads a Gmsh mesh file in the ASCII MSH format, version 2.2 or 4.1: its {@code $Nodes} and the 4-node tetrahedra
 * (element type 4) of its {@code $Elements}; elements of other types (points, lines, triangles, 10-node tets...) are
 * skipped and counted by type, and other sections ({@code $PhysicalNames}, {@code $Entities}, ...) skipped whole.
 * A binary file (file-type 1 in {@code $MeshFormat}) is refused with the way to write an ASCII one.
 */
public final class GmshReader {
    /** Gmsh's element type of the 4-node tetrahedron. */
    public static final int TETRAHEDRON = 4;

    private GmshReader() {
    }

    /** Reads {@code file}, converting coordinates to metres. */
    public static TetMeshReaders.Result read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        TetMeshBuilder b = new TetMeshBuilder(file);
        try (TextLines in = new TextLines(file)) {
            String version = null;
            boolean nodes = false;
            boolean elements = false;
            for (String s = nextLine(in); s != null; s = nextLine(in)) {
                if (!s.startsWith("$")) {
                    throw in.error("found '" + abbreviate(s) + "' outside a section; expected a section such as"
                            + " $MeshFormat, $Nodes or $Elements");
                }
                String section = s.substring(1);
                if (section.equals("MeshFormat")) {
                    version = format(in);
                } else if (version == null) {
                    throw in.error("found $" + section + " before $MeshFormat; expected a Gmsh .msh file starting"
                            + " with $MeshFormat");
                } else if (section.equals("Nodes")) {
                    if (version.equals("2.2")) {
                        nodes22(in, b);
                    } else {
                        nodes41(in, b);
                    }
                    nodes = true;
                    end(in, "Nodes");
                } else if (section.equals("Elements")) {
                    if (!nodes) {
                        throw in.error("$Elements before $Nodes; expected the nodes first");
                    }
                    if (version.equals("2.2")) {
                        elements22(in, b);
                    } else {
                        elements41(in, b);
                    }
                    elements = true;
                    end(in, "Elements");
                } else {
                    skipSection(in, section);
                }
            }
            if (version == null) {
                throw in.error("no $MeshFormat section; expected a Gmsh .msh file");
            }
            if (!nodes || !elements) {
                throw in.error("end of file without a " + (!nodes ? "$Nodes" : "$Elements") + " section; expected"
                        + " both $Nodes and $Elements");
            }
        }
        return b.build(units);
    }

    /** Reads {@code version file-type data-size} and {@code $EndMeshFormat}; returns "2.2" or "4.1". */
    private static String format(TextLines in) throws IOException, MeshFormatException {
        String[] t = tokens(in, "the format line 'version file-type data-size'");
        if (t.length < 3) {
            throw in.error("format line has " + t.length + " values; expected 'version file-type data-size'");
        }
        if (!t[1].equals("0")) {
            throw in.error("file-type " + t[1] + ": this is a binary .msh file; expected an ASCII one (file-type 0:"
                    + " in Gmsh, File > Export with 'Save all' and without 'binary', or gmsh -3 -format msh41"
                    + " without -bin)");
        }
        String v = t[0];
        if (!v.equals("2.2") && !v.equals("4.1")) {
            throw in.error("MSH version " + v + "; expected 2.2 or 4.1 (gmsh -format msh22 or msh41)");
        }
        end(in, "MeshFormat");
        return v;
    }

    private static void nodes22(TextLines in, TetMeshBuilder b) throws IOException, MeshFormatException {
        int n = count(in, "the number of nodes");
        for (int i = 0; i < n; i++) {
            String[] t = tokens(in, n + " nodes (" + i + " read)");
            if (t.length < 4) {
                throw in.error("node line has " + t.length + " values; expected 'tag x y z'");
            }
            b.node(in.integer(t[0], "a node tag"), in.number(t[1], "node x coordinate"),
                    in.number(t[2], "node y coordinate"), in.number(t[3], "node z coordinate"), in.line());
        }
    }

    private static void nodes41(TextLines in, TetMeshBuilder b) throws IOException, MeshFormatException {
        String[] h = tokens(in, "'numEntityBlocks numNodes minNodeTag maxNodeTag'");
        if (h.length < 4) {
            throw in.error("$Nodes header has " + h.length + " values; expected 'numEntityBlocks numNodes"
                    + " minNodeTag maxNodeTag'");
        }
        int blocks = in.integer(h[0], "the number of node blocks");
        for (int k = 0; k < blocks; k++) {
            String[] e = tokens(in, "a node block header 'entityDim entityTag parametric numNodesInBlock'");
            if (e.length < 4) {
                throw in.error("node block header has " + e.length + " values; expected 'entityDim entityTag"
                        + " parametric numNodesInBlock'");
            }
            boolean parametric = !e[2].equals("0");
            int n = in.integer(e[3], "the number of nodes in the block");
            if (n < 0) {
                throw in.error("a node block of " + n + " nodes; expected a count >= 0");
            }
            int[] tags = new int[n];
            for (int i = 0; i < n; i++) {
                String[] t = tokens(in, n + " node tags (" + i + " read)");
                tags[i] = in.integer(t[0], "a node tag");
            }
            for (int i = 0; i < n; i++) {
                String[] t = tokens(in, n + " node coordinates (" + i + " read)");
                if (t.length < 3 || parametric && t.length < 4) {
                    throw in.error("node coordinates line has " + t.length + " values; expected 'x y z'"
                            + (parametric ? " and the parametric coordinates" : ""));
                }
                b.node(tags[i], in.number(t[0], "node x coordinate"), in.number(t[1], "node y coordinate"),
                        in.number(t[2], "node z coordinate"), in.line());
            }
        }
    }

    private static void elements22(TextLines in, TetMeshBuilder b) throws IOException, MeshFormatException {
        int n = count(in, "the number of elements");
        for (int i = 0; i < n; i++) {
            String[] t = tokens(in, n + " elements (" + i + " read)");
            if (t.length < 3) {
                throw in.error("element line has " + t.length + " values; expected 'tag type numTags tags..."
                        + " nodes...'");
            }
            int type = in.integer(t[1], "an element type");
            int tags = in.integer(t[2], "the number of element tags");
            element(in, b, type, t, 3 + tags);
        }
    }

    private static void elements41(TextLines in, TetMeshBuilder b) throws IOException, MeshFormatException {
        String[] h = tokens(in, "'numEntityBlocks numElements minElementTag maxElementTag'");
        if (h.length < 4) {
            throw in.error("$Elements header has " + h.length + " values; expected 'numEntityBlocks numElements"
                    + " minElementTag maxElementTag'");
        }
        int blocks = in.integer(h[0], "the number of element blocks");
        for (int k = 0; k < blocks; k++) {
            String[] e = tokens(in, "an element block header 'entityDim entityTag elementType numElementsInBlock'");
            if (e.length < 4) {
                throw in.error("element block header has " + e.length + " values; expected 'entityDim entityTag"
                        + " elementType numElementsInBlock'");
            }
            int type = in.integer(e[2], "an element type");
            int n = in.integer(e[3], "the number of elements in the block");
            for (int i = 0; i < n; i++) {
                element(in, b, type, tokens(in, n + " elements (" + i + " read)"), 1);
            }
        }
    }

    /** One element whose node tags start at token {@code first}: a tet is added, another type counted. */
    private static void element(TextLines in, TetMeshBuilder b, int type, String[] t, int first)
            throws MeshFormatException {
        if (type != TETRAHEDRON) {
            b.skip("type " + type);
            return;
        }
        if (t.length != first + 4) {
            throw in.error("tetrahedron (element type 4) lists " + Math.max(0, t.length - first) + " nodes; expected"
                    + " 4");
        }
        b.tet(in.integer(t[first], "a node tag"), in.integer(t[first + 1], "a node tag"),
                in.integer(t[first + 2], "a node tag"), in.integer(t[first + 3], "a node tag"), in.line());
    }

    private static int count(TextLines in, String what) throws IOException, MeshFormatException {
        String[] t = tokens(in, what);
        int n = in.integer(t[0], what);
        if (n < 0) {
            throw in.error(what + " is " + n + "; expected a count >= 0");
        }
        return n;
    }

    private static void end(TextLines in, String section) throws IOException, MeshFormatException {
        String s = nextLine(in);
        if (s == null || !s.equals("$End" + section)) {
            throw in.error((s == null ? "end of file" : "found '" + abbreviate(s) + "'") + "; expected $End"
                    + section);
        }
    }

    private static void skipSection(TextLines in, String section) throws IOException, MeshFormatException {
        int start = in.line();
        for (String s = in.next(); s != null; s = in.next()) {
            if (s.trim().equals("$End" + section)) {
                return;
            }
        }
        throw MeshFormatException.atLine(in.file(), start, "section $" + section + " has no $End" + section);
    }

    /** The next non-blank line, trimmed, or null at the end. */
    private static String nextLine(TextLines in) throws IOException {
        for (String s = in.next(); s != null; s = in.next()) {
            if (!s.trim().isEmpty()) {
                return s.trim();
            }
        }
        return null;
    }

    private static String[] tokens(TextLines in, String what) throws IOException, MeshFormatException {
        String s = nextLine(in);
        if (s == null) {
            throw in.error("end of file; expected " + what);
        }
        if (s.startsWith("$")) {
            throw in.error("found " + s + "; expected " + what);
        }
        return s.split("\\s+");
    }

    private static String abbreviate(String s) {
        return s.length() > 40 ? s.substring(0, 40) + "..." : s;
    }
}
