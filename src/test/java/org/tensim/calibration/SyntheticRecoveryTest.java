package org.tensim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.sweep.LocalEngine;

/**
 * The worked example of docs/calibration.md: a target surface made by the project at known
 * values (muscle action 2600 Pa, rib amplitude 1.2) at end-inspiration, with 0.3 mm of Gaussian
 * noise on every coordinate, is fitted from a start 30 % off; every parameter comes back within
 * 2 % of the truth. Coarse generated dome (6 rings, 254 nodes), implicit Euler at 10 ms.
 */
class SyntheticRecoveryTest {
    @TempDir
    Path dir;

    @Test
    void recoversKnownParametersFromANoisySurface() throws Exception {
        Path spec = dir.resolve("synthetic.json");
        // The pressure load, which the figures below were measured with.
        Files.writeString(spec, "{\"scene\": \"diaphragm\", \"mesh\": {\"rings\": 6}, \"muscleLoad\": \"pressure\","
                + " \"solver\": {\"integrator\": \"implicit-euler-cg1e-3\", \"dtS\": 0.01, \"seconds\": 1.34},"
                + " \"fit\": {\"muscleActionPa\": {\"min\": 1000, \"max\": 4000, \"start\": 1800},"
                + " \"ribAmplitudeFactor\": {\"min\": 0.3, \"max\": 2.0, \"start\": 0.8}},"
                + " \"optimizer\": {\"population\": 6, \"generations\": 20, \"sigma\": 0.3, \"seed\": 1},"
                + " \"targets\": [{\"type\": \"surface\", \"file\": \"target.obj\", \"units\": \"mm\","
                + " \"timeS\": 1.33, \"toleranceMm\": 1}]}");
        Map<String, Double> truth = new LinkedHashMap<>();
        truth.put("muscleActionPa", 2600.0);
        truth.put("ribAmplitudeFactor", 1.2);
        SyntheticTarget.write(CalibrationReader.readSetup(spec), truth, 1.33, 0.3, 1, dir.resolve("target.obj"));
        CalibrationSpec s = CalibrationReader.read(spec);
        Calibration.Result r;
        try (LocalEngine e = new LocalEngine(org.tensim.solver.parallel.Parallelism.availableCores())) {
            r = Calibration.run(s, e, dir.resolve("out"), null);
        }
        double[] best = r.outcome().best().values();
        System.out.printf(java.util.Locale.ROOT, "synthetic recovery: muscle %.2f Pa (truth 2600), rib %.5f (truth 1.2),"
                + " %d runs, %.1f s%n", best[0], best[1], r.outcome().evaluations().size(), r.outcome().wallS());
        assertEquals(2, best.length);
        assertEquals(2600, best[0], 0.02 * 2600, "muscle action within 2 %");
        assertEquals(1.2, best[1], 0.02 * 1.2, "rib amplitude within 2 %");
        // the fit improved on the start by far and the files are there
        Calibrator.Evaluation start = r.outcome().evaluations().get(0);
        assertEquals(0, start.generation());
        assertTrue(r.outcome().best().fitness() < 0.5 * start.fitness(), "objective falls from the start");
        for (String f : new String[] {"best-preset.json", "history.csv", "convergence.png", "residuals.json",
            "evaluations.csv"}) {
            assertTrue(Files.isRegularFile(dir.resolve("out").resolve(f)), f);
        }
        String preset = Files.readString(dir.resolve("out/best-preset.json"));
        assertTrue(preset.contains("\"muscleActionPa\" : " + best[0]), preset);
        assertTrue(preset.contains("\"muscleLoad\" : \"pressure\""), "the preset names the load it was fitted with: "
                + preset);
    }
}
