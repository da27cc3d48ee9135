package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CsvWriterTest {
    @Test
    void rowsAreOnDiskAfterEachFlushEvenBeforeClose(@TempDir Path dir) throws IOException {
        Path p = dir.resolve("sub/a.csv");
        CsvWriter w = new CsvWriter(p, List.of("t", "x"), 2);
        w.row(0, 1.5);
        w.row(1, 2.5);
        List<String> lines = Files.readAllLines(p);
        assertEquals(List.of("t,x", "0.0,1.5", "1.0,2.5"), lines);
        w.close();
    }

    @Test
    void aRowOfTheWrongWidthIsRefused(@TempDir Path dir) throws IOException {
        try (CsvWriter w = new CsvWriter(dir.resolve("b.csv"), List.of("t", "x"), 1)) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> w.row(1, 2, 3));
            assertTrue(e.getMessage().contains("3 values, expected 2"), e.getMessage());
        }
    }
}
