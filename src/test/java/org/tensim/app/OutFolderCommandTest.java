package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.io.ProjectFolder;
import picocli.CommandLine;

/**
 * The commands' output folders: each its own default, a study never replaces the diaphragm's results, and the
 * resolution pick is written and read only where the user says.
 */
class OutFolderCommandTest {
    @TempDir
    Path dir;

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    private static Set<String> names(Path d) throws Exception {
        Set<String> s = new TreeSet<>();
        try (var l = Files.list(d)) {
            l.forEach(p -> s.add(p.getFileName().toString()));
        }
        return s;
    }

    /** The default --out of every command that has one, from its picocli model. */
    private static Map<String, String> defaults() {
        Map<String, String> m = new LinkedHashMap<>();
        collect(Main.commandLine(), m);
        return m;
    }

    private static void collect(CommandLine cl, Map<String, String> m) {
        var o = cl.getCommandSpec().findOption("--out");
        if (o != null && o.defaultValueString() != null) {
            m.put(cl.getCommandSpec().qualifiedName(), o.defaultValueString());
        }
        cl.getSubcommands().values().forEach(c -> collect(c, m));
    }

    @Test
    void noTwoCommandsShareADefaultOutputFolder() {
        Map<String, String> d = defaults();
        for (String c : List.of("tensim cube", "tensim bench", "tensim accuracy", "tensim stability",
                "tensim diaphragm", "tensim diaphragm resolution-study", "tensim diaphragm realtime-study",
                "tensim diaphragm-mesh", "tensim sweep", "tensim calibrate")) {
            assertTrue(d.containsKey(c), c + " has a default --out: " + d);
        }
        assertEquals(d.size(), new java.util.HashSet<>(d.values()).size(), "each default is one command's: " + d);
        assertEquals(Path.of("out", "diaphragm-resolution").toString(), d.get("tensim diaphragm resolution-study"));
        assertEquals(Path.of("out", "diaphragm-realtime").toString(), d.get("tensim diaphragm realtime-study"));
    }

    @Test
    void theStudyOverTheDiaphragmsFolderRefusesUntilOverwriteAndItsOwnRerunReplaces() throws Exception {
        Path out = dir.resolve("diaphragm");
        String[] d = run("diaphragm", "--rings", "6", "--seconds", "0.01", "--vtk-per-cycle", "0", "--out",
                out.toString());
        assertEquals("0", d[0], d[2]);
        Set<String> before = names(out);
        assertTrue(before.contains("probe.csv") && before.contains("summary.json"), before.toString());
        String summary = Files.readString(out.resolve("summary.json"));

        String[] refused = run("diaphragm", "resolution-study", "--study-rings", "4,5", "--seconds", "0.01",
                "--out", out.toString());
        assertEquals("2", refused[0], "a refusal of options: " + refused[2]);
        assertTrue(refused[2].contains(out.toString()) && refused[2].contains("--overwrite")
                && refused[2].contains("--out"), refused[2]);
        assertEquals(before, names(out), "nothing deleted");
        assertEquals(summary, Files.readString(out.resolve("summary.json")));

        String[] forced = run("diaphragm", "resolution-study", "--study-rings", "4,5", "--seconds", "0.01",
                "--out", out.toString(), "--overwrite");
        assertEquals("0", forced[0], forced[2]);
        assertEquals("diaphragm resolution-study", Json.readMap(out.resolve("summary.json")).get("command"));
        assertTrue(Files.exists(out.resolve("resolution.csv")));

        String[] again = run("diaphragm", "resolution-study", "--study-rings", "4,5", "--seconds", "0.01",
                "--out", out.toString());
        assertEquals("0", again[0], "the same command over its own folder: " + again[2]);
        assertFalse(Files.exists(out.resolve("probe.csv")), "only this run's outputs are left");
    }

    @Test
    void thePickGoesIntoOutOrWherePickOutSaysAndNeverUnderTheProjectsMeshes() throws Exception {
        Path out = dir.resolve("study");
        DiaphragmResolutionCommand c = new DiaphragmResolutionCommand();
        CommandLine cl = new CommandLine(c);
        cl.parseArgs("--out", out.toString());
        assertEquals(out.resolve("resolution-pick.json"), c.pickFile(c.out.folder(c.spec)));
        Path meshes = ProjectFolder.resolve("meshes");
        assertFalse(c.pickFile(out).normalize().startsWith(meshes.normalize()));

        DiaphragmResolutionCommand given = new DiaphragmResolutionCommand();
        new CommandLine(given).parseArgs("--out", out.toString(), "--pick-out", dir.resolve("mine.json").toString());
        assertEquals(dir.resolve("mine.json"), given.pickFile(out));

        String[] noPick = run("diaphragm", "resolution-study", "--study-rings", "4,5", "--pick-out",
                dir.resolve("p.json").toString(), "--out", out.toString());
        assertEquals("2", noPick[0]);
        assertTrue(noPick[2].contains("--pick-out") && noPick[2].contains("--study-rings"), noPick[2]);
        assertFalse(Files.exists(out), "refused before any folder was made");
    }

    @Test
    void aRunAtAPickNamesItsFileInTheSummary() throws Exception {
        Path pick = dir.resolve("picked.json");
        Json.write(pick, Map.of("format", "tensim-resolution-pick", "rings", 6, "relative_rms_error", 0.04,
                "tolerance", 0.1, "reason", "the coarsest within 10 %", "scene",
                org.tensim.experiment.diaphragm.ResolutionPick.sceneOf(
                        org.tensim.scene.diaphragm.DiaphragmSpec.defaults())));
        Path out = dir.resolve("at-pick");
        String[] r = run("diaphragm", "--pick", pick.toString(), "--seconds", "0.01", "--vtk-per-cycle", "0",
                "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals(pick.toString(), ((Map<?, ?>) s.get("resolution_pick")).get("source"));
        assertTrue(String.valueOf(((Map<?, ?>) s.get("mechanics")).get("source")).contains("6 rings"),
                "the pick's rings run the mechanics: " + s.get("mechanics"));
        assertEquals(11_354, ((Number) s.get("drawn_nodes")).intValue(), "the 43-ring mesh is measured");
        assertEquals(s.get("drawn_nodes"), s.get("diaphragm_nodes"));

        Path plain = dir.resolve("plain");
        assertEquals("0", run("diaphragm", "--rings", "6", "--seconds", "0.01", "--vtk-per-cycle", "0", "--out",
                plain.toString())[0]);
        assertFalse(Json.readMap(plain.resolve("summary.json")).containsKey("resolution_pick"),
                "no pick read unless named");

        String[] both = run("diaphragm", "--pick", pick.toString(), "--rings", "8", "--out", dir.resolve("x")
                .toString());
        assertEquals("2", both[0]);
        assertTrue(both[2].contains("--pick") && both[2].contains("--rings 8"), both[2]);
        String[] missing = run("diaphragm", "--pick", dir.resolve("none.json").toString(), "--out",
                dir.resolve("y").toString());
        assertNotEquals("0", missing[0]);
        assertTrue(missing[2].contains("none.json") && missing[2].contains("no such file"), missing[2]);
    }
}
