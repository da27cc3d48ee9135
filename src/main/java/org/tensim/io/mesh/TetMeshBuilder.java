package org.tensim.io.mesh;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Collects the nodes (by the file's tags) and tetrahedra (with the line each came from) of a volume mesh file, and
 * builds the {@link TetMesh} of the nodes the tets use, refusing a tet that refers to no node, is inverted or is
 * degenerate with its index and line (package-private, shared by the Gmsh and VTK readers).
 */
final class TetMeshBuilder {
    private final Path file;
    private final Map<Integer, Integer> indexOfTag = new HashMap<>();
    private double[] xyz = new double[3 * 64];
    private int nodes;
    private int[] tet = new int[4 * 64];
    private int[] tetLine = new int[64];
    private int tets;
    private final Map<String, Integer> skipped = new LinkedHashMap<>();

    TetMeshBuilder(Path file) {
        this.file = file;
    }

    /** Adds node {@code tag} (file units); a tag given twice is refused at {@code line}. */
    void node(int tag, double x, double y, double z, int line) throws MeshFormatException {
        if (indexOfTag.putIfAbsent(tag, nodes) != null) {
            throw MeshFormatException.atLine(file, line, "node " + tag + " is given twice; expected each node tag"
                    + " once");
        }
        if (3 * nodes + 3 > xyz.length) {
            xyz = Arrays.copyOf(xyz, 2 * xyz.length);
        }
        xyz[3 * nodes] = x;
        xyz[3 * nodes + 1] = y;
        xyz[3 * nodes + 2] = z;
        nodes++;
    }

    /** Adds a tetrahedron on four node tags, read at {@code line}. */
    void tet(int a, int b, int c, int d, int line) {
        if (4 * tets + 4 > tet.length) {
            tet = Arrays.copyOf(tet, 2 * tet.length);
            tetLine = Arrays.copyOf(tetLine, tet.length / 4);
        }
        tet[4 * tets] = a;
        tet[4 * tets + 1] = b;
        tet[4 * tets + 2] = c;
        tet[4 * tets + 3] = d;
        tetLine[tets++] = line;
    }

    /** Counts an element of another kind than a 4-node tetrahedron, by a name of its type. */
    void skip(String type) {
        skipped.merge(type, 1, Integer::sum);
    }

    int nodeCount() {
        return nodes;
    }

    /** The mesh of the nodes the tets use, in metres. */
    TetMeshReaders.Result build(MeshUnits units) throws MeshFormatException {
        if (tets == 0) {
            throw new MeshFormatException(file, "end", "no 4-node tetrahedra found" + (skipped.isEmpty() ? ""
                    : " (other elements: " + skipped + ")") + "; expected a volume mesh of linear tetrahedra");
        }
        int[] used = new int[nodes];
        Arrays.fill(used, -1);
        int count = 0;
        int[] idx = new int[4 * tets];
        for (int t = 0; t < tets; t++) {
            for (int k = 0; k < 4; k++) {
                Integer i = indexOfTag.get(tet[4 * t + k]);
                if (i == null) {
                    throw MeshFormatException.atLine(file, tetLine[t], "tet " + t + " refers to node "
                            + tet[4 * t + k] + ", which the file does not define; expected one of its node tags");
                }
                if (used[i] < 0) {
                    used[i] = count++;
                }
                idx[4 * t + k] = used[i];
            }
        }
        double scale = units.metresPerUnit();
        double[] m = new double[3 * count];
        for (int i = 0; i < nodes; i++) {
            if (used[i] >= 0) {
                for (int a = 0; a < 3; a++) {
                    m[3 * used[i] + a] = xyz[3 * i + a] * scale;
                }
            }
        }
        TetMesh probe;
        try {
            probe = new TetMesh(m, idx);
        } catch (IllegalArgumentException e) {
            // find the tet and give its line
            for (int t = 0; t < tets; t++) {
                String bad = shape(m, idx, t, Arrays.copyOfRange(tet, 4 * t, 4 * t + 4));
                if (bad != null) {
                    throw MeshFormatException.atLine(file, tetLine[t], "tet " + t + " " + bad);
                }
            }
            throw new MeshFormatException(file, "end", e.getMessage());
        }
        return new TetMeshReaders.Result(probe, Map.copyOf(skipped), nodes - count);
    }

    /** The shape check of one tet on a mesh of that tet alone (its message, or null when it is usable). */
    private static String shape(double[] m, int[] idx, int t, int[] tags) {
        double[] xyz = new double[12];
        for (int k = 0; k < 4; k++) {
            System.arraycopy(m, 3 * idx[4 * t + k], xyz, 3 * k, 3);
        }
        try {
            new TetMesh(xyz, new int[] {0, 1, 2, 3});
            return null;
        } catch (IllegalArgumentException e) {
            String msg = e.getMessage().replaceFirst("^tet 0 \\(nodes \\[0, 1, 2, 3\\]\\) ", "");
            return "(node tags " + Arrays.toString(tags) + ") " + msg;
        }
    }
}
