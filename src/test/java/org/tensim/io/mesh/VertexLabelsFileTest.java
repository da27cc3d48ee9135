package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The per-vertex labels file ({@link VertexLabelsFile}, {@link VertexLabel}): round trip and refusals. */
class VertexLabelsFileTest {
    @TempDir
    Path dir;

    @Test
    void randomLabelsSurviveAWriteAndARead() throws Exception {
        SplittableRandom r = new SplittableRandom(20261201L);
        VertexLabel[] all = VertexLabel.values();
        for (int n : new int[] {1, 7, 1000}) {
            VertexLabel[] labels = new VertexLabel[n];
            for (int v = 0; v < n; v++) {
                labels[v] = all[r.nextInt(all.length)];
            }
            Path f = dir.resolve("labels-" + n + ".txt");
            VertexLabelsFile.write(f, labels);
            assertArrayEquals(labels, VertexLabelsFile.read(f, n), n + " vertices");
        }
    }

    @Test
    void linesInAnyOrderWithCommentsAndBlankLinesAreRead() throws Exception {
        Path f = file("# made by hand", "tensim-labels 1 vertices=3", "", "2 origin-lumbar", "# middle",
                "0 tendon", "1   muscle  ");
        assertArrayEquals(new VertexLabel[] {VertexLabel.TENDON, VertexLabel.MUSCLE, VertexLabel.ORIGIN_LUMBAR},
                VertexLabelsFile.read(f, 3));
    }

    @Test
    void everyLabelHasItsFileNameAndParsesBack() {
        for (VertexLabel l : VertexLabel.values()) {
            assertEquals(l, VertexLabel.parse(l.fileName()));
            assertTrue(l.fileName().matches("[a-z]+(-[a-z]+)*"), l.fileName());
        }
        assertEquals("origin-sternal", VertexLabel.ORIGIN_STERNAL.fileName());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> VertexLabel.parse("Tendon"));
        assertTrue(e.getMessage().contains("'Tendon'"), e.getMessage());
        for (VertexLabel l : VertexLabel.values()) {
            assertTrue(e.getMessage().contains(l.fileName()), "lists " + l.fileName() + ": " + e.getMessage());
        }
    }

    @Test
    void aMissingVertexIsRefusedNamingItAtTheEnd() throws Exception {
        MeshFormatException e = refused(3, "tensim-labels 1 vertices=3", "0 muscle", "2 tendon");
        assertEquals("line 3", e.location());
        assertTrue(e.getMessage().contains("vertex 1") && e.getMessage().contains("1 of 3"), e.getMessage());
    }

    @Test
    void aDuplicateIndexIsRefusedNamingBothLines() throws Exception {
        MeshFormatException e = refused(2, "tensim-labels 1 vertices=2", "0 muscle", "1 tendon", "0 tendon");
        assertEquals("line 4", e.location());
        assertTrue(e.getMessage().contains("'0 tendon'") && e.getMessage().contains("line 2"), e.getMessage());
    }

    @Test
    void anIndexOutOfRangeIsRefused() throws Exception {
        for (String bad : List.of("2 muscle", "-1 muscle")) {
            MeshFormatException e = refused(2, "# c", "tensim-labels 1 vertices=2", "0 muscle", bad);
            assertEquals("line 4", e.location(), bad);
            assertTrue(e.getMessage().contains("'" + bad + "'") && e.getMessage().contains("0..1"), e.getMessage());
        }
    }

    @Test
    void anUnknownLabelIsRefusedListingTheKnownOnes() throws Exception {
        MeshFormatException e = refused(2, "tensim-labels 1 vertices=2", "0 muscle", "1 ligament");
        assertEquals("line 3", e.location());
        assertTrue(e.getMessage().contains("'ligament'") && e.getMessage().contains(VertexLabel.knownNames()),
                e.getMessage());
    }

    @Test
    void aLabelFileForAnotherMeshIsRefusedAtItsHeader() throws Exception {
        MeshFormatException e = refused(5, "# for the coarse mesh", "tensim-labels 1 vertices=4", "0 muscle");
        assertEquals("line 2", e.location());
        assertTrue(e.getMessage().contains("4 vertices") && e.getMessage().contains("has 5"), e.getMessage());
        assertTrue(e.getMessage().startsWith(dir.toString()), "names the file: " + e.getMessage());
    }

    @Test
    void malformedLinesAreRefusedNamingTheLineAndTheText() throws Exception {
        String[][] cases = {
            {"0 muscle extra", "expected 'index label'"},
            {"0", "expected 'index label'"},
            {"x muscle", "'x' is not a whole number"},
            {"1.5 muscle", "'1.5' is not a whole number"},
        };
        for (String[] c : cases) {
            MeshFormatException e = refused(2, "tensim-labels 1 vertices=2", "1 tendon", c[0]);
            assertEquals("line 3", e.location(), c[0]);
            assertTrue(e.getMessage().contains(c[1]) && e.getMessage().contains(c[0]), e.getMessage());
        }
    }

    @Test
    void aMissingOrMalformedHeaderIsRefused() throws Exception {
        String[][] cases = {
            {"0 muscle", "not a labels header"},
            {"tensim-labels 1", "malformed header"},
            {"tensim-labels 2 vertices=1", "version '2'"},
            {"tensim-labels 1 vertices=one", "'one' is not a whole number"},
        };
        for (String[] c : cases) {
            MeshFormatException e = refused(1, "# comment", c[0], "0 muscle");
            assertEquals("line 2", e.location(), c[0]);
            assertTrue(e.getMessage().contains(c[1]) && e.getMessage().contains("tensim-labels 1 vertices=1"),
                    e.getMessage());
        }
        MeshFormatException e = refused(1, "# only a comment");
        assertTrue(e.getMessage().contains("without the header"), e.getMessage());
    }

    @Test
    void writingAVertexWithoutALabelIsRefused() {
        VertexLabel[] labels = {VertexLabel.MUSCLE, null};
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> VertexLabelsFile.write(dir.resolve("x.txt"), labels));
        assertTrue(e.getMessage().contains("vertex 1 of 2"), e.getMessage());
    }

    private MeshFormatException refused(int vertices, String... lines) throws Exception {
        Path f = file(lines);
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> VertexLabelsFile.read(f, vertices));
        assertEquals(f, e.file());
        return e;
    }

    private Path file(String... lines) throws Exception {
        Path f = Files.createTempFile(dir, "labels", ".txt");
        Files.write(f, List.of(lines), StandardCharsets.US_ASCII);
        return f;
    }
}
