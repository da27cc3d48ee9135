package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.scene.file.SceneLoader;

/**
 * {@code tensim run} evaluates a scene's expect block: the statistics are the CSV's (checked against free fall's
 * analytic answer), each check's measured value and verdict go to summary.json, and a failed check ends the run
 * with status expectation_failed and exit code 3, its outputs kept.
 */
class SceneExpectRunTest {
    @TempDir
    Path dir;

    /** An unfixed cube falling: its mean is at -g t^2 / 2, sampled at t = 0, 0.1, ..., 0.5 s. */
    static String fall(String... expect) {
        return String.join("\n",
                "version: 1",
                "bodies: {c: {type: cube, element: mass-spring, side: 1 m, node_mass: 10 g}}",
                "regions: {all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}}",
                "conditions: [{type: gravity, acceleration: [0, -9.81 m/s^2, 0]}]",
                "probes: {c: {region: all}}",
                "run: {dt: 1 ms, duration: 0.5 s, csv: fall.csv, every: 100}",
                "expect:", String.join("\n", expect), "");
    }

    static final double G = 9.81;
    /** The mean of -g t^2 / 2 over the rows: t^2 sums to 0.55 s^2 over the six rows. */
    static final double MEAN_DY = -0.5 * G * 0.55 / 6;
    static final double FINAL_DY = -0.5 * G * 0.25;

    @Test
    void checksThatHoldPassAndTheirMeasuresAreTheCsvsStatistics() throws Exception {
        Path f = Files.writeString(dir.resolve("fall.yaml"), fall(
                "  - {column: c_mean_dy_m, stat: final, value: " + FINAL_DY + " m, tolerance: 0.000001 m}",
                "  - {column: c_mean_dy_m, stat: mean, value: " + MEAN_DY * 1000 + " mm, tolerance: 0.001 mm}",
                "  - {column: c_mean_dy_m, stat: max, between: [-1 nm, 1 nm]}",
                "  - {column: c_mean_dy_m, stat: min, value: " + FINAL_DY + " m, tolerance: 1e-6 %}",
                "  - {column: t_s, stat: final, value: 0.5 s, tolerance: 1 ns}",
                "  - {summary: steps, value: 500, tolerance: 0}",
                "  - {summary: body_nodes.c, value: 20, tolerance: 0}",
                "  - {summary: columns.c_mean_dy_m.min, between: [-1.3 m, -1.2 m]}"));
        Path out = dir.resolve("out");
        String[] r = runCapturing("run", f.toString(), "--out", out.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("ok", s.get("status"));
        assertEquals(0, ((Number) s.get("expectations_failed")).intValue());
        List<Map<String, Object>> checks = outcomes(s);
        assertEquals(8, checks.size());
        // The measured values are those of the CSV's rows.
        List<String> lines = Files.readAllLines(out.resolve("fall.csv"));
        double sum = 0;
        double last = 0;
        for (String line : lines.subList(1, lines.size())) {
            last = Double.parseDouble(line.split(",")[2]);
            sum += last;
        }
        assertEquals(last, checks.get(0).get("measured"));
        assertEquals(sum / (lines.size() - 1), (Double) checks.get(1).get("measured") * 1, 1e-15);
        assertEquals(MEAN_DY, (Double) checks.get(1).get("measured"), 1e-9);
        assertEquals(0.0, checks.get(2).get("measured"));
        assertEquals(500.0, checks.get(5).get("measured"));
        for (Map<String, Object> c : checks) {
            assertEquals(true, c.get("pass"), c.toString());
        }
        assertEquals("c_mean_dy_m final", checks.get(0).get("check"));
        assertEquals("m", checks.get(0).get("unit"));
        assertTrue(r[1].contains("pass: c_mean_dy_m mean = "), r[1]);
    }

    @Test
    void aCheckThatFailsEndsTheRunWithCodeThreeAndKeepsItsOutputs() throws Exception {
        Path f = Files.writeString(dir.resolve("fall.yaml"), fall(
                "  - {column: c_mean_dy_m, stat: final, between: [1 m, 2 m]}",
                "  - {summary: steps, value: 500, tolerance: 0}"));
        Path out = dir.resolve("out");
        String[] r = runCapturing("run", f.toString(), "--out", out.toString());
        assertEquals("3", r[0], r[1] + r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("expectation_failed", s.get("status"));
        assertEquals(1, ((Number) s.get("expectations_failed")).intValue());
        List<Map<String, Object>> checks = outcomes(s);
        assertEquals(false, checks.get(0).get("pass"));
        assertEquals(FINAL_DY, (Double) checks.get(0).get("measured"), 1e-9);
        assertEquals(1.0, checks.get(0).get("low"));
        assertEquals(2.0, checks.get(0).get("high"));
        assertEquals("fall.yaml:8:5: expect[0]", checks.get(0).get("at"));
        assertEquals(true, checks.get(1).get("pass"));
        assertEquals(7, Files.readAllLines(out.resolve("fall.csv")).size(), "the CSV is kept whole");
        assertTrue(r[2].contains("expectation failed: c_mean_dy_m final = -1.22625 m, expected in [1.00000,"
                + " 2.00000] m (between 1 m and 2 m) at fall.yaml:8:5: expect[0]"), r[2]);
    }

    /** Every summary key an expectation may name is a number of the runner's summary. */
    @Test
    void everySummaryKeyAnExpectationMayNameIsWrittenByTheRun() throws Exception {
        Path f = Files.writeString(dir.resolve("fall.yaml"), fall("  - {summary: steps, value: 500, tolerance: 0}"));
        Scene scene = SceneLoader.load(f);
        Map<String, String> keys = SceneExpectation.summaryKeys(scene.bodies().keySet(),
                SceneExpectation.columns(scene.probes()));
        StringBuilder expect = new StringBuilder();
        for (String k : keys.keySet()) {
            expect.append("  - {summary: ").append(k).append(", between: [-1e9, 1e9]}\n");
        }
        Files.writeString(f, fall(expect.toString().stripTrailing()));
        Path out = dir.resolve("out");
        String[] r = runCapturing("run", f.toString(), "--out", out.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        List<Map<String, Object>> checks = outcomes(Json.readMap(out.resolve("summary.json")));
        assertEquals(keys.size(), checks.size());
        assertTrue(keys.size() >= 10, keys.toString());
        for (Map<String, Object> c : checks) {
            assertTrue(c.get("measured") instanceof Double, "a number was found: " + c);
        }
    }

    /** Runs a command in this JVM: exit code, then standard output and standard error (System's and picocli's). */
    static String[] runCapturing(String... args) {
        PrintStream out = System.out;
        PrintStream err = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        String[] r;
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            r = SceneCommandsTest.run(args);
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
        return new String[] {r[0], r[1] + o.toString(StandardCharsets.UTF_8),
            r[2] + e.toString(StandardCharsets.UTF_8)};
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> outcomes(Map<String, Object> summary) {
        return (List<Map<String, Object>>) summary.get("expectations");
    }
}
