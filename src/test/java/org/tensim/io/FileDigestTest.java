package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The digest names contents: the same files give the same digest, an edit in place of the same size another. */
class FileDigestTest {
    @TempDir
    Path dir;

    @Test
    void anEditOfTheSameSizeChangesTheDigest() throws Exception {
        Path mesh = dir.resolve("mesh.obj");
        Path parts = dir.resolve("thorax");
        Files.createDirectories(parts.resolve("ribs"));
        Files.writeString(mesh, "v 0 0 0\n");
        Files.writeString(parts.resolve("parts.json"), "{}");
        Files.writeString(parts.resolve("ribs").resolve("r1.obj"), "v 1 2 3\n");
        String first = FileDigest.of(List.of(mesh, parts));
        assertEquals(64, first.length());
        assertEquals(first, FileDigest.of(List.of(mesh, parts)), "the same contents");
        Files.writeString(parts.resolve("ribs").resolve("r1.obj"), "v 1 2 4\n");
        String edited = FileDigest.of(List.of(mesh, parts));
        assertNotEquals(first, edited, "one byte of a part changed");
        Files.writeString(mesh, "v 0 0 1\n");
        assertNotEquals(edited, FileDigest.of(List.of(mesh, parts)), "one byte of the mesh changed");
        assertNotEquals(FileDigest.of(List.of(mesh, parts)), FileDigest.of(List.of(parts, mesh)), "order counts");
    }
}
