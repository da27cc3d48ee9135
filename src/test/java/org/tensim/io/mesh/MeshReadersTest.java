package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The OBJ, STL and OFF readers on small files: the same tetrahedron in each, and broken files. */
class MeshReadersTest {
    @TempDir
    Path dir;

    private static final double[][] TET = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
    private static final int[][] FACES = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, text.getBytes(StandardCharsets.US_ASCII));
        return p;
    }

    private String obj() {
        StringBuilder s = new StringBuilder("# tetrahedron\n");
        for (double[] v : TET) {
            s.append("v ").append(v[0]).append(' ').append(v[1]).append(' ').append(v[2]).append('\n');
        }
        for (int[] f : FACES) {
            s.append("f ").append(f[0] + 1).append("//1 ").append(f[1] + 1).append(' ').append(f[2] + 1).append('\n');
        }
        return s.toString();
    }

    private byte[] binaryStl(int declared, int written) {
        ByteBuffer b = ByteBuffer.allocate(84 + 50 * written).order(ByteOrder.LITTLE_ENDIAN);
        b.position(80);
        b.putInt(declared);
        for (int t = 0; t < written; t++) {
            int[] f = FACES[t % 4];
            b.putFloat(0).putFloat(0).putFloat(0);
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++) {
                    b.putFloat((float) TET[f[k]][a]);
                }
            }
            b.putShort((short) 0);
        }
        return b.array();
    }

    private static void assertTetrahedron(TriangleMesh raw, double scale) {
        MeshCleaner.Result r = MeshCleaner.clean(raw, MeshCleaner.Options.defaults(), "tet");
        assertEquals(4, r.mesh().vertexCount());
        assertEquals(4, r.mesh().triangleCount());
        assertEquals(1, r.report().components());
        assertEquals(0, r.report().boundaryLoops());
        assertEquals(0, r.report().nonManifoldEdges());
        // Total area of the tetrahedron with legs a: 3 a^2 / 2 + sqrt(3) a^2 / 2.
        double a = 10 * scale;
        assertEquals((1.5 + Math.sqrt(3) / 2) * a * a, r.mesh().totalArea(), 1e-9 * a * a);
    }

    @Test
    void theSameTetrahedronIsReadFromEachFormatInMetres() throws Exception {
        assertTetrahedron(MeshReaders.read(write("t.obj", obj()), MeshUnits.MM), 1e-3);
        assertTetrahedron(MeshReaders.read(write("t.obj", obj()), MeshUnits.M), 1);
        StringBuilder off = new StringBuilder("OFF\n# comment\n4 4 6\n");
        for (double[] v : TET) {
            off.append(v[0]).append(' ').append(v[1]).append(' ').append(v[2]).append('\n');
        }
        for (int[] f : FACES) {
            off.append("3 ").append(f[0]).append(' ').append(f[1]).append(' ').append(f[2]).append('\n');
        }
        assertTetrahedron(MeshReaders.read(write("t.off", off.toString()), MeshUnits.MM), 1e-3);
        StringBuilder stl = new StringBuilder("solid tet\n");
        for (int[] f : FACES) {
            stl.append(" facet normal 0 0 0\n  outer loop\n");
            for (int k : f) {
                stl.append("   vertex ").append(TET[k][0]).append(' ').append(TET[k][1]).append(' ')
                        .append(TET[k][2]).append('\n');
            }
            stl.append("  endloop\n endfacet\n");
        }
        stl.append("endsolid tet\n");
        TriangleMesh ascii = MeshReaders.read(write("t.stl", stl.toString()), MeshUnits.MM);
        assertEquals(12, ascii.vertexCount(), "STL stores three corners per triangle");
        assertTetrahedron(ascii, 1e-3);
        Path bin = dir.resolve("b.stl");
        Files.write(bin, binaryStl(4, 4));
        assertTetrahedron(MeshReaders.read(bin, MeshUnits.MM), 1e-3);
    }

    @Test
    void polygonsAreSplitIntoFansAndNegativeIndicesCountBack() throws Exception {
        TriangleMesh m = MeshReaders.read(write("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n"),
                MeshUnits.M);
        assertEquals(2, m.triangleCount());
        assertEquals(1.0, m.totalArea(), 1e-12);
    }

    private static MeshFormatException fails(Path p) {
        return assertThrows(MeshFormatException.class, () -> MeshReaders.read(p, MeshUnits.MM));
    }

    @Test
    void malformedFilesNameTheFileTheLineAndWhatWasExpected() throws Exception {
        MeshFormatException e = fails(write("bad.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n"));
        assertTrue(e.getMessage().contains("bad.obj") && e.getMessage().contains("line 2")
                && e.getMessage().contains("'x' is not a number"), e.getMessage());
        e = fails(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 7\n"));
        assertTrue(e.getMessage().contains("line 5") && e.getMessage().contains("expected 1..3"), e.getMessage());
        e = fails(write("nan.obj", "v 0 0 0\nv NaN 0 0\nv 0 1 0\nf 1 2 3\n"));
        assertTrue(e.getMessage().contains("line 2") && e.getMessage().contains("finite"), e.getMessage());
        e = fails(write("empty.obj", ""));
        assertTrue(e.getMessage().contains("empty.obj") && e.getMessage().contains("no vertex"), e.getMessage());
        e = fails(write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"));
        assertTrue(e.getMessage().contains("line 6") && e.getMessage().contains("expected 0..2"), e.getMessage());
        e = fails(write("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"));
        assertTrue(e.getMessage().contains("end of file after 2 vertices"), e.getMessage());
        e = fails(write("empty.stl", ""));
        assertTrue(e.getMessage().contains("byte 0") && e.getMessage().contains("empty"), e.getMessage());
        e = fails(write("bad.stl", "solid x\n facet normal 0 0 0\n  outer loop\n   vertex 0 0 oops\n"));
        assertTrue(e.getMessage().contains("line 4") && e.getMessage().contains("'oops'"), e.getMessage());
        Path truncated = dir.resolve("trunc.stl");
        byte[] full = binaryStl(4, 4);
        Files.write(truncated, Arrays.copyOf(full, full.length - 30));
        e = fails(truncated);
        assertTrue(e.getMessage().contains("byte 234") && e.getMessage().contains("declares 4 triangles")
                && e.getMessage().contains("triangle 3 is incomplete"), e.getMessage());
        byte[] nan = binaryStl(4, 4);
        ByteBuffer.wrap(nan).order(ByteOrder.LITTLE_ENDIAN).putFloat(84 + 50 + 12 + 4, Float.NaN);
        Path nanStl = dir.resolve("nan.stl");
        Files.write(nanStl, nan);
        e = fails(nanStl);
        assertTrue(e.getMessage().contains("byte 146") && e.getMessage().contains("finite"), e.getMessage());
        e = fails(write("mesh.ply", "ply\n"));
        assertTrue(e.getMessage().contains("expected a file name ending in .obj, .stl or .off"), e.getMessage());
    }

    @Test
    void writtenObjReadsBackTheSameMesh() throws Exception {
        TriangleMesh m = MeshReaders.read(write("t.obj", obj()), MeshUnits.MM);
        Path out = dir.resolve("out/copy.obj");
        ObjWriter.write(out, m, MeshUnits.MM, List.of("copy"), 6);
        TriangleMesh back = MeshReaders.read(out, MeshUnits.MM);
        assertEquals(m.vertexCount(), back.vertexCount());
        for (int v = 0; v < m.vertexCount(); v++) {
            for (int a = 0; a < 3; a++) {
                assertEquals(m.coord(v, a), back.coord(v, a), 1e-12);
            }
        }
        assertEquals(Arrays.toString(m.triangles()), Arrays.toString(back.triangles()));
    }
}
