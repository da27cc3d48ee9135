package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A run folder is used only by the command whose results it holds, unless the user asks to overwrite. */
class FolderClaimTest {
    @TempDir
    Path dir;

    /** The folder's entries, names and contents, to show that a refusal changed nothing. */
    private static Map<String, String> contents(Path d) throws Exception {
        Map<String, String> m = new java.util.TreeMap<>();
        try (var s = Files.walk(d)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                m.put(d.relativize(p).toString(), Files.isRegularFile(p) ? Files.readString(p) : "<dir>");
            }
        }
        return m;
    }

    private static void finished(Path out, String command, String file) throws Exception {
        RunFolder.run(out, command, List.of(file), run -> {
            Files.writeString(run.file(file), "13 minutes of RK2");
            run.finish(RunStatus.OK, Map.of());
        });
    }

    @Test
    void anotherCommandsFolderIsRefusedNamingItAndTheWaysOnAndNothingIsRemoved() throws Exception {
        Path out = dir.resolve("diaphragm");
        finished(out, "diaphragm", "probe.csv");
        Map<String, String> before = contents(out);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunFolder.open(out, "diaphragm resolution-study", List.of("resolution.csv")));
        String m = e.getMessage();
        assertTrue(m.contains(out.toString()) && m.contains("`tensim diaphragm`") && m.contains("--out")
                && m.contains("--overwrite"), m);
        assertEquals(before, contents(out), "the refused run changed nothing");

        RunFolder.run(out, "diaphragm resolution-study", List.of("resolution.csv"), true, run -> {
            Files.writeString(run.file("resolution.csv"), "rings\n");
            run.finish(RunStatus.OK, Map.of());
        });
        assertEquals("diaphragm resolution-study", Json.readMap(out.resolve(RunFolder.SUMMARY)).get("command"),
                "--overwrite proceeds");
        assertTrue(Files.exists(out.resolve("resolution.csv")));
    }

    @Test
    void theSameCommandReplacesItsOwnRunWhateverItsStatus() throws Exception {
        Path out = dir.resolve("cube");
        RunFolder.run(out, "cube", List.of(), run -> {
            Files.writeString(run.file("old.csv"), "x");
            run.finish(RunStatus.INTERRUPTED, Map.of());
        });
        RunFolder.run(out, "cube", List.of(), run -> {
            Files.writeString(run.file("new.csv"), "y");
            run.finish(RunStatus.OK, Map.of());
        });
        assertTrue(Files.exists(out.resolve("new.csv")));
        assertTrue(Files.notExists(out.resolve("old.csv")), "the previous run's outputs are replaced");
    }

    @Test
    void aKilledRunBelongsToTheCommandItsManifestNames() throws Exception {
        Path out = dir.resolve("k");
        RunFolder killed = RunFolder.open(out, "stability", List.of());
        Files.writeString(killed.file("stability.csv"), "omega\n");
        RunSignals.deactivate(killed); // no summary: as after SIGKILL
        assertTrue(Files.notExists(out.resolve(RunFolder.SUMMARY)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunFolder.open(out, "accuracy", List.of()));
        assertTrue(e.getMessage().contains("unfinished run of `tensim stability`"), e.getMessage());
        assertTrue(Files.exists(out.resolve("stability.csv")));
        RunFolder.run(out, "stability", List.of(), run -> run.finish(RunStatus.OK, Map.of()));
        assertTrue(Files.notExists(out.resolve("stability.csv")), "its own command clears the killed run");
    }

    @Test
    void filesNoTensimRunWroteAreRefusedAndAnEmptyOrOwnFolderIsNot() throws Exception {
        Path theirs = dir.resolve("theirs");
        Files.createDirectories(theirs);
        Files.writeString(theirs.resolve("thesis.tex"), "years of work");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> FolderClaim.check(theirs, "cube", List.of("cube.csv"), false));
        assertTrue(e.getMessage().contains("files that no tensim run wrote (thesis.tex)"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> RunFolder.open(theirs, "cube", List.of("cube.csv")));
        assertEquals("years of work", Files.readString(theirs.resolve("thesis.tex")));

        Path empty = dir.resolve("empty");
        Files.createDirectories(empty);
        FolderClaim.check(empty, "cube", List.of(), false);
        FolderClaim.check(dir.resolve("not-yet"), "cube", List.of(), false);
        // A folder of a command that writes no summary (a sweep) is known by its own names.
        Path sweep = dir.resolve("sweep");
        Files.createDirectories(sweep.resolve("charts"));
        Files.writeString(sweep.resolve("results.csv"), "a\n");
        FolderClaim.check(sweep, "sweep", List.of("results.csv", "charts", "sweep.json"), false);
        assertThrows(IllegalArgumentException.class, () -> FolderClaim.check(sweep, "calibrate",
                List.of("history.csv"), false));
    }

    @Test
    void aSummaryThatNamesNoCommandIsNotTakenForOurs() throws Exception {
        Path out = dir.resolve("s");
        Files.createDirectories(out);
        Files.writeString(out.resolve(RunFolder.SUMMARY), "{\"status\": \"ok\"}");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RunFolder.open(out, "cube", List.of()));
        assertTrue(e.getMessage().contains("names no tensim command"), e.getMessage());
        assertTrue(Files.exists(out.resolve(RunFolder.SUMMARY)));
    }
}
