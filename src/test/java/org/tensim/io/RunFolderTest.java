package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The run folder: only this run's outputs, and a summary that says how the run ended. */
class RunFolderTest {
    @TempDir
    Path dir;

    private static void write(Path p, String text) throws IOException {
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
    }

    @Test
    void aFailedReRunLeavesNoFileOfThePreviousRun() throws Exception {
        Path out = dir.resolve("o");
        RunFolder.run(out, "t", List.of("a.csv"), run -> {
            try (CsvWriter w = run.csv("a.csv", List.of("x"), 1)) {
                w.row(1);
            }
            write(run.file("frames").resolve("f0.vtk"), "old frame");
            write(run.file("old-only.png"), "png");
            run.finish(RunStatus.OK, Map.of("steps", 4000));
        });
        write(out.resolve("notes.txt"), "the user's own file");
        assertEquals("ok", Json.readMap(out.resolve("summary.json")).get("status"));

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> RunFolder.run(out, "t",
                List.of("a.csv"), run -> {
                    try (CsvWriter w = run.csv("a.csv", List.of("x"), 1)) {
                        w.row(2);
                    }
                    throw new IllegalStateException("boom at step 3");
                }));
        assertEquals("boom at step 3", e.getMessage());
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("failed", s.get("status"));
        assertEquals("boom at step 3", s.get("error"));
        assertEquals(List.of("a.csv"), s.get("files"));
        assertFalse(s.containsKey("steps"), "nothing of the old summary");
        assertFalse(Files.exists(out.resolve("frames")), "the old run's folder of frames is gone");
        assertFalse(Files.exists(out.resolve("old-only.png")), "the old run's chart is gone");
        assertEquals(List.of("x", "2.0"), Files.readAllLines(out.resolve("a.csv")));
        assertTrue(Files.exists(out.resolve("notes.txt")), "files no run wrote are left alone");
    }

    @Test
    void aKilledRunsFilesAreRemovedByTheNextRunThroughItsManifest() throws Exception {
        Path out = dir.resolve("o");
        RunFolder killed = RunFolder.open(out, "t", List.of());
        write(killed.file("half.csv"), "t_s\n0.1\n");
        // no finish: as after SIGKILL. A temporary file of an atomic write is left too.
        write(out.resolve(".chart.png123.tmp"), "partial");
        RunSignals.deactivate(killed);
        assertFalse(Files.exists(out.resolve("summary.json")), "a killed run leaves no summary");
        RunFolder.run(out, "t", List.of(), run -> run.finish(RunStatus.OK, Map.of()));
        assertFalse(Files.exists(out.resolve("half.csv")));
        assertFalse(Files.exists(out.resolve(".chart.png123.tmp")));
    }

    @Test
    void theInterruptedStatusIsWrittenOnceAndTheCsvEndsOnAWholeRow() throws Exception {
        Path out = dir.resolve("o");
        RunFolder run = RunFolder.open(out, "t", List.of());
        CsvWriter w = run.csv("rows.csv", List.of("a", "b"), 1000);
        w.row(1, 2);
        w.row(3, 4);
        assertEquals(RunStatus.INTERRUPTED, run.interruptIfUnfinished());
        assertEquals(List.of("a,b", "1.0,2.0", "3.0,4.0"), Files.readAllLines(out.resolve("rows.csv")),
                "the rows kept in memory are written, whole, when the signal closes the file");
        assertThrows(IOException.class, () -> w.row(5, 6), "the loop learns that the run was interrupted");
        run.finish(RunStatus.OK, Map.of());
        assertEquals("interrupted", Json.readMap(out.resolve("summary.json")).get("status"),
                "the run's own end does not overwrite the signal's status");
    }

    @Test
    void outputsAreMode0644AndNamesStayInsideTheFolder() throws Exception {
        Path out = dir.resolve("o");
        RunFolder.run(out, "t", List.of(), run -> {
            try (CsvWriter w = run.csv("a.csv", List.of("x"), 1)) {
                w.row(1);
            }
            Json.write(run.file("b.json"), Map.of("k", 1));
            assertThrows(IllegalArgumentException.class, () -> run.file("../escape.txt"));
            run.finish(RunStatus.OK, Map.of());
        });
        for (String f : List.of("a.csv", "b.json", "summary.json")) {
            assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(out.resolve(f))),
                    f);
        }
    }

    @Test
    void anEmptyOrFileOutIsRefusedWithWhatIsWrong() throws Exception {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunFolder.open(Path.of(""), "t", List.of()));
        assertTrue(e.getMessage().contains("--out must name a folder"), e.getMessage());
        Path file = dir.resolve("file");
        Files.writeString(file, "x");
        IOException f = assertThrows(IOException.class, () -> RunFolder.open(file, "t", List.of()));
        assertTrue(f.getMessage().contains("exists and is a file"), f.getMessage());
    }
}
