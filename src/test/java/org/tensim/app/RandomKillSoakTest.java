package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.RandomCases;
import org.tensim.io.mesh.MeshReaders;
import org.tensim.io.mesh.MeshUnits;

/**
 * The random-kill soak: 20 runs of each headless command, each stopped
 * at a random moment by SIGINT, SIGTERM or SIGKILL (or left to end), over a folder
 * holding an old run's files; every folder must then hold a complete result or a
 * clearly marked incomplete one, with no torn row and no stale file
 * ({@link FolderCheck}). Minutes long: run it with {@code ./tensim test --tags soak};
 * it prints one line per command with the signals sent and the outcomes.
 */
@Tag("soak")
class RandomKillSoakTest {
    static final int RUNS = Integer.getInteger("tensim.soak.runs", 20);

    @TempDir
    Path dir;

    @Test
    void everyHeadlessCommandLeavesACompleteOrMarkedFolderWhenKilledAtRandom() throws Exception {
        Map<String, String[]> commands = new LinkedHashMap<>();
        commands.put("cube", new String[] {"cube", "--duration", "4000"});
        commands.put("diaphragm", new String[] {"diaphragm", "--seconds", "2", "--vtk-per-cycle", "40"});
        commands.put("accuracy", new String[] {"accuracy"});
        commands.put("stability", new String[] {"stability"});
        commands.put("bench", new String[] {"bench", "--n", "11,21", "--threads", "1", "--repeats", "3"});
        List<String> report = new ArrayList<>();
        for (var c : commands.entrySet()) {
            Map<String, Integer> outcomes = new LinkedHashMap<>();
            RandomCases.check("soak " + c.getKey(), RUNS, r -> outcomes.merge(
                    ProcessLevelTest.killAndCheck(dir, r, c.getValue()), 1, Integer::sum));
            report.add(c.getKey() + ": " + RUNS + " runs, folders sound; ended by " + outcomes);
        }
        Map<String, Integer> mesh = new LinkedHashMap<>();
        RandomCases.check("soak diaphragm-mesh", RUNS, r -> mesh.merge(killMeshWriter(r), 1, Integer::sum));
        report.add("diaphragm-mesh: " + RUNS + " runs, OBJ complete or absent; ended by " + mesh);
        report.forEach(System.out::println);
    }

    /** diaphragm-mesh writes one file, whole then renamed: after any stop it is complete or absent. */
    private String killMeshWriter(SplittableRandom r) throws Exception {
        Path cwd = Files.createTempDirectory(dir, "mesh");
        Map<String, String> env = new java.util.HashMap<>();
        RunProcess p = RunProcess.start(cwd, env, "diaphragm-mesh", "--rings", "120");
        long delayMs = 200 + r.nextInt(3000);
        String signal = RandomCases.oneOf(r, "INT", "TERM", "KILL");
        boolean ended = p.process.waitFor(delayMs, java.util.concurrent.TimeUnit.MILLISECONDS);
        if (!ended) {
            signal = p.signal(signal);
        }
        int code = p.waitFor(120);
        Path obj = cwd.resolve("out/diaphragm-mesh/diaphragm-default.obj");
        if (Files.exists(obj)) {
            assertEquals(org.tensim.scene.diaphragm.DoubleDomeGenerator.shell(
                    org.tensim.scene.diaphragm.DoubleDomeGenerator.Shape.adult().withRings(120)).vertexCount(),
                    MeshReaders.read(obj, MeshUnits.MM).vertexCount(), "a complete mesh, not a cut one (exit " + code
                    + ")");
        }
        try (var s = Files.list(cwd.resolve("out/diaphragm-mesh"))) {
            long temps = s.filter(f -> f.getFileName().toString().endsWith(".tmp")).count();
            if (!"KILL".equals(signal) || ended) {
                assertEquals(0, temps, "a signal that lets the JVM end removes the temporary file");
            }
        } catch (java.nio.file.NoSuchFileException e) {
            // killed before the folder was made
        }
        return ended ? "none" : signal;
    }
}
