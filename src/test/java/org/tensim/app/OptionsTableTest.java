package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.io.ProjectFolder;
import org.tensim.scene.tunable.TunableParameter;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * docs/reference/options.md is what {@link OptionsTable} prints, and what it prints is true: every link names an
 * option of its command, a GUI parameter of the same unit, a unit the option's description gives, and a
 * {@code summary.json} key that holds the value a real run was given.
 */
class OptionsTableTest {
    @TempDir
    Path dir;

    @Test
    void theCommittedPageIsTheGeneratedOne() throws Exception {
        Path page = ProjectFolder.resolve("docs", "reference", "options.md");
        String generated = OptionsTable.markdown();
        String committed = Files.readString(page);
        if (!committed.equals(generated)) {
            String[] a = committed.split("\n", -1);
            String[] b = generated.split("\n", -1);
            int i = 0;
            while (i < Math.min(a.length, b.length) && a[i].equals(b[i])) {
                i++;
            }
            fail(page + " differs from what org.tensim.app.OptionsTable prints, first at line " + (i + 1)
                    + ":\n  committed: " + (i < a.length ? a[i] : "(end of file)") + "\n  generated: "
                    + (i < b.length ? b[i] : "(end of file)") + "\nregenerate it: java -cp 'build/install/tensim/lib/*'"
                    + " org.tensim.app.OptionsTable > docs/reference/options.md");
        }
    }

    @Test
    void everyLinkNamesAnOptionOfItsCommandAndAGuiParameterOfTheSameUnit() {
        CommandLine cl = Main.commandLine();
        for (var e : OptionsTable.LINKS.entrySet()) {
            CommandSpec c = cl.getSubcommands().get(e.getKey()).getCommandSpec();
            for (OptionsTable.Link l : e.getValue()) {
                OptionSpec o = c.findOption(l.flag());
                assertNotNull(o, e.getKey() + " has no option " + l.flag());
                if (l.guiKey() != null) {
                    TunableParameter p = OptionsTable.guiParameter(e.getKey(), l.guiKey());
                    assertNotNull(p, l.flag() + ": the GUI of " + e.getKey() + " has no parameter " + l.guiKey());
                    assertEquals(p.unit(), l.unit(), l.flag() + " against the GUI's " + l.guiKey());
                } else if (!l.unit().isEmpty()) {
                    String text = String.join(" ", o.description());
                    Pattern unit = Pattern.compile("(^|[\\s,(])" + Pattern.quote(l.unit()) + "([\\s,;:.)]|$)");
                    assertTrue(unit.matcher(text).find(), l.flag() + ": the description does not give the unit '"
                            + l.unit() + "': " + text);
                }
            }
        }
    }

    @Test
    void everySceneFileKeyIsAPropertyOfTheSceneSchema() throws Exception {
        com.fasterxml.jackson.databind.JsonNode defs = Json.mapper().readTree(Files.readAllBytes(
                ProjectFolder.resolve("docs", "scene.schema.json"))).get("$defs");
        int checked = 0;
        for (var e : OptionsTable.LINKS.entrySet()) {
            for (OptionsTable.Link l : e.getValue()) {
                if (l.sceneKey() != null) {
                    String[] dp = l.sceneKey().split(":");
                    assertNotNull(OptionsTable.SCENE_PATHS.get(dp[0]), l.flag() + ": no key path for " + dp[0]);
                    assertNotNull(defs.get(dp[0]), l.flag() + ": the scene schema has no definition " + dp[0]);
                    assertTrue(defs.get(dp[0]).get("properties").has(dp[1]), l.flag() + ": the scene schema's "
                            + dp[0] + " has no property " + dp[1]);
                    checked++;
                }
            }
        }
        assertTrue(checked > 0, "no scene-file key was checked");
    }

    @Test
    void theDiaphragmsSummaryKeysHoldTheValuesARunWasGiven() throws Exception {
        // a coarse mesh of the generator's, read as a file: a step of it costs milliseconds
        Path mesh = dir.resolve("dome-6.obj");
        CommandLine gen = Main.commandLine();
        gen.setOut(new PrintWriter(new StringWriter()));
        assertEquals(0, gen.execute("diaphragm-mesh", "--rings", "6", "--out", mesh.toString()));
        Map<String, String> given = new LinkedHashMap<>();
        given.put("--mesh", mesh.toString());
        given.put("--rib-amplitude", "0.5");
        given.put("--muscle-action", "12000");
        given.put("--period", "3");
        given.put("--muscle-load", "fibres");
        given.put("--tendon-fraction", "0.2");
        given.put("--seconds", "0.006");
        given.put("--integrator", "bdf2");
        given.put("--dt", "0.002");
        given.put("--threads", "1");
        given.put("--newton", "2");
        given.put("--cg-iterations", "7");
        Map<String, Object> s = run("diaphragm", given);
        for (OptionsTable.Link l : OptionsTable.LINKS.get("diaphragm")) {
            if (l.summaryKey() == null) {
                continue;
            }
            Object v = value(s, l.summaryKey());
            assertNotNull(v, "summary.json has no " + l.summaryKey() + " (" + l.flag() + "): " + s.keySet());
            if (l.flag().equals("--mesh")) {
                assertTrue(v.toString().startsWith(mesh.toString()), "source " + v + " against --mesh " + mesh);
            } else if (l.flag().equals("--tendon-fraction")) {
                // the grown region's measured share: whole triangles of a 6-ring dome, near the share asked
                assertEquals(0.2, ((Number) v).doubleValue(), 0.05, l.summaryKey());
            } else {
                same(given.get(l.flag()), v, l);
            }
        }
    }

    @Test
    void theCubesSummaryKeysHoldTheValuesARunWasGiven() throws Exception {
        Map<String, String> given = new LinkedHashMap<>();
        given.put("--seconds", "0.02");
        given.put("--dt", "0.001");
        given.put("--force", "300");
        given.put("--frequency", "0.5");
        given.put("--tilt", "2");
        given.put("--stiffness", "200");
        given.put("--damping", "1");
        given.put("--mass", "2");
        given.put("--integrator", "rk4");
        Map<String, Object> s = run("cube", given);
        for (OptionsTable.Link l : OptionsTable.LINKS.get("cube")) {
            if (l.summaryKey() != null) {
                Object v = value(s, l.summaryKey());
                assertNotNull(v, "summary.json has no " + l.summaryKey() + " (" + l.flag() + "): " + s);
                same(given.get(l.flag()), v, l);
            }
        }
    }

    private Map<String, Object> run(String command, Map<String, String> given) throws Exception {
        Path out = dir.resolve(command);
        List<String> args = new ArrayList<>(List.of(command, "--out", out.toString()));
        given.forEach((k, v) -> {
            args.add(k);
            args.add(v);
        });
        CommandLine cl = Main.commandLine();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(err));
        assertEquals(0, cl.execute(args.toArray(String[]::new)), String.join(" ", args) + ": " + err);
        return Json.readMap(out.resolve("summary.json"));
    }

    @SuppressWarnings("unchecked")
    private static Object value(Map<String, Object> summary, String dotted) {
        Object v = summary;
        for (String part : dotted.split("\\.")) {
            if (!(v instanceof Map)) {
                return null;
            }
            v = ((Map<String, Object>) v).get(part);
        }
        return v;
    }

    private static void same(String given, Object v, OptionsTable.Link l) {
        assertNotNull(given, "the test gives no value for " + l.flag());
        if (v instanceof Number n) {
            assertEquals(Double.parseDouble(given), n.doubleValue(), 1e-9 * Math.abs(n.doubleValue()) + 1e-12,
                    l.summaryKey() + " against " + l.flag() + " " + given);
        } else {
            assertEquals(given, String.valueOf(v), l.summaryKey() + " against " + l.flag());
        }
    }
}
