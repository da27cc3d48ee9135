package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Gmsh (2.2, 4.1) and legacy VTK (4.2, 5.1) readers on the same hand-written cube of five tets (10 mm, with a
 * node no tet uses and a few lower elements to skip), and broken copies of it.
 */
class TetMeshReadersTest {
    @TempDir
    Path dir;

    private static Path fixture(String name) throws URISyntaxException {
        return Path.of(TetMeshReadersTest.class.getResource(name).toURI());
    }

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, text.getBytes(StandardCharsets.US_ASCII));
        return p;
    }

    private static String text(String name) throws IOException, URISyntaxException {
        return Files.readString(fixture(name), StandardCharsets.US_ASCII);
    }

    private MeshFormatException refused(String name, String text) throws IOException {
        Path p = write(name, text);
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> TetMeshReaders.read(p, MeshUnits.MM));
        System.out.println(e.getMessage());
        assertTrue(e.getMessage().startsWith(p.toString()), "names the file: " + e.getMessage());
        return e;
    }

    @Test
    void everyFormatReadsTheSameCubeOfFiveTets() throws Exception {
        TetMeshReaders.Result first = null;
        for (String name : new String[] {"cube5.msh", "cube5-v41.msh", "cube5.vtk", "cube5-v51.vtk"}) {
            TetMeshReaders.Result r = TetMeshReaders.read(fixture(name), MeshUnits.MM);
            TetMesh m = r.mesh();
            assertEquals(8, m.nodeCount(), name);
            assertEquals(5, m.tetCount(), name);
            assertEquals(1, r.unusedNodes(), name + ": the apex node no tet uses is dropped");
            assertEquals(1e-6, m.totalVolume(), 1e-18, name + ": a 10 mm cube, in m^3");
            assertEquals(1e-6 / 3, m.volume(0), 1e-18, name + ": the middle tet is a third of the cube");
            TriangleMesh b = m.boundary();
            assertEquals(12, b.triangleCount(), name + ": two triangles a cube face");
            assertEquals(8, b.vertexCount(), name);
            assertEquals(0, b.boundaryEdgeCount(), name + ": the boundary is closed");
            assertEquals(1e-6, b.signedVolume(), 1e-18, name + ": the boundary faces outwards");
            for (int i = 0; i < b.vertexCount(); i++) {
                for (int a = 0; a < 3; a++) {
                    assertEquals(m.coord(m.boundaryNode(i), a), b.coord(i, a), 0, name);
                }
            }
            if (first == null) {
                first = r;
                assertEquals(Map.of("type 15", 1, "type 2", 2), r.skipped(), name);
            } else {
                assertArrayEquals(first.mesh().coordinates(), m.coordinates(), 1e-15, name);
                assertArrayEquals(first.mesh().tets(), m.tets(), name);
            }
        }
        assertEquals(Map.of("VTK type 5", 1), TetMeshReaders.read(fixture("cube5.vtk"), MeshUnits.MM).skipped());
        assertEquals(10, TetMeshReaders.read(fixture("cube5.msh"), MeshUnits.M).mesh().coord(0, 0), 0,
                "metres are kept as they are (node 0 is the first tet's first, Gmsh's node 2)");
    }

    @Test
    void aBinaryFileIsRefusedWithTheWayToWriteAnAsciiOne() throws Exception {
        MeshFormatException e = refused("bin.msh", text("cube5.msh").replace("2.2 0 8", "2.2 1 8"));
        assertEquals("line 2", e.location());
        assertTrue(e.getMessage().contains("binary"), e.getMessage());
        String vtk = text("cube5.vtk").replace("ASCII", "BINARY");
        MeshFormatException v = refused("bin.vtk", vtk);
        assertEquals("line 3", v.location());
        assertTrue(v.getMessage().contains("BINARY"), v.getMessage());
        MeshFormatException old = refused("old.msh", text("cube5.msh").replace("2.2 0 8", "3.0 0 8"));
        assertTrue(old.getMessage().contains("expected 2.2 or 4.1"), old.getMessage());
    }

    @Test
    void aTetWithTheWrongNumberOfNodesIsRefusedAtItsLine() throws Exception {
        MeshFormatException e = refused("short.msh", text("cube5.msh").replace("4 4 2 1 1 2 3 5 8",
                "4 4 2 1 1 2 3 5"));
        assertEquals("line 25", e.location());
        assertTrue(e.getMessage().contains("lists 3 nodes; expected 4"), e.getMessage());
        MeshFormatException v = refused("short.vtk", text("cube5.vtk").replace("CELLS 6 29\n4 1 2 4 7",
                "CELLS 6 28\n3 1 2 4"));
        assertEquals("line 10", v.location());
        assertTrue(v.getMessage().contains("with 3 points; expected 4"), v.getMessage());
        MeshFormatException offsets = refused("offsets.vtk", text("cube5-v51.vtk").replace("20 23", "20 30"));
        assertEquals("line 11", offsets.location());
        assertTrue(offsets.getMessage().contains("offset 6 is 30"), offsets.getMessage());
        MeshFormatException unknown = refused("unknown.msh", text("cube5.msh").replace("1 2 3 5\n", "1 2 3 42\n"));
        assertEquals("line 26", unknown.location());
        assertTrue(unknown.getMessage().contains("tet 1 refers to node 42"), unknown.getMessage());
    }

    @Test
    void aMissingSectionIsRefused() throws Exception {
        String msh = text("cube5.msh");
        String noElements = msh.substring(0, msh.indexOf("$Elements"));
        assertTrue(refused("nodes-only.msh", noElements).getMessage().contains("without a $Elements section"));
        assertTrue(refused("no-format.msh", msh.substring(msh.indexOf("$Nodes"))).getMessage()
                .contains("before $MeshFormat"));
        assertTrue(refused("unclosed.msh", msh.replace("$EndNodes", "")).getMessage().contains("$EndNodes"));
        String vtk = text("cube5.vtk");
        assertTrue(refused("no-types.vtk", vtk.substring(0, vtk.indexOf("CELL_TYPES"))).getMessage()
                .contains("without CELL_TYPES"));
        assertTrue(refused("polydata.vtk", vtk.replace("UNSTRUCTURED_GRID", "POLYDATA")).getMessage()
                .contains("expected DATASET UNSTRUCTURED_GRID"));
        MeshFormatException triangles = refused("surface.msh", msh.replaceAll("\n\\d+ 4 2 1 1 [0-9 ]+", "")
                .replace("$Elements\n8\n", "$Elements\n3\n"));
        assertTrue(triangles.getMessage().contains("no 4-node tetrahedra found"), triangles.getMessage());
    }

    @Test
    void anInvertedOrDegenerateTetIsRefusedWithItsIndexAndLine() throws Exception {
        String msh = text("cube5.msh");
        MeshFormatException e = refused("inverted.msh", msh.replace("7 4 2 1 1 6 2 5 8", "7 4 2 1 1 2 6 5 8"));
        assertEquals("line 28", e.location());
        assertTrue(e.getMessage().contains("tet 3 (node tags [2, 6, 5, 8]) is inverted"), e.getMessage());
        MeshFormatException flat = refused("flat.msh", msh.replace("5 4 2 1 1 1 2 3 5", "5 4 2 1 1 1 2 3 4"));
        assertEquals("line 26", flat.location());
        assertTrue(flat.getMessage().contains("tet 1 (node tags [1, 2, 3, 4]) is degenerate"), flat.getMessage());
        MeshFormatException v = refused("inverted.vtk", text("cube5.vtk").replace("4 5 1 4 7", "4 1 5 4 7"));
        assertEquals("line 13", v.location());
        assertTrue(v.getMessage().contains("tet 3") && v.getMessage().contains("inverted"), v.getMessage());
        assertTrue(refused("cube.tet", "").getMessage().contains("expected a file name ending in .msh"));
    }
}
