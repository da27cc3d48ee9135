package org.tensim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
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
import org.tensim.sweep.SpecReader;

/** Penalties instead of crashes, refusals before any run, and the landmark measure. */
class CalibrationBehaviourTest {
    @TempDir
    Path dir;

    @Test
    void divergedCandidatesArePenalisedAndTheFitGoesOn() throws Exception {
        // Explicit Euler at 30 ms: stiff cubes (above about 900 N/m) blow up, soft ones do not.
        Path spec = dir.resolve("cube.json");
        Files.writeString(spec, "{\"scene\": \"cube\", \"solver\": {\"integrator\": \"euler\", \"dtS\": 0.03,"
                + " \"seconds\": 6}, \"fixed\": {\"forceAmplitudeN\": 300},"
                + " \"fit\": {\"stiffnessNPerM\": {\"min\": 50, \"max\": 9000, \"start\": 6000}},"
                + " \"optimizer\": {\"population\": 6, \"generations\": 6, \"sigma\": 0.4, \"seed\": 3},"
                + " \"targets\": [{\"type\": \"summary\", \"field\": \"mss_peak_y_m\", \"value\": -1.0,"
                + " \"tolerance\": 0.01}]}");
        CalibrationSpec s = CalibrationReader.read(spec);
        Calibration.Result r;
        try (LocalEngine e = new LocalEngine(2)) {
            r = Calibration.run(s, e, dir.resolve("out"), null);
        }
        List<Calibrator.Evaluation> all = r.outcome().evaluations();
        long diverged = all.stream().filter(e -> e.result().status().equals(PointResult.DIVERGED)).count();
        assertTrue(diverged > 0, "some candidates diverged");
        for (Calibrator.Evaluation e : all) {
            if (!e.result().ok()) {
                assertEquals(Calibrator.PENALTY, e.fitness());
            } else {
                assertTrue(e.fitness() < Calibrator.PENALTY);
            }
        }
        assertTrue(r.outcome().best().result().ok(), "the best candidate is a finished run");
        assertTrue(Files.readString(dir.resolve("out/evaluations.csv")).contains(",diverged,"));
    }

    @Test
    @SuppressWarnings("unchecked")
    void aBestStoppedAtABoundAndUnmetTargetsAreReported() throws Exception {
        // The cube's mass-spring peak is -2.4 m at 300 N/m and -0.41 m at 1000 N/m (RK2, 10 ms, 300 N):
        // -5 m needs a softer cube than the range allows, so the fit ends on the lower bound.
        String spec = "{\"scene\": \"cube\", \"solver\": {\"integrator\": \"rk2\", \"dtS\": 0.01,"
                + " \"seconds\": 2}, \"fixed\": {\"forceAmplitudeN\": 300},"
                + " \"fit\": {\"stiffnessNPerM\": {\"min\": 300, \"max\": 1000, \"start\": 700}},"
                + " \"optimizer\": {\"population\": 4, \"generations\": 4, \"sigma\": 0.3, \"seed\": 2},"
                + " \"targets\": [{\"type\": \"summary\", \"field\": \"mss_peak_y_m\", \"value\": VALUE,"
                + " \"tolerance\": TOL}]}";
        Path far = dir.resolve("far.json");
        Files.writeString(far, spec.replace("VALUE", "-5").replace("TOL", "0.01"));
        CalibrationSpec s = CalibrationReader.read(far);
        Calibration.Result r;
        try (LocalEngine e = new LocalEngine(2)) {
            r = Calibration.run(s, e, dir.resolve("far"), null);
        }
        java.util.Map<String, Object> sum = r.summary();
        assertEquals(java.util.Map.of("stiffnessNPerM", "min"), sum.get("at_bounds"));
        assertEquals(0, sum.get("targets_met"));
        assertEquals(false, sum.get("all_targets_met"));
        assertEquals(false, ((List<java.util.Map<String, Object>>) sum.get("targets")).get(0).get("met"));
        List<String> w = CalibrationReport.warnings(s.free(), sum);
        assertEquals(2, w.size(), w.toString());
        assertTrue(w.get(0).contains("stiffnessNPerM") && w.get(0).contains("lower bound")
                && w.get(0).contains("widen the range"), w.get(0));
        assertTrue(w.get(1).contains("not met") && w.get(1).contains("mss_peak_y_m"), w.get(1));
        assertTrue(Files.readString(dir.resolve("far/residuals.json")).contains("\"at_bounds\""));

        // Within reach and a loose tolerance: met, and no warning about it.
        Path near = dir.resolve("near.json");
        Files.writeString(near, spec.replace("VALUE", "-1").replace("TOL", "0.5"));
        CalibrationSpec s2 = CalibrationReader.read(near);
        try (LocalEngine e = new LocalEngine(2)) {
            r = Calibration.run(s2, e, dir.resolve("near"), null);
        }
        sum = r.summary();
        double peak = r.outcome().best().result().field("mss_peak_y_m");
        assertTrue(Math.abs(peak + 1) <= 0.5, "best peak " + peak);
        assertEquals(true, sum.get("all_targets_met"));
        assertEquals(1, sum.get("targets_met"));
        assertTrue(CalibrationReport.warnings(s2.free(), sum).stream().noneMatch(x -> x.contains("not met")));
    }

    @Test
    void aBoundThatIsTheParametersOwnLimitIsNamedAsSuch() {
        // muscleActionPa takes at most 30 kPa: a fit stopped there cannot be helped by wider bounds.
        List<CalibrationSpec.Free> free = List.of(
                new CalibrationSpec.Free("muscleActionPa", 5000, 30000, 18000, 0, 30000),
                new CalibrationSpec.Free("ribAmplitudeFactor", 0.5, 2, 1, 0, 3));
        double[] best = {30000, 0.5};
        java.util.Map<String, String> at = CalibrationReport.atBounds(free, best);
        assertEquals(java.util.Map.of("muscleActionPa", "max", "ribAmplitudeFactor", "min"), at);
        java.util.Map<String, Object> summary = new java.util.LinkedHashMap<>();
        summary.put("best", java.util.Map.of("muscleActionPa", 30000.0, "ribAmplitudeFactor", 0.5));
        summary.put("at_bounds", at);
        summary.put("targets", List.of());
        List<String> w = CalibrationReport.warnings(free, summary);
        assertEquals(2, w.size(), w.toString());
        assertTrue(w.get(0).contains("largest value the parameter takes"), w.get(0));
        assertTrue(w.get(1).contains("widen the range in 'fit.ribAmplitudeFactor', up to 0.0"), w.get(1));
        // Inside the bounds (0.2 % of the range away): nothing to report.
        assertTrue(CalibrationReport.atBounds(free, new double[] {29950, 0.504}).isEmpty());
    }

    @Test
    void badTargetsAreRefusedBeforeAnyRunNamingTheField() throws Exception {
        Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
        Files.writeString(dir.resolve("bad.csv"), "id,t,x,y,z\na,0,1,2,3\nb,0.1,1,zz,3\n");
        String head = "{\"scene\": \"diaphragm\", \"mesh\": {\"rings\": 6}, \"solver\": {\"seconds\": 1.4},"
                + " \"fit\": {\"muscleActionPa\": {\"min\": 1000, \"max\": 4000}}, \"targets\": [";
        String[][] cases = {
            {"{\"type\": \"surface\", \"file\": \"bad.obj\", \"timeS\": 1}", "'targets[0].file'"},
            {"{\"type\": \"landmarks\", \"file\": \"bad.csv\"}", "bad.csv line 3"},
            {"{\"type\": \"summary\", \"field\": \"dome_excursion_mm\", \"value\": 1e999, \"tolerance\": 1}",
                "'targets[0].value'"},
            {"{\"type\": \"summary\", \"field\": \"dome\", \"value\": 18, \"tolerance\": 1}", "'targets[0].field'"},
            {"{\"type\": \"summary\", \"field\": \"dome_excursion_mm\", \"value\": 18, \"tolerance\": 0}",
                "'targets[0].tolerance'"},
            {"{\"type\": \"surface\", \"file\": \"missing.obj\", \"timeS\": 1}", "'targets[0].file'"},
        };
        for (String[] c : cases) {
            Path f = dir.resolve("c.json");
            Files.writeString(f, head + c[0] + "]}");
            SpecReader.SpecException e = assertThrows(SpecReader.SpecException.class, () -> CalibrationReader.read(f),
                    c[0]);
            assertTrue(e.getMessage().contains(c[1]), c[0] + " -> " + e.getMessage());
        }
        Path f = dir.resolve("d.json");
        Files.writeString(f, head.replace("\"max\": 4000", "\"max\": 4000, \"start\": 5000")
                + "{\"type\": \"summary\", \"field\": \"dome_excursion_mm\", \"value\": 18, \"tolerance\": 1}]}");
        assertTrue(assertThrows(SpecReader.SpecException.class, () -> CalibrationReader.read(f)).getMessage()
                .contains("'fit.muscleActionPa.start'"));
    }

    @Test
    void landmarksAreMatchedToTheNearestNodesAtRestAndMeasuredInMillimetres() throws Exception {
        Path spec = dir.resolve("s.json");
        Files.writeString(spec, "{\"scene\": \"diaphragm\", \"mesh\": {\"rings\": 6}, \"solver\": {\"integrator\":"
                + " \"implicit-euler-cg1e-3\", \"dtS\": 0.01, \"seconds\": 0.05}}");
        org.tensim.sweep.RunSetup setup = CalibrationReader.readSetup(spec);
        // Two landmarks 1 mm to the side of two nodes at rest, at t = 0 (before any motion).
        PointResult probe = SceneRun.run(setup, List.of(), new Point(0, new double[0]));
        assertTrue(probe.ok());
        double[] rest = restPositions(setup);
        Path csv = dir.resolve("lm.csv");
        Files.writeString(csv, String.format(java.util.Locale.ROOT, "id,t,x,y,z\nA,0,%.9f,%.9f,%.9f\nB,0,%.9f,%.9f,%.9f\n",
                1e3 * rest[0] + 1, 1e3 * rest[1], 1e3 * rest[2], 1e3 * rest[30], 1e3 * rest[31] + 1, 1e3 * rest[32]));
        LandmarkTarget t = CalibrationReader.landmarks(csv, 1e-3, 0.05, 0.5, 1, "lm_");
        PointResult r = SceneRun.run(setup.withMeasures(List.of(t.measure())), List.of(), new Point(0, new double[0]));
        assertEquals(1.0, r.field("lm_rms_mm"), 1e-6, "each landmark is 1 mm from its node at t = 0");
        assertEquals(2.0, t.residuals(r)[0], 1e-5, "residual = RMS / tolerance");
    }

    private static double[] restPositions(org.tensim.sweep.RunSetup setup) {
        double[][] rest = new double[1][];
        org.tensim.sweep.Measure grab = run -> {
            rest[0] = run.rest();
            return new org.tensim.sweep.Measure.Probe() {
                @Override
                public void afterStep(double t, double[] x) {
                }

                @Override
                public void finish(java.util.Map<String, Double> fields) {
                }
            };
        };
        SceneRun.run(setup.withMeasures(List.of(grab)), List.of(), new Point(0, new double[0]));
        return rest[0];
    }
}
