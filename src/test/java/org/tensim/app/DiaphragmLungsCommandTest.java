package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.solver.prefactored.PrefactoredBdf2;
import org.tensim.testsupport.Commands;
import org.tensim.testsupport.CoarseMeshes;

/**
 * {@code tensim diaphragm --thorax DIR --lungs}: the liver comes with the lungs unless {@code --no-liver}, the run
 * takes the organs' integrator and step (bdf2 at 2.5 ms) unless one is given and says so in its summary, and the
 * liver's options out of place are refused. On the decimated BodyParts3D diaphragm; skipped, naming the file, where
 * ../shared is absent.
 */
class DiaphragmLungsCommandTest {
    static final Path THORAX = org.tensim.testsupport.SharedData.THORAX;
    static final Path MESH = org.tensim.testsupport.SharedData.BODYPARTS3D_DIAPHRAGM;

    @TempDir
    Path dir;

    private Map<String, Object> runLungs(String name, String... extra) throws Exception {
        Path mesh = dir.resolve("coarse.obj");
        if (!Files.exists(mesh)) {
            CoarseMeshes.faceByFace(MESH, 0.006, mesh);
        }
        Path out = dir.resolve(name);
        java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("diaphragm", "--mesh",
                mesh.toString(), "--units", "mm", "--thorax", THORAX.toString(), "--lungs", "--vtk-per-cycle", "0",
                "--threads", "1", "--out", out.toString()));
        args.addAll(java.util.List.of(extra));
        String[] r = Commands.run(args.toArray(String[]::new));
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("ok", s.get("status"), name + ": " + s.get("diverged"));
        return s;
    }

    @SuppressWarnings("unchecked")
    private static int liverNodes(Map<String, Object> s) {
        return ((Number) ((Map<String, Object>) s.get("organs")).get("liver_nodes")).intValue();
    }

    @Test
    void theLungsTakeTheLiverAndTheOrgansStepUnlessToldOtherwise() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        Map<String, Object> s = runLungs("defaults", "--seconds", "0.005");
        assertEquals(PrefactoredBdf2.NAME, s.get("integrator"));
        assertEquals(DiaphragmSolverOptions.ORGANS_DT_S, ((Number) s.get("dt_s")).doubleValue(), 1e-15);
        assertTrue(String.valueOf(s.get("dt_rule")).contains("with --lungs and neither --integrator nor --dt: bdf2 at"
                + " 0.0025 s"), "the summary says why: " + s.get("dt_rule"));
        assertTrue(liverNodes(s) > 100, "the liver is built by default: " + liverNodes(s));

        // An integrator given stands, at the scene's own step: the paper's RK2 with the liver (its contact once
        // diverged within 1 ms at a fold of the diaphragm's lower surface, docs/lungs.md).
        s = runLungs("rk2", "--integrator", "rk2", "--seconds", "0.001");
        assertEquals("rk2", s.get("integrator"));
        assertTrue(String.valueOf(s.get("dt_rule")).startsWith("rk2 stable step"), String.valueOf(s.get("dt_rule")));
        assertTrue(liverNodes(s) > 100);
        @SuppressWarnings("unchecked")
        Map<String, Object> omega = (Map<String, Object>) s.get("omega_measured_with_terms");
        assertTrue(((Number) omega.get("omega_rad_s")).doubleValue() <= ((Number) s.get("omega_max_bound_rad_s"))
                .doubleValue(), "the organs' terms leave the frequency under the scene's own bound: " + omega);

        // --no-liver leaves it out.
        s = runLungs("no-liver", "--no-liver", "--seconds", "0.005");
        assertEquals(0, liverNodes(s));
    }

    @Test
    void liverOptionsOutOfPlaceAreRefused() {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        String[] r;
        r = Commands.run("diaphragm", "--no-liver", "--out", dir.resolve("b").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].contains("--liver, --no-liver and --lung-probe go with --lungs"), r[2]);
        r = Commands.run("diaphragm", "--mesh", MESH.toString(), "--units", "mm", "--thorax", THORAX.toString(),
                "--lungs", "--no-liver", "--liver-abdomen", "5", "--out", dir.resolve("c").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].contains("--liver-abdomen 5.0") && r[2].contains("with the liver"), r[2]);
    }
}
