package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.file.BodyContext;
import org.tensim.scene.file.MapReader;
import org.tensim.scene.file.SceneNode;
import org.tensim.scene.file.SceneTree;
import org.tensim.scene.file.SceneUnits;
import org.tensim.scene.file.bodies.DiaphragmBodyType;
import org.tensim.tuning.DiaphragmOptions;

/**
 * The diaphragm's default and its thorax as scene files (docs/examples/diaphragm.yaml, diaphragm-thorax.yaml): each
 * file's body gives the spec {@code tensim diaphragm} builds from the same options, field for field, and
 * {@code tensim run} of it writes the command's summary figures and CSV files bit for bit (at coarse settings
 * given by --set and by the same options on the command line).
 */
class DiaphragmSceneFileTest {
    static final Path DEFAULT = Path.of("docs", "examples", "diaphragm.yaml");
    static final Path THORAX = Path.of("docs", "examples", "diaphragm-thorax.yaml");
    static final Path SHARED_MESH = Path.of("..", "shared", "meshes", "bodyparts3d", "diaphragm-FJ3131-dec28k-mm.obj");
    static final Path SHARED_THORAX = Path.of("..", "shared", "meshes", "thorax");
    /** Summary keys that depend on the machine and the moment, not on the physics. */
    static final List<String> TIMING = List.of("command", "run_wall_s", "finished_utc", "steps_per_s",
            "realtime_factor", "steps_per_cpu_s", "realtime_factor_cpu", "stage_ms_per_step", "load_average",
            "load_average_1min", "commit", "commit_uncommitted_changes", "cores", "files", "scene", "scene_digest",
            "overrides");

    @TempDir
    Path dir;

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    /** The spec a scene file's diaphragm body gives, read without building it. */
    static DiaphragmSpec fileSpec(Path file) {
        SceneNode body = SceneTree.read(file).get("bodies").get("diaphragm");
        List<String> keys = new ArrayList<>(DiaphragmBodyType.KEYS);
        keys.add(0, "type");
        return DiaphragmBodyType.spec(new BodyContext("diaphragm", new MapReader(body, keys), new SceneUnits(),
                file.toAbsolutePath().getParent()));
    }

    @Test
    void theDefaultFileIsTheCommandsDefaultSpec() {
        DiaphragmSpec command = DiaphragmOptions.parse(List.of()).spec(DiaphragmSetup.DEFAULT_MESH,
                DiaphragmSpec.PAPER_RINGS);
        assertEquals(command, fileSpec(DEFAULT));
        assertEquals(DiaphragmSetup.DEFAULT_MESH, fileSpec(DEFAULT).mesh().file(), "the 43-ring mesh, as the command");
    }

    @Test
    void theThoraxFileIsTheCommandsThoraxSpec() {
        Assumptions.assumeTrue(Files.isRegularFile(SHARED_MESH), "absent: " + SHARED_MESH);
        Assumptions.assumeTrue(Files.isRegularFile(SHARED_THORAX.resolve("parts.json")), "absent: "
                + SHARED_THORAX.resolve("parts.json"));
        DiaphragmSpec command = DiaphragmOptions.parse(List.of("--mesh", SHARED_MESH.toAbsolutePath().normalize()
                .toString(), "--units", "mm", "--thorax", SHARED_THORAX.toAbsolutePath().normalize().toString()))
                .spec(null, DiaphragmSpec.PAPER_RINGS);
        DiaphragmSpec file = fileSpec(THORAX);
        assertEquals(command, file);
        assertNotEquals(DiaphragmSpec.defaults().cage(), file.cage(), "a thorax, not the parametric cage");
    }

    /**
     * The default file at 6 rings over one whole breathing cycle of 0.1 s (so that the breathing figures are
     * measured), against {@code tensim diaphragm --rings 6 --period 0.1 --seconds 0.1}.
     */
    @Test
    void runningTheDefaultFileWritesTheCommandsFiguresBitForBit() throws Exception {
        Path a = dir.resolve("command");
        Path b = dir.resolve("file");
        String[] c = run("diaphragm", "--rings", "6", "--period", "0.1", "--seconds", "0.1", "--out", a.toString());
        assertEquals("0", c[0], c[2]);
        String[] f = run("run", DEFAULT.toString(), "--set", "bodies.diaphragm.rings=6", "--set",
                "bodies.diaphragm.period=100 ms", "--set", "run.duration=0.1 s", "--out", b.toString());
        // The file's expect block states the 43-ring 4 s run; this coarse run is checked against it all the same.
        Map<String, Object> sb = Json.readMap(b.resolve("summary.json"));
        List<?> outcomes = (List<?>) sb.get("expectations");
        assertEquals(3, outcomes.size(), "the file's three checks were evaluated");
        boolean allPass = true;
        for (Object o : outcomes) {
            Map<?, ?> m = (Map<?, ?>) o;
            String key = m.get("check").toString().replace("summary ", "");
            System.out.println("6 rings, 0.1 s: " + m.get("check") + " = " + m.get("measured") + " " + m.get("unit")
                    + ", pass " + m.get("pass"));
            assertEquals(((Number) sb.get(key)).doubleValue(), ((Number) m.get("measured")).doubleValue(), 0, key);
            double v = ((Number) m.get("measured")).doubleValue();
            double lo = ((Number) m.get("low")).doubleValue();
            double hi = ((Number) m.get("high")).doubleValue();
            assertEquals(v >= lo && v <= hi, m.get("pass"), key + "'s verdict");
            allPass &= Boolean.TRUE.equals(m.get("pass"));
        }
        assertEquals(allPass ? "0" : "3", f[0], f[2]);
        assertEquals(allPass ? "ok" : "expectation_failed", sb.get("status"));
        Map<String, Object> fields = sameFigures(a, b);
        assertTrue(fields.containsKey("dome_excursion_mm"), "the breathing was measured: " + fields);
        assertEquals(DEFAULT.toString(), Json.readMap(b.resolve("summary.json")).get("scene"));
    }

    /** {@code check} of a {@code dt: auto} diaphragm file prints the step and step count {@code run} takes. */
    @Test
    void checkPrintsTheStepRunTakesForDtAuto() throws Exception {
        Path out = dir.resolve("run");
        List<String> sets = List.of("--set", "bodies.diaphragm.rings=6", "--set", "bodies.diaphragm.period=100 ms",
                "--set", "run.duration=0.01 s");
        List<String> runArgs = new ArrayList<>(List.of("run", DEFAULT.toString(), "--out", out.toString()));
        runArgs.addAll(sets);
        String[] r = run(runArgs.toArray(String[]::new));
        List<String> checkArgs = new ArrayList<>(List.of("check", DEFAULT.toString()));
        checkArgs.addAll(sets);
        String[] c = run(checkArgs.toArray(String[]::new));
        assertEquals("0", c[0], c[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        double dt = ((Number) s.get("dt_s")).doubleValue();
        long steps = ((Number) s.get("steps")).longValue();
        String line = c[1].lines().filter(l -> l.startsWith("run: ")).findFirst().orElseThrow();
        assertTrue(line.contains(String.format(java.util.Locale.ROOT, "dt auto: %.6g s", dt))
                && line.contains("(" + steps + " steps)"), line + " against run's dt " + dt + " s, " + steps
                + " steps (" + r[0] + ")");
    }

    /**
     * The thorax file for two bdf2 steps of 2.5 ms, against the command's --thorax run: minutes on two cores (the
     * full BodyParts3D mesh among the thorax's bones), so tagged slow, out of the default run.
     */
    @Test
    @Tag("slow")
    void runningTheThoraxFileWritesTheCommandsFiguresBitForBit() throws Exception {
        Assumptions.assumeTrue(Files.isRegularFile(SHARED_MESH), "absent: " + SHARED_MESH);
        Assumptions.assumeTrue(Files.isRegularFile(SHARED_THORAX.resolve("parts.json")), "absent: "
                + SHARED_THORAX.resolve("parts.json"));
        Path a = dir.resolve("command");
        Path b = dir.resolve("file");
        // Absolute paths, as the file's are resolved: the summary's source names them.
        String[] c = run("diaphragm", "--mesh", SHARED_MESH.toAbsolutePath().normalize().toString(), "--units", "mm",
                "--thorax", SHARED_THORAX.toAbsolutePath().normalize().toString(), "--integrator", "bdf2", "--dt",
                "0.0025", "--seconds", "0.005", "--out", a.toString());
        assertEquals("0", c[0], c[2]);
        String[] f = run("run", THORAX.toString(), "--set", "run.duration=5 ms", "--out", b.toString());
        assertEquals("0", f[0], f[2]);
        sameFigures(a, b);
    }

    /** Asserts the two runs' summaries equal but for timing and provenance, and their CSV files byte for byte. */
    private static Map<String, Object> sameFigures(Path a, Path b) throws Exception {
        Map<String, Object> sa = new TreeMap<>(Json.readMap(a.resolve("summary.json")));
        Map<String, Object> sb = new TreeMap<>(Json.readMap(b.resolve("summary.json")));
        assertEquals("ok", sa.get("status"));
        TIMING.forEach(sa::remove);
        TIMING.forEach(sb::remove);
        for (String k : List.of("status", "expectations", "expectations_failed")) { // the file's checks (above)
            sb.remove(k);
            sa.remove(k);
        }
        assertEquals(sa, sb, "summary.json without its timing and provenance");
        for (String csv : List.of("probe.csv", "displacements.csv")) {
            assertArrayEquals(Files.readAllBytes(a.resolve(csv)), Files.readAllBytes(b.resolve(csv)), csv);
        }
        return sa;
    }
}
