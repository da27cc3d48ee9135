package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.experiment.diaphragm.RealTimeSetting;
import org.tensim.io.Json;
import org.tensim.solver.integrators.Integrators;

/** diaphragm --realtime, the checked --dt and the real-time study's selection options. */
class DiaphragmRealtimeOptionTest {
    @TempDir
    Path dir;

    private static String[] run(String... args) {
        return CommandLineTest.run(args);
    }

    private static void rejected(String expected, String... args) {
        String[] r = run(args);
        assertFalse(r[0].equals("0"), "exit code of " + String.join(" ", args));
        assertTrue(r[2].contains(expected), r[2]);
        assertFalse(r[2].contains("\tat "), "no stack trace: " + r[2]);
    }

    @Test
    void badStepsAndSelectionsGetOneClearLine() {
        rejected("--dt -1.0: the time step must be a finite number > 0 s (or 0 for the scene's own step)", "diaphragm",
                "--dt", "-1");
        rejected("got 5.0 s", "diaphragm", "--dt", "5");
        rejected("(--period 2.0 s), got 2.5 s", "diaphragm", "--period", "2", "--dt", "2.5");
        rejected("--realtime chooses the integrator and the step itself", "diaphragm", "--realtime", "--dt", "0.01");
        rejected("--realtime chooses the integrator and the step itself", "diaphragm", "--realtime", "--integrator",
                "rk4");
        rejected("--study-rings must be ascending ring counts of 4 or more, got [43, 10]", "diaphragm",
                "realtime-study", "--study-rings", "43,10");
        rejected("--resolution-study is now a subcommand: tensim diaphragm resolution-study", "diaphragm",
                "--resolution-study");
        rejected("--realtime-study is now a subcommand: tensim diaphragm realtime-study", "diaphragm",
                "--realtime-study");
        rejected("--study-configs is not a regular expression", "diaphragm", "realtime-study", "--study-configs",
                "bdf2[");
    }

    /**
     * --integrator takes every setup of the catalogue, as a sweep spec does: bdf2-newton2 runs BDF2 with its
     * two Newton iterations; an unknown name is refused with every valid one.
     */
    @Test
    void integratorTakesEveryNamedSetupOfTheCatalogue() throws Exception {
        rejected("unknown integrator 'bdf3': expected one of " + String.join(", ", Integrators.choiceNames()),
                "diaphragm", "--integrator", "bdf3");
        Path mesh = dir.resolve("coarse.obj");
        String[] m = run("diaphragm-mesh", "--rings", "8", "--out", mesh.toString());
        assertEquals("0", m[0], "diaphragm-mesh failed: " + m[2]);
        assertTrue(Files.isRegularFile(mesh), "diaphragm-mesh wrote no " + mesh + ": " + m[2]);
        Path out = dir.resolve("out");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--integrator", Integrators.LARGE_STEP_ACCURATE,
                "--dt", "0.02", "--seconds", "0.1", "--threads", "1", "--vtk-per-cycle", "0", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> summary = Json.readMap(out.resolve("summary.json"));
        assertEquals("bdf2", summary.get("integrator"), "the method the setup runs");
        assertEquals(0.02, ((Number) summary.get("dt_s")).doubleValue(), 1e-12);
    }

    /** The default load is the fibres': --realtime without --muscle-load runs their setting. */
    @Test
    void realtimeRunsTheMeasuredSettingAndNamesIt() throws Exception {
        Path mesh = dir.resolve("coarse.obj");
        String[] m = run("diaphragm-mesh", "--rings", "10", "--out", mesh.toString());
        assertEquals("0", m[0], "diaphragm-mesh failed: " + m[2]);
        assertTrue(Files.isRegularFile(mesh), "diaphragm-mesh wrote no " + mesh + ": " + m[2]);
        Path out = dir.resolve("out");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--realtime", "--seconds", "1.4", "--vtk-per-cycle",
                "0", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        RealTimeSetting s = RealTimeSetting.FIBRES;
        assertEquals(s, RealTimeSetting.forMuscleLoad(org.tensim.scene.diaphragm.BoundaryConditions.defaults().muscleLoad()));
        Map<String, Object> summary = Json.readMap(out.resolve("summary.json"));
        assertEquals(s.integrator(), summary.get("integrator"));
        @SuppressWarnings("unchecked")
        Map<String, Object> named = (Map<String, Object>) summary.get("realtime_setting");
        assertEquals(s.integrator(), named.get("integrator"));
        assertFalse(named.keySet().stream().anyMatch(k -> k.startsWith("measured")),
                "no figures written from constants (the summary's provenance and timings are the run's own): " + named);
        assertEquals(s.dtS(), ((Number) named.get("dt_s")).doubleValue(), 1e-12);
        if (s.dtS() > 0) {
            assertEquals(s.dtS(), ((Number) summary.get("dt_s")).doubleValue(), 1e-12);
        }
    }

    /**
     * With the fibres the study found a large step within the tolerance; with the pressure it found none, and
     * --realtime --muscle-load pressure runs RK2 at the scene's stable step.
     */
    @Test
    void realtimeWithThePressureRunsRk2AtTheStableStep() throws Exception {
        RealTimeSetting s = RealTimeSetting.forMuscleLoad(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES);
        assertEquals(Integrators.REAL_TIME, s.integrator());
        assertEquals(Integrators.REAL_TIME_STEP_S, s.dtS());
        assertEquals(RealTimeSetting.PRESSURE, RealTimeSetting.forMuscleLoad(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.PRESSURE));
        assertEquals("rk2", RealTimeSetting.PRESSURE.integrator());
        Path mesh = dir.resolve("coarse.obj");
        String[] m = run("diaphragm-mesh", "--rings", "8", "--out", mesh.toString());
        assertEquals("0", m[0], "diaphragm-mesh failed: " + m[2]);
        assertTrue(Files.isRegularFile(mesh), "diaphragm-mesh wrote no " + mesh + ": " + m[2]);
        Path out = dir.resolve("out");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--realtime", "--muscle-load", "pressure",
                "--seconds", "0.2", "--vtk-per-cycle", "0", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> summary = Json.readMap(out.resolve("summary.json"));
        assertEquals("rk2", summary.get("integrator"));
    }

    /**
     * In a thorax, with or without contact, the fibres' load takes the thorax's setting (the links tied, 1 x 8 at
     * 25 ms); another load there has none measured and is refused by name; elsewhere the load's setting.
     */
    @Test
    void aThoraxTakesItsOwnSetting() {
        var fibres = org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES;
        var pressure = org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.PRESSURE;
        assertEquals(RealTimeSetting.THORAX, RealTimeSetting.forScene(fibres, true));
        assertEquals(Integrators.CONTACT_REAL_TIME, RealTimeSetting.THORAX.integrator());
        assertEquals(Integrators.REAL_TIME_STEP_S, RealTimeSetting.THORAX.dtS());
        assertEquals(RealTimeSetting.FIBRES, RealTimeSetting.forScene(fibres, false));
        assertEquals(RealTimeSetting.PRESSURE, RealTimeSetting.forScene(pressure, false));
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> RealTimeSetting.forScene(pressure, true));
        assertTrue(e.getMessage().contains("no real-time setting was measured in a thorax with the pressure load"),
                e.getMessage());
        Map<String, Object> m = RealTimeSetting.THORAX.toMap();
        assertEquals(1.0, ((Number) m.get("link_coupling")).doubleValue(), m.toString());
        assertEquals(Integrators.CONTACT_REAL_TIME_KRYLOV,
                ((Number) m.get("cg_iterations_per_newton_iteration")).intValue(), m.toString());
        assertTrue(m.containsKey("tolerance_against_converged_contact_step") && !m.containsKey("tolerance_against_rk2"),
                m.toString());
        assertTrue(RealTimeSetting.THORAX.describe().contains("links tied in the preconditioner"),
                RealTimeSetting.THORAX.describe());
    }
}
