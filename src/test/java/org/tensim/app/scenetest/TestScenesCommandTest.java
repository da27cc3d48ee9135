package org.tensim.app.scenetest;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * {@code tensim test-scenes DIR}: every scene file under DIR is a group of JUnit tests, one per check of its
 * expect block; a check that holds passes, one that does not fails, a file that does not load is a failed test
 * with the loader's message; the JUnit XML report counts them the same; the project's examples pass.
 */
class TestScenesCommandTest {
    @TempDir
    Path dir;

    static String[] run(String... args) {
        return Commands.run(args);
    }

    /** A cube hanging from its bottom face under gravity for 0.05 s, with the given expect block (or none). */
    static String scene(String expect) {
        return String.join("\n",
                "version: 1",
                "bodies: {c: {type: cube, element: mass-spring, side: 1 m, node_mass: 10 g}}",
                "regions: {bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}}",
                "conditions: [{type: fixed, region: bottom}, {type: gravity, acceleration: [0, -9.81, 0]}]",
                "probes: {p: {node: 13}}",
                "run: {dt: 1 ms, duration: 0.05 s, every: 10}",
                expect, "");
    }

    static final String HOLDS = "  - {column: p_dy_m, stat: min, between: [-1 m, 0 m]}\n"
            + "  - {summary: steps, value: 50, tolerance: 0}";

    @Test
    void passingFailingAndUnloadableScenesAreTestsAndTheXmlReportCountsThem() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.createDirectories(scenes.resolve("sub"));
        Files.writeString(scenes.resolve("sub/holds.yaml"), scene("expect:\n" + HOLDS));
        // Impossible: the node hangs below its rest position, never 1 m above it.
        Files.writeString(scenes.resolve("impossible.yml"), scene("expect:\n"
                + "  - {column: p_dy_m, stat: max, between: [1 m, 2 m]}\n"
                + "  - {summary: steps, value: 50, tolerance: 0}"));
        Files.writeString(scenes.resolve("broken.yaml"), scene("expect:\n" + HOLDS).replace("node_mass", "node_mas"));
        Files.writeString(scenes.resolve("plain.json"), Json.line(new com.fasterxml.jackson.databind.ObjectMapper(
                new com.fasterxml.jackson.dataformat.yaml.YAMLFactory()).readValue(scene(""), Object.class)));
        // Not scene files: a sweep spec and some other YAML.
        Files.writeString(scenes.resolve("sweep.json"), "{\"scene\": \"cube\", \"parameters\": {}}");
        Files.writeString(scenes.resolve("other.yaml"), "name: not a scene\nsteps: [1, 2]\n");
        Path out = dir.resolve("out");
        Path reports = dir.resolve("xml");
        String[] r = run("test-scenes", scenes.toString(), "--out", out.toString(), "--reports", reports.toString());
        assertEquals("1", r[0], r[1] + r[2]);
        List<String> lines = r[1].strip().lines().toList();
        assertEquals("4 passed, 2 failed", lines.get(lines.size() - 1), r[1]);
        assertTrue(r[1].contains("FAIL impossible.yml > p_dy_m max in [1.00000, 2.00000] m"), r[1]);
        assertTrue(r[1].contains("FAIL broken.yaml > load: broken.yaml:2:"), r[1]);
        assertTrue(r[1].contains("unknown key 'node_mas'; did you mean 'node_mass'?"), r[1]);
        assertTrue(r[1].contains("pass sub/holds.yaml > summary steps"), r[1]);
        assertTrue(r[1].contains("pass plain.json > load (no expect block: nothing run)"), r[1]);
        assertFalse(r[1].contains("sweep.json") || r[1].contains("other.yaml"), r[1]);

        // The JUnit XML report: one testcase per test, a failure element per failed one, with its message.
        Document xml = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(reports.resolve("TEST-junit-jupiter.xml").toFile());
        Element suite = xml.getDocumentElement();
        assertEquals("testsuite", suite.getTagName());
        assertEquals("6", suite.getAttribute("tests"));
        assertEquals("2", suite.getAttribute("failures"));
        assertEquals("0", suite.getAttribute("errors"));
        NodeList cases = suite.getElementsByTagName("testcase");
        assertEquals(6, cases.getLength());
        List<String> failures = new ArrayList<>();
        NodeList f = suite.getElementsByTagName("failure");
        for (int i = 0; i < f.getLength(); i++) {
            failures.add(((Element) f.item(i)).getAttribute("message"));
        }
        assertEquals(2, failures.size(), failures.toString());
        assertTrue(failures.stream().anyMatch(m -> m.startsWith("FAIL: p_dy_m max = ") && m.contains("impossible.yml")),
                failures.toString());
        assertTrue(failures.stream().anyMatch(m -> m.contains("did you mean 'node_mass'?")), failures.toString());

        // Each run is a run folder as tensim run writes it.
        assertEquals("ok", Json.readMap(out.resolve("runs/sub/holds/summary.json")).get("status"));
        assertEquals("expectation_failed", Json.readMap(out.resolve("runs/impossible/summary.json")).get("status"));
        assertTrue(Files.exists(out.resolve("runs/impossible/probes.csv")));
        assertFalse(Files.exists(out.resolve("runs/plain")), "a scene without checks is not run");
    }

    @Test
    void aFolderWithoutSceneFilesOrNoFolderIsAUsageError() throws Exception {
        Files.writeString(dir.resolve("other.yaml"), "name: not a scene\n");
        String[] none = run("test-scenes", dir.toString(), "--out", dir.resolve("out").toString());
        assertEquals("2", none[0], none[2]);
        assertTrue(none[2].contains("holds no scene file"), none[2]);
        String[] missing = run("test-scenes", dir.resolve("nowhere").toString());
        assertEquals("2", missing[0], missing[2]);
        assertTrue(missing[2].contains("no such folder"), missing[2]);
    }

    /**
     * The project's examples are a regression suite that passes (the cube's figures within 1 % of today's); those
     * that read the shared meshes are skipped, naming the file, where ../shared is absent, and pass where it is.
     */
    @Test
    void theProjectsExamplesPass() throws Exception {
        Path out = dir.resolve("out");
        String[] r = run("test-scenes", "docs/examples", "--out", out.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        List<String> lines = r[1].strip().lines().toList();
        String last = lines.get(lines.size() - 1);
        boolean shared = Files.isDirectory(Path.of("../shared/meshes/thorax"));
        assertTrue(last.matches("\\d+ passed, 0 failed" + (shared ? "" : ", 2 skipped")), r[1]);
        if (!shared) {
            assertTrue(r[1].contains("skip diaphragm-thorax.yaml > load: skipped: reads "), r[1]);
            assertTrue(r[1].contains("skip liver.yaml > load: skipped: reads "), r[1]);
            assertTrue(r[1].contains("shared/meshes/thorax/liver.obj, which is absent"), r[1]);
        }
        int passed = Integer.parseInt(last.substring(0, last.indexOf(' ')));
        int skipped = shared ? 0 : 2;
        assertTrue(r[1].contains("pass cube.yaml > mss_dy_m min"), r[1]);
        assertTrue(r[1].contains("pass cube.yaml > ts_dy_m min"), r[1]);
        Document xml = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(out.resolve("reports/TEST-junit-jupiter.xml").toFile());
        assertEquals(String.valueOf(passed + skipped), xml.getDocumentElement().getAttribute("tests"));
        assertEquals("0", xml.getDocumentElement().getAttribute("failures"));
        assertEquals(String.valueOf(skipped), xml.getDocumentElement().getAttribute("skipped"));
        assertEquals(passed + skipped, xml.getDocumentElement().getElementsByTagName("testcase").getLength());
    }

    /**
     * A scene naming a mesh that is not on this machine is skipped with the file's name, apart from the failures:
     * the suite passes; a scene naming a folder where a file is expected still fails.
     */
    @Test
    void aSceneWhoseMeshIsAbsentIsSkippedNamingIt() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        String organ = String.join("\n", "version: 1",
                "bodies: {o: {type: volume, surface: {file: MESH, units: mm}, cell: 10,",
                "  material: {E: 1 kPa, nu: 0.3, density: 1000 kg/m^3}}}",
                "run: {dt: 1 ms, duration: 0.01 s}",
                "expect: [{summary: steps, value: 10, tolerance: 0}]", "");
        Files.writeString(scenes.resolve("away.yaml"), organ.replace("MESH", "data/organ.obj"));
        Files.writeString(scenes.resolve("holds.yaml"), scene("expect:\n" + HOLDS));
        String[] r = run("test-scenes", scenes.toString(), "--out", dir.resolve("out").toString());
        assertEquals("0", r[0], r[1] + r[2]);
        assertTrue(r[1].contains("skip away.yaml > load: skipped: reads " + scenes.resolve("data/organ.obj")
                + ", which is absent"), r[1]);
        assertTrue(r[1].strip().endsWith("2 passed, 0 failed, 1 skipped"), r[1]);
        Files.createDirectories(scenes.resolve("data/organ.obj"));
        String[] folder = run("test-scenes", scenes.toString(), "--out", dir.resolve("out2").toString());
        assertEquals("1", folder[0], folder[1] + folder[2]);
        assertTrue(folder[1].contains("FAIL away.yaml > load:"), folder[1]);
        assertTrue(folder[1].contains("it is a folder; expected a file"), folder[1]);
        assertTrue(folder[1].strip().endsWith("2 passed, 1 failed"), folder[1]);
    }
}
