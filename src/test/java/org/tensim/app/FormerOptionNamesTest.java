package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.cli.HelpLayout;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.sweep.SpecReader;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.PresetScene;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The options renamed so that one meaning has one name keep their former names: a command line, a sweep spec's
 * {@code "diaphragm"} object or a preset written with a former name means what it meant.
 */
class FormerOptionNamesTest {
    @TempDir
    Path dir;

    /** The value the last command of a parse took for an option (by any of its names). */
    private static Object parsed(String option, String... args) {
        CommandLine.ParseResult r = Main.commandLine().parseArgs(args);
        while (r.hasSubcommand()) {
            r = r.subcommand();
        }
        Object v = r.matchedOptionValue(option, null);
        assertNotNull(v, option + " not taken from " + Arrays.toString(args));
        return v instanceof int[] a ? Arrays.toString(a) : v;
    }

    @Test
    void everyCommandTakesTheFormerNameForTheSameOption() {
        String[][] cases = {
            {"cube", "--duration", "--seconds", "0.5"},
            {"accuracy", "--integrators", "--integrator", "rk2,rk4"},
            {"stability", "--integrators", "--integrator", "heun"},
            {"bench", "--n", "--size", "5,7"},
            {"diaphragm", "--resolution", "--rings", "12"},
            {"diaphragm", "--muscle-force", "--muscle-action", "15000"},
            {"gui", "--resolution", "--rings", "12"},
            {"gui", "--muscle-force", "--muscle-action", "2000"},
            {"diaphragm resolution-study", "--muscle-force", "--muscle-action", "15000"},
            {"diaphragm realtime-study", "--resolution", "--rings", "20"},
        };
        for (String[] c : cases) {
            List<String> path = List.of(c[0].split(" "));
            List<String> former = new ArrayList<>(path);
            former.addAll(List.of(c[1], c[3]));
            List<String> now = new ArrayList<>(path);
            now.addAll(List.of(c[2], c[3]));
            assertEquals(parsed(c[2], now.toArray(String[]::new)), parsed(c[2], former.toArray(String[]::new)),
                    c[0] + " " + c[1] + " against " + c[2]);
        }
    }

    /** Wherever an option has a former name, it has the name that replaced it: the help shows that one. */
    @Test
    void theFormerNamesBelongToTheOptionsThatReplacedThem() {
        List<CommandLine> all = new ArrayList<>();
        collect(Main.commandLine(), all);
        int seen = 0;
        for (CommandLine c : all) {
            for (OptionSpec o : c.getCommandSpec().options()) {
                List<String> names = Arrays.asList(o.names());
                for (String n : names) {
                    String replacement = HelpLayout.FORMER_NAMES.get(n);
                    if (replacement != null) {
                        seen++;
                        assertEquals(replacement, o.names()[0], c.getCommandSpec().qualifiedName() + " " + n);
                    }
                }
            }
        }
        assertTrue(seen >= HelpLayout.FORMER_NAMES.size(), "every former name is still somewhere: " + seen);
    }

    private static void collect(CommandLine c, List<CommandLine> all) {
        all.add(c);
        c.getSubcommands().values().forEach(s -> collect(s, all));
    }

    @Test
    void theCubeRunsTheSameWithEitherNameOfItsDuration() throws Exception {
        Path a = dir.resolve("seconds");
        Path b = dir.resolve("duration");
        assertEquals(0, Main.commandLine().execute("cube", "--seconds", "0.05", "--out", a.toString()));
        assertEquals(0, Main.commandLine().execute("cube", "--duration", "0.05", "--out", b.toString()));
        byte[] csv = Files.readAllBytes(a.resolve("cube.csv"));
        assertTrue(csv.length > 100 && new String(csv).lines().count() > 40, "50 steps written");
        assertArrayEquals(csv, Files.readAllBytes(b.resolve("cube.csv")));
    }

    @Test
    void theDiaphragmSceneIsTheSameWithTheFormerNames() {
        DiaphragmSpec former = DiaphragmOptions.parse(List.of("--resolution", "12", "--muscle-force", "15000"))
                .spec(null, DiaphragmSpec.PAPER_RINGS);
        DiaphragmSpec now = DiaphragmOptions.parse(List.of("--rings", "12", "--muscle-action", "15000"))
                .spec(null, DiaphragmSpec.PAPER_RINGS);
        assertEquals(now, former);
        assertEquals(12, now.mesh().rings());
        // The former names are still options of the diaphragm but not listed as its keys.
        assertTrue(DiaphragmOptions.names().contains("muscle-action") && DiaphragmOptions.names().contains("rings"));
        assertTrue(!DiaphragmOptions.names().contains("muscle-force")
                && !DiaphragmOptions.names().contains("resolution"));
    }

    @Test
    void aSweepSpecOrAPresetWithTheFormerKeysReadsTheSame() throws Exception {
        String body = "\"parameters\": {\"ribAmplitudeFactor\": {\"min\": 0.5, \"max\": 1, \"steps\": 2}},"
                + " \"solver\": {\"seconds\": 0.1}, \"outputs\": [\"apex_descent_mm\"]}";
        Path former = dir.resolve("former.json");
        Files.writeString(former, "{\"scene\": \"diaphragm\", \"diaphragm\": {\"resolution\": 8, \"muscle-force\":"
                + " 15000}, " + body);
        Path now = dir.resolve("now.json");
        Files.writeString(now, "{\"scene\": \"diaphragm\", \"diaphragm\": {\"rings\": 8, \"muscle-action\": 15000}, "
                + body);
        List<String> a = SpecReader.readSweep(former).setup().diaphragm();
        List<String> b = SpecReader.readSweep(now).setup().diaphragm();
        assertTrue(PresetScene.same(a, b), a + " against " + b);
        assertEquals(DiaphragmOptions.parse(b).spec(null, DiaphragmSpec.PAPER_RINGS),
                DiaphragmOptions.parse(a).spec(null, DiaphragmSpec.PAPER_RINGS));
        // A preset records the scene by the current names.
        assertEquals(java.util.Set.of("rings", "muscle-action"), PresetScene.toJson(a).keySet());
        // Options given beside a preset replace its own, whichever name either used.
        assertEquals(List.of("--rings", "20", "--muscle-action", "15000"),
                PresetScene.merge(a, List.of("--rings", "20")));
    }
}
