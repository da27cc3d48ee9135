package org.tensim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.sweep.LocalEngine;
import org.tensim.sweep.Point;
import org.tensim.sweep.PointResult;
import org.tensim.sweep.SceneRun;

/**
 * A calibration over a scene file's named parameter: a coarse volume bar clamped at one end sags under gravity;
 * the sag its run gives at E = 400 kPa (0.8 mm, small: linear) is the target, and the fit, started at 650 kPa
 * within [200, 800] kPa, finds E again within 1 %. Implicit Euler at 0.5 s steps over 10 s settles the bar at rest,
 * where the sag falls as 1/E, so that E is identifiable from it alone.
 */
class SceneFileCalibrationTest {
    static final String BAR = String.join("\n",
            "version: 1",
            "units: {length: mm}",
            "bodies:",
            "  bar: {type: volume, box: [40, 10, 10], cell: 5, material: {E: 300 kPa, density: 1000 kg/m^3}}",
            "regions:",
            "  clamp: {box: {min: [0, 0, 0], max: [0, 1, 1], frame: relative}}",
            "  tip: {box: {min: [1, 0, 0], max: [1, 1, 1], frame: relative}}",
            "conditions:",
            "  - {type: fixed, region: clamp}",
            "  - {type: gravity, acceleration: [0, 0, -9.81 m/s^2]}",
            "probes:",
            "  sag: {region: tip}",
            "run: {integrator: implicit-euler, dt: 0.5 s, duration: 10 s}",
            "parameters:",
            "  E: {path: bodies.bar.material.E, unit: kPa, range: [100, 1000], apply: live}",
            "");

    @TempDir
    Path dir;

    @Test
    void recoversTheModulusThatMadeTheSag() throws Exception {
        Path scene = Files.writeString(dir.resolve("bar.yaml"), BAR);
        Path spec = dir.resolve("fit.json");
        String head = "{\"scene\": \"bar.yaml\", \"fit\": {\"E\": {\"min\": 200, \"max\": 800, \"start\": 650}},"
                + " \"optimizer\": {\"population\": 4, \"generations\": 20, \"sigma\": 0.3, \"seed\": 1,"
                + " \"stopFitness\": 0.01},";
        Files.writeString(spec, head + " \"targets\": [{\"type\": \"summary\", \"field\": \"sag_mean_dz_m_final\","
                + " \"value\": 0, \"tolerance\": 1}]}");
        PointResult truth = SceneRun.run(CalibrationReader.readSetup(spec), List.of("E"), new Point(0,
                new double[] {400}));
        double sag = truth.field("sag_mean_dz_m_final");
        assertTrue(truth.ok() && sag < -1e-4, "the bar sags: " + sag + " m");
        PointResult stiffer = SceneRun.run(CalibrationReader.readSetup(spec), List.of("E"), new Point(1,
                new double[] {800}));
        assertEquals(0.5, stiffer.field("sag_mean_dz_m_final") / sag, 0.005, "twice E, half the sag (static, linear)");
        Files.writeString(spec, head + " \"targets\": [{\"type\": \"summary\", \"field\": \"sag_mean_dz_m_final\","
                + " \"value\": " + sag + ", \"tolerance\": " + (0.01 * Math.abs(sag)) + "}]}");
        CalibrationSpec s = CalibrationReader.read(spec);
        Calibration.Result r;
        try (LocalEngine e = new LocalEngine(2)) {
            r = Calibration.run(s, e, dir.resolve("out"), null);
        }
        double e = r.outcome().best().values()[0];
        System.out.printf(java.util.Locale.ROOT, "scene-file calibration: E %.4f kPa (truth 400), %d runs, %.1f s%n", e,
                r.outcome().evaluations().size(), r.outcome().wallS());
        assertEquals(400, e, 0.01 * 400, "E within 1 %");
        List<String> set = Files.readAllLines(dir.resolve("out/best-set.txt"));
        assertEquals(List.of("--set E=" + e), set, "the fitted value as tensim run takes it");
        assertTrue(Files.isRegularFile(scene));
    }
}
