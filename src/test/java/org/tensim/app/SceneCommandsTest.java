package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.FileDigest;
import org.tensim.io.Json;

/**
 * {@code tensim run} and {@code tensim check} on scene files: the cube's scene writes {@code tensim cube}'s
 * cube.csv to the byte; free fall and prescribed motion give their analytic answers; overrides are applied and
 * recorded.
 */
class SceneCommandsTest {
    @TempDir
    Path dir;

    static String[] run(String... args) {
        return Commands.run(args);
    }

    @Test
    void theCubesSceneWritesTheCubeCommandsCsvToTheByte() throws Exception {
        Path a = dir.resolve("cube");
        Path b = dir.resolve("scene");
        assertEquals("0", run("cube", "--out", a.toString())[0]);
        String[] r = run("run", "docs/examples/cube.yaml", "--out", b.toString());
        assertEquals("0", r[0], r[2]);
        byte[] expected = Files.readAllBytes(a.resolve("cube.csv"));
        assertTrue(expected.length > 100_000, "the whole 4 s run, every step");
        assertArrayEquals(expected, Files.readAllBytes(b.resolve("cube.csv")));
        // The summary's peaks are the cube command's, the file's digest and (no) overrides are recorded.
        Map<String, Object> cube = Json.readMap(a.resolve("summary.json"));
        Map<String, Object> scene = Json.readMap(b.resolve("summary.json"));
        Map<?, ?> columns = (Map<?, ?>) scene.get("columns");
        assertEquals(cube.get("mss_peak_y_m"), ((Map<?, ?>) columns.get("mss_dy_m")).get("min"));
        assertEquals(cube.get("ts_peak_y_m"), ((Map<?, ?>) columns.get("ts_dy_m")).get("min"));
        assertEquals(FileDigest.of(List.of(Path.of("docs/examples/cube.yaml"))), scene.get("scene_digest"));
        assertEquals(List.of(), scene.get("overrides"));
        assertEquals(cube.get("steps"), scene.get("steps"));
    }

    @Test
    void overridesChangeTheRunAndAreRecorded() throws Exception {
        Path a = dir.resolve("cube");
        Path b = dir.resolve("scene");
        assertEquals("0", run("cube", "--out", a.toString(), "--duration", "0.5", "--stiffness", "150")[0]);
        String[] r = run("run", "docs/examples/cube.yaml", "--out", b.toString(), "--duration", "0.5",
                "--set", "bodies.mss.stiffness=150 N/m", "--set", "bodies.ts.stiffness=0.15 kN/m");
        // The file's expectations are of its own 4 s run: half a second of a stiffer cube does not meet them.
        assertEquals("3", r[0], r[2]);
        assertArrayEquals(Files.readAllBytes(a.resolve("cube.csv")), Files.readAllBytes(b.resolve("cube.csv")));
        Map<String, Object> s = Json.readMap(b.resolve("summary.json"));
        assertEquals("expectation_failed", s.get("status"));
        assertEquals(List.of("bodies.mss.stiffness=150 N/m", "bodies.ts.stiffness=0.15 kN/m"), s.get("overrides"));
        assertEquals(0.5, s.get("duration_s"));
        String[] bad = run("check", "docs/examples/cube.yaml", "--set", "bodies.mss.stiffness=3 kPa");
        assertEquals("2", bad[0]);
        assertTrue(bad[2].contains("--set bodies.mss.stiffness=3 kPa: bodies.mss.stiffness: \"3 kPa\" is not a"
                + " stiffness"), bad[2]);
        String[] typo = run("check", "docs/examples/cube.yaml", "--set", "bodies.mss.stifness=3");
        assertTrue(typo[2].contains("did you mean 'stiffness'?"), typo[2]);
        String[] nowhere = run("check", "docs/examples/cube.yaml", "--set", "bodys.mss.stiffness=3");
        assertTrue(nowhere[2].contains("the file has no bodys; did you mean 'bodies'?"), nowhere[2]);
    }

    /** An unfixed cube under gravity: the springs' forces cancel in the sum, so its mean falls as g t^2 / 2. */
    @Test
    void freeFallOfTheMeanIsGravitysParabola() throws Exception {
        Path f = Files.writeString(dir.resolve("fall.yaml"), String.join("\n",
                "version: 1",
                "bodies: {c: {type: cube, element: mass-spring, side: 1 m, node_mass: 10 g}}",
                "regions: {all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}}",
                "conditions: [{type: gravity, acceleration: [0, -9.81 m/s^2, 0]}]",
                "probes: {c: {region: all}}",
                "run: {dt: 1 ms, duration: 0.5 s, csv: fall.csv, every: 100}", ""));
        String[] r = run("run", f.toString(), "--out", dir.resolve("out").toString());
        assertEquals("0", r[0], r[2]);
        List<String> lines = Files.readAllLines(dir.resolve("out").resolve("fall.csv"));
        assertEquals("t_s,c_mean_dx_m,c_mean_dy_m,c_mean_dz_m", lines.get(0));
        assertEquals(7, lines.size(), "rows at 0, 0.1, ..., 0.5 s");
        for (String line : lines.subList(1, lines.size())) {
            double[] v = java.util.Arrays.stream(line.split(",")).mapToDouble(Double::parseDouble).toArray();
            assertEquals(-0.5 * 9.81 * v[0] * v[0], v[2], 1e-9, "mean y at t = " + v[0]);
            assertEquals(0, v[1], 1e-12);
            assertEquals(0, v[3], 1e-12);
        }
    }

    /** Driven nodes are where their motion puts them, at every sample; extents follow the driven face. */
    @Test
    void prescribedMotionFollowsItsLaw() throws Exception {
        Path f = Files.writeString(dir.resolve("pull.yaml"), String.join("\n",
                "version: 1",
                "units: {length: mm}",
                "bodies: {c: {type: cube, element: none, side: 100}}",
                "laws: {up: {type: ramp, duration: 0.2 s, to: 2}}",
                "regions:",
                "  bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}",
                "  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}",
                "conditions:",
                "  - {type: fixed, region: bottom}",
                "  - {type: motion, region: top, displacement: [0, 5, 0], law: up}",
                "probes: {lid: {region: top}, box: {region: top, quantity: extents}}",
                "run: {dt: 1 ms, duration: 0.3 s, every: 50}", ""));
        assertEquals("0", run("check", f.toString())[0]);
        String[] r = run("run", f.toString(), "--out", dir.resolve("out").toString());
        assertEquals("0", r[0], r[2]);
        List<String> lines = Files.readAllLines(dir.resolve("out").resolve("probes.csv"));
        assertEquals("t_s,lid_mean_dx_m,lid_mean_dy_m,lid_mean_dz_m,box_min_x_m,box_max_x_m,box_min_y_m,box_max_y_m,"
                + "box_min_z_m,box_max_z_m", lines.get(0));
        for (String line : lines.subList(1, lines.size())) {
            double[] v = java.util.Arrays.stream(line.split(",")).mapToDouble(Double::parseDouble).toArray();
            double law = Math.min(2, 2 * v[0] / 0.2);
            assertEquals(0.005 * law, v[2], 1e-12, "lid at t = " + v[0]);
            assertEquals(0.1 + 0.005 * law, v[7], 1e-12);
            assertEquals(v[6], v[7], 1e-12, "the driven face stays flat");
            assertEquals(0, v[4], 1e-12);
            assertEquals(0.1, v[5], 1e-12);
        }
    }

    /** The scene files the README and docs/scenes.md show are accepted as they stand. */
    @Test
    void theDocsScenesAreAccepted() throws Exception {
        for (String doc : List.of("README.md", "docs/scenes.md")) {
            String text = Files.readString(Path.of(doc));
            int start = text.indexOf("```yaml\n");
            assertTrue(start >= 0, doc + " shows a scene");
            String yaml = text.substring(start + 8, text.indexOf("```", start + 8));
            Path f = Files.writeString(dir.resolve("doc.yaml"), yaml);
            String[] r = run("check", f.toString());
            assertEquals("0", r[0], doc + "'s scene: " + r[2]);
            assertTrue(r[1].contains("region loaded on ts: 2 nodes"), r[1]);
        }
    }

    /** The same scene written as JSON is read to the same scene. */
    @Test
    void jsonIsReadLikeYaml() throws Exception {
        Object tree = new com.fasterxml.jackson.databind.ObjectMapper(
                new com.fasterxml.jackson.dataformat.yaml.YAMLFactory()).readValue(Path.of("docs/examples/cube.yaml")
                .toFile(), Object.class);
        Path json = dir.resolve("cube.json");
        Json.write(json, tree);
        String[] y = run("check", "docs/examples/cube.yaml");
        String[] j = run("check", json.toString());
        assertEquals("0", j[0], j[2]);
        assertEquals(y[1].substring(y[1].indexOf('\n')), j[1].substring(j[1].indexOf('\n')), "the same report");
    }

    /** A run that diverges stops with status "diverged" and exit code 1, keeping the rows it wrote. */
    @Test
    void aDivergingRunStopsCleanly() throws Exception {
        Path f = Files.writeString(dir.resolve("blow.yaml"), String.join("\n",
                "version: 1",
                "bodies: {c: {type: cube, element: mass-spring, stiffness: 1e6 N/m, damping: 0}}",
                "regions: {bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}}",
                "conditions: [{type: fixed, region: bottom}, {type: gravity, acceleration: [0, -9.81, 0]}]",
                "probes: {p: {node: 13}}",
                "run: {integrator: euler, dt: 0.01 s, duration: 100 s}", ""));
        Path out = dir.resolve("out");
        String[] r = run("run", f.toString(), "--out", out.toString());
        assertEquals("1", r[0], r[1] + r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("diverged", s.get("status"));
        List<String> lines = Files.readAllLines(out.resolve("probes.csv"));
        assertTrue(lines.size() > 1 && lines.size() < 10_002, "rows until it diverged: " + lines.size());
        assertEquals(4, lines.get(lines.size() - 1).split(",").length, "the last row is whole");
    }

    /**
     * Each example scene passes {@code tensim check}, one dynamic test per file; a scene that reads a file that is
     * absent (the liver's mesh under ../shared) is skipped with that file's name.
     */
    @TestFactory
    Stream<DynamicTest> everyExampleSceneChecks() throws Exception {
        List<Path> scenes;
        try (var files = Files.list(Path.of("docs/examples"))) {
            scenes = files.filter(p -> p.toString().matches(".*\\.ya?ml")).sorted().toList();
        }
        assertTrue(scenes.contains(Path.of("docs/examples/cube.yaml")), scenes.toString());
        return scenes.stream().map(f -> DynamicTest.dynamicTest(f.getFileName().toString(), () -> {
            for (Path needed : filesNamedIn(f)) {
                Assumptions.assumeTrue(Files.exists(needed), f + " reads " + needed.normalize() + ", which is absent");
            }
            String[] r = run("check", f.toString());
            assertEquals("0", r[0], f + ": " + r[2]);
            assertTrue(r[1].strip().endsWith("ok"), r[1]);
        }));
    }

    /**
     * The files and folders a scene names (the scalar values of {@code file:}, a diaphragm's {@code mesh:},
     * {@code thorax:}, {@code labels:} and {@code boxes:}; comments aside), resolved against its folder.
     */
    private static List<Path> filesNamedIn(Path scene) throws java.io.IOException {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile(
                        "\\b(?:file|mesh|thorax|labels|boxes):[ \\t]*([^\\s,}#{\\[][^\\s,}#]*)")
                .matcher(Files.readString(scene).replaceAll("#[^\\n]*", ""));
        List<Path> out = new java.util.ArrayList<>();
        while (m.find()) {
            out.add(scene.toAbsolutePath().getParent().resolve(m.group(1)));
        }
        return out;
    }
}
