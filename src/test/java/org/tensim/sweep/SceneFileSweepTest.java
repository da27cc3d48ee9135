package org.tensim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.app.Main;
import org.tensim.io.Json;

/**
 * A sweep over a scene file's named parameter ({@code "scene": "cube.yaml"}): each point runs what {@code tensim
 * run FILE --set NAME=VALUE} runs, to the bit; the spec's overrides apply to every point; names, values and
 * overrides the file refuses are refused before any run.
 */
class SceneFileSweepTest {
    static final Path CUBE = Path.of("docs/examples/cube.yaml").toAbsolutePath();

    @TempDir
    Path dir;

    /** A spec over the cube's force, its stiffness overridden, 0.5 s each. */
    static String spec(String more) {
        return "{\"scene\": \"" + CUBE + "\", \"overrides\": {\"stiffness\": 200}, \"parameters\": {\"force\":"
                + " {\"values\": [100, 700]}}, \"solver\": {\"seconds\": 0.5}, \"outputs\": [\"mss_dy_m_min\","
                + " \"ts_dy_m_min\", \"steps\"]" + more + "}";
    }

    @Test
    void eachPointIsTheRunOfTheFileWithTheValueSet() throws Exception {
        Path f = Files.writeString(dir.resolve("s.json"), spec(""));
        SweepSpec s = SpecReader.readSweep(f);
        assertEquals(CUBE.toString(), s.setup().scene());
        assertEquals(java.util.List.of("stiffness=200"), s.setup().overrides());
        assertEquals("rk2", s.setup().integrator(), "the file's integrator");
        Sweep.Outcome o;
        try (LocalEngine e = new LocalEngine(1)) {
            o = Sweep.run(s, dir.resolve("out"), e, false, null);
        }
        assertEquals(2, o.results().size());
        PointResult weak = o.results().stream().filter(r -> r.values()[0] == 100).findFirst().orElseThrow();
        PointResult strong = o.results().stream().filter(r -> r.values()[0] == 700).findFirst().orElseThrow();
        assertTrue(weak.ok() && strong.ok(), weak + " " + strong);
        assertEquals(500, weak.field("steps"));
        assertTrue(strong.field("mss_dy_m_min") < 2 * weak.field("mss_dy_m_min"), "seven times the force pushes"
                + " P further down: " + strong.field("mss_dy_m_min") + " m against " + weak.field("mss_dy_m_min"));
        for (PointResult r : o.results()) {
            JsonNode summary = run("--set", "stiffness=200", "--set", "force=" + r.values()[0], "--seconds", "0.5");
            for (String col : new String[] {"mss_dy_m", "ts_dy_m"}) {
                double expected = summary.get("columns").get(col).get("min").asDouble();
                assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(r.field(col + "_min")),
                        "force " + r.values()[0] + " " + col + ": the sweep's " + r.field(col + "_min") + " against"
                        + " tensim run's " + expected);
            }
        }
    }

    @Test
    void namesValuesAndOverridesTheFileRefusesAreRefusedBeforeAnyRun() throws Exception {
        Path unknown = Files.writeString(dir.resolve("a.json"), spec("").replace("\"force\":", "\"forse\":"));
        SpecReader.SpecException e = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(unknown));
        assertTrue(e.getMessage().contains("field 'parameters.forse'") && e.getMessage().contains("force"),
                e.getMessage());
        Path range = Files.writeString(dir.resolve("b.json"), spec("").replace("[100, 700]", "[100, 7000]"));
        e = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(range));
        assertTrue(e.getMessage().contains("parameters.force.values[1]") && e.getMessage().contains("1000"),
                e.getMessage());
        Path over = Files.writeString(dir.resolve("c.json"), spec("").replace("\"stiffness\": 200",
                "\"stiffness\": 5000"));
        e = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(over));
        assertTrue(e.getMessage().contains("field 'scene': --set stiffness=5000: bodies.mss.stiffness: 5000 is"
                + " outside parameter stiffness's range"), e.getMessage());
        Path builtIn = Files.writeString(dir.resolve("d.json"), "{\"scene\": \"cube\", \"overrides\": {\"x\": 1},"
                + " \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"outputs\": [\"steps\"]}");
        e = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(builtIn));
        assertTrue(e.getMessage().contains("field 'overrides'"), e.getMessage());
        Path column = Files.writeString(dir.resolve("e.json"), spec("").replace("\"mss_dy_m_min\"",
                "\"mss_dy_min\""));
        e = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(column));
        assertTrue(e.getMessage().contains("mss_dy_m_min"), "lists the fields: " + e.getMessage());
    }

    /** {@code tensim run CUBE ARGS} into a fresh folder; its summary.json. */
    private JsonNode run(String... args) throws Exception {
        Path out = Files.createTempDirectory(dir, "run");
        String[] all = new String[args.length + 4];
        all[0] = "run";
        all[1] = CUBE.toString();
        System.arraycopy(args, 0, all, 2, args.length);
        all[args.length + 2] = "--out";
        all[args.length + 3] = out.resolve("r").toString();
        PrintStream saved = System.out;
        ByteArrayOutputStream sink = new ByteArrayOutputStream();
        int code;
        System.setOut(new PrintStream(sink, true, StandardCharsets.UTF_8));
        try {
            code = Main.commandLine().execute(all);
        } finally {
            System.setOut(saved);
        }
        // 3: the run ended, failing the file's expect block, which holds for its own force and duration only.
        assertTrue(code == 0 || code == 3, code + ": " + sink.toString(StandardCharsets.UTF_8));
        return Json.mapper().readTree(Files.readAllBytes(out.resolve("r").resolve("summary.json")));
    }
}
