package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.knowm.xchart.XYChart;

/** Output files: no link followed, errors that say what failed, chart library errors wrapped. */
class OutputFilesTest {
    @TempDir
    Path dir;

    @Test
    void csvWritingRefusesASymbolicLinkAndLeavesItsTargetAlone() throws IOException {
        Path victim = dir.resolve("victim.txt");
        Files.writeString(victim, "precious");
        Path link = dir.resolve("out.csv");
        Files.createSymbolicLink(link, victim);
        IOException e = assertThrows(IOException.class, () -> new CsvWriter(link, List.of("a"), 1));
        assertTrue(e.getMessage().contains("symbolic link") && e.getMessage().contains("out.csv"), e.getMessage());
        assertEquals("precious", Files.readString(victim));
        IOException j = assertThrows(IOException.class, () -> Json.write(link, List.of(1)));
        assertTrue(j.getMessage().contains("symbolic link"), j.getMessage());
        assertEquals("precious", Files.readString(victim));
    }

    @Test
    void fileSystemErrorsSayWhatFailed() throws IOException {
        Path file = dir.resolve("a-file");
        Files.writeString(file, "x");
        IOException e = assertThrows(IOException.class, () -> new CsvWriter(file.resolve("x.csv"), List.of("a"), 1));
        assertTrue(e.getMessage().contains("exists and is a file"), e.getMessage());
        assertEquals("the disk is full (no space left on device)",
                OutputFiles.reason(new FileSystemException("/x", null, "No space left on device")));
        assertEquals("permission denied", OutputFiles.reason(new java.nio.file.AccessDeniedException("/x")));
        assertTrue(OutputFiles.describe("write", Path.of("/x/y.csv"),
                new java.nio.file.AccessDeniedException("/x/y.csv")).getMessage()
                .equals("cannot write /x/y.csv: permission denied"));
    }

    @Test
    void aChartLibraryErrorIsWrappedWithTheChartsName() {
        XYChart c = Charts.lineChart("errors", "x", "y", 300, 200);
        Charts.logLog(c);
        Charts.addLine(c, "bad", new double[] {1, 2}, new double[] {-1, 1}); // log axis, value <= 0
        IOException e = assertThrows(IOException.class, () -> Charts.savePng(c, dir.resolve("c.png")));
        assertTrue(e.getMessage().startsWith("cannot draw the chart 'errors'"), e.getMessage());
    }

    @Test
    void csvFilesEndOnAWholeRowAfterEveryWrite() throws IOException {
        Path p = dir.resolve("r.csv");
        try (CsvWriter w = new CsvWriter(p, List.of("a", "b", "c"), 7)) {
            for (int i = 0; i < 100; i++) {
                w.row(Math.PI * i, -1e-300 * i, 1e300 / (i + 1));
                String text = Files.readString(p);
                assertTrue(text.endsWith("\n"), "after row " + i);
                for (String line : text.split("\n")) {
                    assertEquals(3, line.split(",", -1).length, line);
                }
            }
        }
    }
}
