package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.RandomCases;
import org.tensim.io.Json;

/**
 * The real program in its own process: output folders after re-runs, failures and
 * signals, exit codes against the summary's status, and the messages a user sees.
 * A few random kills here; the 20-per-command soak is {@link RandomKillSoakTest}.
 */
@Tag("process")
class ProcessLevelTest {
    @TempDir
    Path dir;

    private static Map<String, String> env() {
        Map<String, String> e = new HashMap<>();
        e.put("TENSIM_PROGRESS", "none");
        return e;
    }

    private static Map<String, Object> summary(Path out) throws Exception {
        return Json.readMap(out.resolve("summary.json"));
    }

    @Test
    void aFailingReRunOverAnOldFolderLeavesNothingOfTheOldRun() throws Exception {
        Path o = dir.resolve("o");
        RunProcess ok = RunProcess.start(dir, env(), "cube", "--duration", "0.5", "--out", o.toString());
        assertEquals(0, ok.waitFor(120), ok.err());
        assertEquals("ok", summary(o).get("status"));
        assertEquals(502, Files.readAllLines(o.resolve("cube.csv")).size());
        RunProcess bad = RunProcess.start(dir, env(), "cube", "--force", "1e300", "--out", o.toString());
        int code = bad.waitFor(120);
        assertEquals(1, code, bad.err());
        Map<String, Object> s = summary(o);
        assertEquals("diverged", s.get("status"));
        assertEquals(0, ((Number) s.get("steps")).intValue(), "the new summary, not the old one's 500 steps");
        assertTrue(Files.readAllLines(o.resolve("cube.csv")).size() < 10, "the new, short CSV");
        assertEquals(List.of(), FolderCheck.problems(o, code, null));
        assertEquals(1, bad.err().strip().split("\n").length, "one line: " + bad.err());
    }

    @Test
    void exitCodesFollowTheSummarysStatus() throws Exception {
        Path usage = dir.resolve("usage");
        RunProcess u = RunProcess.start(dir, env(), "cube", "--dt", "10", "--out", usage.toString());
        assertEquals(2, u.waitFor(60), u.err());
        assertTrue(u.err().contains("--dt 10.0 s is longer than the run"), u.err());
        assertFalse(Files.exists(usage), "a refused command line writes nothing");

        Path failed = dir.resolve("failed");
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
        RunProcess f = RunProcess.start(dir, env(), "diaphragm", "--mesh", bad.toString(), "--out", failed.toString());
        assertEquals(1, f.waitFor(120), f.err());
        assertEquals("failed", summary(failed).get("status"));
        assertTrue(summary(failed).get("error").toString().contains("bad.obj, line 4"));
        assertEquals(List.of(), FolderCheck.problems(failed, 1, null));

        Path wrongUnits = dir.resolve("units");
        Path metres = dir.resolve("dome-m.obj");
        RunProcess mesh = RunProcess.start(dir, env(), "diaphragm-mesh", "--rings", "6", "--out", metres.toString());
        assertEquals(0, mesh.waitFor(60), mesh.err());
        // The mesh is in mm: read as metres it is 280 m across.
        RunProcess w = RunProcess.start(dir, env(), "diaphragm", "--mesh", metres.toString(), "--units", "m",
                "--out", wrongUnits.toString());
        assertEquals(1, w.waitFor(120), w.err());
        assertTrue(w.err().contains("dome-m.obj") && w.err().contains("use --units mm"), w.err());
        assertFalse(w.err().contains("internal error") || w.err().contains("\tat "), w.err());
    }

    /** A few random kills of a long cube run: whatever the moment and the signal, the folder is sound. */
    @Test
    void killedAtRandomMomentsTheFolderIsCompleteOrMarked() throws Exception {
        RandomCases.check("random kills", 3, r -> killAndCheck(dir, r, "cube", "--duration", "4000"));
    }

    /** Starts the command, sends a random signal after a random delay, checks the folder; returns the signal. */
    static String killAndCheck(Path dir, SplittableRandom r, String... args) throws Exception {
        Path o = Files.createTempDirectory(dir, "kill");
        // An old run of the same command first (the folder is its own): none of its files may survive.
        String command = String.join(" ", java.util.Arrays.stream(args).takeWhile(a -> !a.startsWith("-"))
                .toList());
        Files.writeString(o.resolve("summary.json"), "{\"status\":\"ok\",\"command\":\"" + command
                + "\",\"steps\":4000}");
        Files.writeString(o.resolve(".tensim-files"), "#command " + command + "\nold.csv\n");
        Files.writeString(o.resolve("old.csv"), "t_s\n1\n");
        String[] full = java.util.Arrays.copyOf(args, args.length + 2);
        full[args.length] = "--out";
        full[args.length + 1] = o.toString();
        RunProcess p = RunProcess.start(dir, env(), full);
        long delayMs = 300 + r.nextInt(4000);
        String signal = RandomCases.oneOf(r, "INT", "TERM", "KILL");
        boolean ended = p.process.waitFor(delayMs, java.util.concurrent.TimeUnit.MILLISECONDS);
        if (!ended) {
            signal = p.signal(signal);
        }
        int code = p.waitFor(120);
        String what = String.join(" ", args) + ", " + (ended ? "ended by itself" : "SIG" + signal) + " after "
                + delayMs + " ms, exit " + code + ": ";
        if (!ended && Files.exists(o.resolve("old.csv")) && Files.exists(o.resolve("summary.json"))
                && Json.readMap(o.resolve("summary.json")).get("steps") instanceof Number n && n.intValue() == 4000) {
            // Stopped before the program reached its folder (during the JVM's start): the old run's
            // files are all there, untouched and consistent, and the exit code says it was a signal.
            assertTrue(code == 130 || code == 143 || code == 137, what + "a signal's exit code");
            assertEquals(List.of("#command " + command, "old.csv"), Files.readAllLines(o.resolve(".tensim-files")),
                    what);
            return "SIG" + signal + " before start";
        }
        List<String> problems = FolderCheck.problems(o, code, ended ? null : signal);
        assertEquals(List.of(), problems, what + p.err());
        assertFalse(Files.exists(o.resolve("old.csv")), what + "the old run's file is gone");
        if (Files.exists(o.resolve("summary.json"))) {
            assertFalse(Json.readMap(o.resolve("summary.json")).get("steps") instanceof Number n
                    && n.intValue() == 4000, what + "not the old summary");
        }
        if (!ended && !signal.equals("KILL") && code == 130) {
            assertEquals("interrupted", Json.readMap(o.resolve("summary.json")).get("status"), what);
        }
        return ended ? "none" : "SIG" + signal + (code == 130 ? " (interrupted)" : code == 137 ? " (killed)"
                : " (exit " + code + ")");
    }

    @Test
    void csvWritingDoesNotFollowASymlinkInTheFolder() throws Exception {
        Path o = dir.resolve("o");
        Files.createDirectories(o);
        Path victim = dir.resolve("victim.txt");
        Files.writeString(victim, "precious");
        Files.createSymbolicLink(o.resolve("cube.csv"), victim);
        RunProcess p = RunProcess.start(dir, env(), "cube", "--duration", "0.1", "--out", o.toString());
        assertEquals(0, p.waitFor(120), p.err());
        assertEquals("precious", Files.readString(victim));
        assertFalse(Files.isSymbolicLink(o.resolve("cube.csv")));
    }

    @Test
    void diaphragmMeshWritesUnderOutNeverOverTheCommittedMesh() throws Exception {
        Path committed = RunProcess.HOME.resolve("meshes/diaphragm-default.obj");
        long before = Files.exists(committed) ? Files.getLastModifiedTime(committed).toMillis() : -1;
        RunProcess p = RunProcess.start(dir, env(), "diaphragm-mesh", "--rings", "6");
        assertEquals(0, p.waitFor(60), p.err());
        Path written = dir.resolve("out/diaphragm-mesh/diaphragm-default.obj");
        assertTrue(Files.isRegularFile(written), p.out());
        assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(written)));
        assertEquals(before, Files.exists(committed) ? Files.getLastModifiedTime(committed).toMillis() : -1,
                "the committed mesh is untouched");
        RunProcess big = RunProcess.start(dir, env(), "diaphragm-mesh", "--rings", "100000");
        assertEquals(2, big.waitFor(60));
        assertTrue(big.err().contains("--rings 100000: expected 2 to 500"), big.err());
    }

    @Test
    void guiHelpNeedsNoDisplayAndAnUnreachableDisplayGivesOneLine() throws Exception {
        Map<String, String> noDisplay = env();
        noDisplay.put("DISPLAY", null);
        RunProcess h = RunProcess.start(dir, noDisplay, "gui", "--help");
        assertEquals(0, h.waitFor(60), h.err());
        assertTrue(h.out().contains("Usage: tensim gui"), h.out());
        Map<String, String> unreachable = env();
        unreachable.put("DISPLAY", "127.0.0.1:77");
        RunProcess g = RunProcess.start(dir, unreachable, "gui", "--scene", "cube");
        assertEquals(1, g.waitFor(60), g.err());
        String[] lines = g.err().strip().split("\n");
        assertEquals(1, lines.length, g.err());
        assertTrue(lines[0].contains("cannot reach the display DISPLAY='127.0.0.1:77'"), lines[0]);
    }

    @Test
    void theLauncherRefusesATestOptionWithoutItsValue() throws Exception {
        for (String opt : List.of("--tags", "--exclude-tags", "--class")) {
            Process p = new ProcessBuilder("bash", RunProcess.HOME.resolve("tensim").toString(), "test", opt)
                    .redirectErrorStream(true).start();
            String text = new String(p.getInputStream().readAllBytes());
            assertEquals(2, p.waitFor(), text);
            assertTrue(text.contains("test: " + opt + " needs a value"), text);
            assertFalse(text.contains("unbound variable"), text);
        }
    }
}
