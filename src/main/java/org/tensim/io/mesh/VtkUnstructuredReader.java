package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Reads a legacy VTK file (ASCII) holding an {@code UNSTRUCTURED_GRID}: its {@code POINTS}, {@code CELLS} and
 * {@code CELL_TYPES}, keeping the cells of type VTK_TETRA (10) and counting the others by type. Both layouts of
 * {@code CELLS} are read: the classic one (versions up to 4.2: one {@code n i1 .. in} per cell) and that of version
 * 5.1 ({@code OFFSETS} and {@code CONNECTIVITY} arrays). What follows the cell types ({@code POINT_DATA},
 * {@code CELL_DATA}) is ignored. A BINARY file is refused.
 */
public final class VtkUnstructuredReader {
    /** VTK's cell type of the 4-node tetrahedron. */
    public static final int VTK_TETRA = 10;

    private VtkUnstructuredReader() {
    }

    /** Reads {@code file}, converting coordinates to metres. */
    public static TetMeshReaders.Result read(Path file, MeshUnits units) throws IOException, MeshFormatException {
        TetMeshBuilder b = new TetMeshBuilder(file);
        try (TextTokens in = new TextTokens(file)) {
            String header = in.restOfLine();
            if (header == null || !header.trim().toLowerCase(Locale.ROOT).startsWith("# vtk datafile version")) {
                throw in.error("found '" + (header == null ? "" : header.trim()) + "'; expected the legacy VTK"
                        + " header '# vtk DataFile Version x.x'");
            }
            in.restOfLine(); // the title
            String format = in.need("ASCII or BINARY");
            if (format.equalsIgnoreCase("BINARY")) {
                throw in.error("this is a BINARY VTK file; expected an ASCII one (in ParaView, Save Data with"
                        + " 'File type: ASCII'; meshio: binary=False)");
            }
            if (!format.equalsIgnoreCase("ASCII")) {
                throw in.error("found '" + format + "'; expected ASCII");
            }
            String kw = in.need("DATASET UNSTRUCTURED_GRID");
            String kind = in.need("DATASET UNSTRUCTURED_GRID");
            if (!kw.equalsIgnoreCase("DATASET") || !kind.equalsIgnoreCase("UNSTRUCTURED_GRID")) {
                throw in.error("found '" + kw + " " + kind + "'; expected DATASET UNSTRUCTURED_GRID (a volume mesh)");
            }
            int points = -1;
            int[] offsets = null;
            int[] connectivity = null;
            int[] cellLine = null;
            int cells = -1;
            boolean types = false;
            for (String s = in.next(); s != null; s = in.next()) {
                String key = s.toUpperCase(Locale.ROOT);
                if (key.equals("POINTS")) {
                    points = in.integer("the number of points");
                    in.need("the points' data type");
                    for (int i = 0; i < points; i++) {
                        double x = in.number("point " + i + "'s x coordinate");
                        double y = in.number("point " + i + "'s y coordinate");
                        double z = in.number("point " + i + "'s z coordinate");
                        b.node(i, x, y, z, in.line());
                    }
                } else if (key.equals("CELLS")) {
                    int first = in.integer("the number of cells");
                    int size = in.integer("the size of the cell list");
                    if (first < 0 || size < first) {
                        throw in.error("CELLS " + first + " " + size + "; expected a count >= 0 and a list size at"
                                + " least as large");
                    }
                    String next = in.need("the cells");
                    if (next.equalsIgnoreCase("OFFSETS")) {
                        in.need("the offsets' data type");
                        cells = first - 1;
                        offsets = new int[first];
                        for (int i = 0; i < first; i++) {
                            offsets[i] = in.integer("offset " + i);
                            if (i == 0 ? offsets[i] != 0 : offsets[i] < offsets[i - 1] || offsets[i] > size) {
                                throw in.error("offset " + i + " is " + offsets[i] + "; expected offsets from 0,"
                                        + " non-decreasing, up to the connectivity's size " + size);
                            }
                        }
                        if (first < 1 || offsets[first - 1] != size) {
                            throw in.error("the offsets end at " + (first < 1 ? "nothing" : offsets[first - 1])
                                    + "; expected the connectivity's size " + size);
                        }
                        String c = in.need("CONNECTIVITY");
                        if (!c.equalsIgnoreCase("CONNECTIVITY")) {
                            throw in.error("found '" + c + "'; expected CONNECTIVITY after the offsets");
                        }
                        in.need("the connectivity's data type");
                        connectivity = new int[size];
                        cellLine = new int[Math.max(cells, 0)];
                        int cell = 0;
                        for (int i = 0; i < size; i++) {
                            connectivity[i] = in.integer("connectivity entry " + i);
                            while (cell < cells && offsets[cell] == i) {
                                cellLine[cell++] = in.line();
                            }
                        }
                    } else {
                        cells = first;
                        offsets = new int[cells + 1];
                        connectivity = new int[size - cells];
                        cellLine = new int[cells];
                        int at = 0;
                        for (int i = 0; i < cells; i++) {
                            String countToken = i == 0 ? next : in.need("cell " + i);
                            int n;
                            try {
                                n = Integer.parseInt(countToken);
                            } catch (NumberFormatException e) {
                                throw in.error("'" + countToken + "' is not a whole number; expected cell " + i
                                        + "'s number of points");
                            }
                            cellLine[i] = in.line();
                            if (n < 1 || at + n > connectivity.length) {
                                throw in.error("cell " + i + " has " + n + " points, past the list size " + size
                                        + " given after CELLS; expected 'n i1 .. in' within it");
                            }
                            offsets[i] = at;
                            for (int k = 0; k < n; k++) {
                                connectivity[at++] = in.integer("cell " + i + "'s point index");
                            }
                        }
                        offsets[cells] = at;
                    }
                } else if (key.equals("CELL_TYPES")) {
                    if (offsets == null) {
                        throw in.error("CELL_TYPES before CELLS; expected CELLS first");
                    }
                    int n = in.integer("the number of cell types");
                    if (n != cells) {
                        throw in.error("CELL_TYPES lists " + n + " cells; expected " + cells + ", as CELLS does");
                    }
                    for (int i = 0; i < n; i++) {
                        int type = in.integer("cell " + i + "'s type");
                        int from = offsets[i];
                        int count = offsets[i + 1] - from;
                        if (type != VTK_TETRA) {
                            b.skip("VTK type " + type);
                        } else if (count != 4) {
                            throw MeshFormatException.atLine(file, cellLine[i], "cell " + i + " is a VTK_TETRA (10)"
                                    + " with " + count + " points; expected 4");
                        } else {
                            b.tet(connectivity[from], connectivity[from + 1], connectivity[from + 2],
                                    connectivity[from + 3], cellLine[i]);
                        }
                    }
                    types = true;
                    break;
                } else if (points < 0) {
                    throw in.error("found '" + s + "'; expected POINTS, CELLS and CELL_TYPES");
                } else {
                    throw in.error("found '" + s + "' before CELL_TYPES; expected CELLS and CELL_TYPES");
                }
            }
            if (points < 0 || offsets == null || !types) {
                throw in.error("end of file without " + (points < 0 ? "POINTS" : offsets == null ? "CELLS"
                        : "CELL_TYPES") + "; expected POINTS, CELLS and CELL_TYPES");
            }
        }
        return b.build(units);
    }
}
