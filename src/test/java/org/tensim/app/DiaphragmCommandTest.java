package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.io.Json;
import org.tensim.solver.parallel.Parallelism;

/** The diaphragm command end to end on a coarse mesh, and its error messages. */
class DiaphragmCommandTest {
    @TempDir
    Path dir;

    // The PNG charts are drawn into images, which Java2D does without a display (headless): these
    // tests need none and are never skipped. With a display given, AWT failing to start is a failure.

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    /** A generated mesh of the given rings in the test folder. */
    private Path coarseMesh(int rings) {
        Path mesh = dir.resolve("coarse-" + rings + ".obj");
        assertEquals("0", run("diaphragm-mesh", "--rings", String.valueOf(rings), "--out", mesh.toString())[0]);
        return mesh;
    }

    @Test
    void aRunShorterThanAnInspirationSucceedsAndSaysTheBreathingWasNotMeasured() throws Exception {
        Path mesh = coarseMesh(6);
        Path out = dir.resolve("short");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--seconds", "0.2", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertFalse(s.containsKey("dome_excursion_mm"), s.toString());
        assertTrue(String.valueOf(s.get("breathing")).startsWith("not measured: the run of 0.2 s"), s.toString());
        assertEquals(0.2, ((Number) s.get("simulated_s")).doubleValue(), 1e-3);
        // the displacement CSV holds the end of the run: a header and one row per diaphragm node
        int nodes = ((Number) s.get("diaphragm_nodes")).intValue();
        assertEquals(1 + nodes, Files.readAllLines(out.resolve("displacements.csv")).size());
    }

    @Test
    void writesEveryOutputAndASummaryWithTheIssuesKeys() throws Exception {
        Path mesh = coarseMesh(10);
        Path out = dir.resolve("out");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--seconds", "1.4", "--out", out.toString(),
                "--vtk-per-cycle", "4");
        assertEquals("0", r[0], r[2]);
        for (String f : List.of("summary.json", "displacements.csv", "probe.csv", "sagittal.png", "axial.png",
                "sagittal-cycle.png", "axial-cycle.png", "breathing.png", "vtk/diaphragm.pvd",
                "vtk/diaphragm_0000.vtk", "vtk/diaphragm_0001.vtk")) {
            assertTrue(Files.size(out.resolve(f)) > 0, f);
        }
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        for (String k : List.of("nodes", "springs", "rigid_links", "attached_nodes", "dome_excursion_mm",
                "ap_extent_change_mm", "transverse_extent_change_mm", "vertical_extent_change_mm", "steps_per_s",
                "realtime_factor")) {
            assertTrue(s.containsKey(k), k);
        }
        assertTrue(((Number) s.get("dome_excursion_mm")).doubleValue() > 5);
        // the default muscle load: the fibres' active tension at its 15 kPa
        assertEquals("fibres", s.get("muscle_load"), s.toString());
        assertEquals(DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, ((Number) s.get("muscle_force_pa")).doubleValue(), 0);
        // No region of the double dome snaps through at the default load: with the pressure its largest descent
        // was 1.76 times the dome excursion here (25.7 against 14.6 mm, 2026-11-23); a snapped region goes far
        // lower (BodyParts3D at 7.5 kPa: 100 mm against 18).
        double largest = ((Number) s.get("largest_descent_mm")).doubleValue();
        assertTrue(largest >= ((Number) s.get("apex_descent_mm")).doubleValue()
                && largest < 2.5 * ((Number) s.get("dome_excursion_mm")).doubleValue(), s.toString());
        // displacements.csv: a header and one row per diaphragm node per time (two times by default)
        long rows = Files.lines(out.resolve("displacements.csv")).count() - 1;
        assertEquals(2L * ((Number) s.get("diaphragm_nodes")).longValue(), rows);
        assertEquals(((Number) s.get("springs")).intValue() >= Parallelism.AUTO_PARALLEL_SPRINGS
                ? Parallelism.availableCores() : 1, ((Number) s.get("threads")).intValue(),
                "automatic: one thread for a small scene, all cores from the threshold");

        // Another integrator with its CG tolerance, on one thread: the same physiology within a few mm.
        Path out2 = dir.resolve("implicit");
        r = run("diaphragm", "--mesh", mesh.toString(), "--seconds", "1.4", "--out", out2.toString(),
                "--vtk-per-cycle", "0", "--integrator", "implicit-euler", "--dt", "0.0005", "--cg-tolerance", "1e-6",
                "--threads", "1");
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s2 = Json.readMap(out2.resolve("summary.json"));
        assertEquals("implicit-euler", s2.get("integrator"));
        assertEquals(1, ((Number) s2.get("threads")).intValue());
        assertTrue(((Number) s2.get("cg_products_per_step")).doubleValue() > 0);
        assertEquals(((Number) s.get("dome_excursion_mm")).doubleValue(),
                ((Number) s2.get("dome_excursion_mm")).doubleValue(), 2.0);
    }

    /** The tendon plane and the action lines are settable from the command line, and act. */
    @Test
    void tendonPlaneAndActionLinesAreSettable() throws Exception {
        // 16 rings: below about 14 the coarse dome's response is erratic (docs/diaphragm.md).
        Path mesh = coarseMesh(16);
        Path a = dir.resolve("a");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--seconds", "1.4", "--out", a.toString(),
                "--vtk-per-cycle", "0", "--tendon-fraction", "0.2", "--threads", "1", "--muscle-load", "pressure");
        assertEquals("0", r[0], r[2]);
        Map<String, Object> sa = Json.readMap(a.resolve("summary.json"));
        assertEquals(0.2, ((Number) sa.get("tendon_area_fraction")).doubleValue(), 0.03);
        // One narrow action line far outside the diaphragm: the muscle pulls nothing, the dome stays up. Action
        // lines place the pressure's traction (the fibres' tension has none): both runs with the pressure load,
        // which the figures below were measured with.
        Path b = dir.resolve("b");
        r = run("diaphragm", "--mesh", mesh.toString(), "--seconds", "1.4", "--out", b.toString(),
                "--vtk-per-cycle", "0", "--action-line", "500,500,10", "--threads", "1", "--muscle-load", "pressure");
        assertEquals("0", r[0], r[2]);
        Map<String, Object> sb = Json.readMap(b.resolve("summary.json"));
        // The apex at end-inspiration (its travel over the run also counts the ribs' transient lift:
        // 4.6-7.8 mm without the muscle against 13.6-16.1 mm with it, measured 2026-11-23 17:10 UTC;
        // end-inspiration descent 0.8-1.0 mm against 12.2-12.7 mm).
        assertTrue(Math.abs(((Number) sb.get("apex_descent_mm")).doubleValue()) < 0.3
                * ((Number) sa.get("apex_descent_mm")).doubleValue(), sb + " vs " + sa);
        r = run("diaphragm", "--tendon-normal", "0,0,0");
        assertTrue(r[2].contains("--tendon-normal must not be the zero vector"), r[2]);
        r = run("diaphragm", "--action-line", "1,2");
        assertTrue(r[2].contains("expected X,Y,R in mm"), r[2]);
        r = run("diaphragm", "--action-line", "500,500,10");
        assertTrue(r[2].contains("--action-line") && r[2].contains("'fibres'") && r[2].contains("pressure"), r[2]);
    }

    @Test
    void aDivergingRunStopsWithOneLineAndKeepsWhatItWrote() throws Exception {
        Path mesh = dir.resolve("coarse.obj");
        run("diaphragm-mesh", "--rings", "8", "--out", mesh.toString());
        Path out = dir.resolve("diverged");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--seconds", "1.4", "--dt", "0.002", "--out",
                out.toString());
        assertEquals("1", r[0]);
        assertTrue(r[2].contains("diverged") && r[2].contains("reduce the time step"), r[2]);
        assertFalse(r[2].contains("\tat "), r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("diverged", s.get("status"));
        assertTrue(s.containsKey("diverged"));
        assertTrue(Files.size(out.resolve("probe.csv")) > 0);
        assertTrue(Files.isRegularFile(out.resolve("vtk/diaphragm_0000.vtk")));
    }

    @Test
    void aSingleSurfaceMeshIsOffset() throws Exception {
        Path mesh = dir.resolve("upper.obj");
        org.tensim.io.mesh.ObjWriter.write(mesh, org.tensim.scene.diaphragm.DoubleDomeGenerator.upperSurface(
                org.tensim.scene.diaphragm.DoubleDomeGenerator.Shape.adult().withRings(8)),
                org.tensim.io.mesh.MeshUnits.MM, List.of(), 4);
        DiaphragmSetup.Built b = DiaphragmSetup.load(mesh, org.tensim.io.mesh.MeshUnits.MM, 0.002,
                null, org.tensim.scene.diaphragm.DiaphragmParameters.defaults(),
                org.tensim.scene.diaphragm.BreathingCycle.quiet(),
                new org.tensim.scene.diaphragm.DiaphragmControls(1, DiaphragmSetup.defaultMusclePa()));
        assertEquals(DiaphragmSetup.SurfaceMode.OFFSET, b.mode());
        assertEquals(0.002, b.scene().surfaces().thicknessM(), 1e-4);
    }

    @Test
    void badInputGivesOneClearLineAndNoStackTrace() throws Exception {
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
        String[] r = run("diaphragm", "--mesh", bad.toString(), "--out", dir.resolve("o").toString());
        assertEquals("1", r[0]);
        assertTrue(r[2].contains("bad.obj, line 4") && r[2].contains("expected 1..3"), r[2]);
        assertFalse(r[2].contains("\tat "), "no stack trace: " + r[2]);
        r = run("diaphragm", "--units", "inch");
        assertEquals("2", r[0], "a bad option value is a usage error");
        assertTrue(r[2].contains("mesh units must be 'mm' or 'm', got 'inch'"), r[2]);
        r = run("diaphragm", "--rib-amplitude", "5");
        assertTrue(r[2].contains("rib amplitude must be at most 3"), r[2]);
        r = run("diaphragm", "--cg-tolerance", "1e-3");
        assertTrue(r[2].contains("--cg-tolerance applies to --integrator implicit-euler only, not rk2"), r[2]);
        r = run("diaphragm", "--threads", "-1");
        assertTrue(r[2].contains("--threads -1: expected 0 (automatic) or 1 to"), r[2]);
        r = run("diaphragm", "--integrator", "implicit-euler", "--cg-tolerance", "-1");
        assertTrue(r[2].contains("-1"), r[2]);
        assertFalse(r[2].contains("\tat "), "no stack trace: " + r[2]);
    }
}
