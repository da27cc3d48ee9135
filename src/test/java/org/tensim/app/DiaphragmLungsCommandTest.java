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
 * takes the organs' integrator and step (bdf2 at 2.5 ms) unless one is given and says so in its summary, and an
 * explicit integrator at the scene's own step, which diverges with the liver within 1 ms, is refused before
 * anything is built. On the decimated BodyParts3D diaphragm; skipped, naming the file, where ../shared is absent.
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

        // --no-liver leaves it out, and then the paper's RK2 at the scene's own step runs.
        s = runLungs("no-liver", "--no-liver", "--integrator", "rk2", "--seconds", "0.0001");
        assertEquals("rk2", s.get("integrator"));
        assertEquals(0, liverNodes(s));
        assertTrue(String.valueOf(s.get("dt_rule")).startsWith("rk2 stable step"), String.valueOf(s.get("dt_rule")));
    }

    @Test
    void anExplicitStepThatDivergesWithTheLiverIsRefusedBeforeTheBuild() {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        String[] r = Commands.run("diaphragm", "--mesh", MESH.toString(), "--units", "mm", "--thorax",
                THORAX.toString(), "--lungs", "--integrator", "rk2", "--out", dir.resolve("a").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].contains("--integrator rk2 at the scene's own step diverges with the liver")
                && r[2].contains("--no-liver") && r[2].contains("--dt"), r[2]);
        assertFalse(Files.exists(dir.resolve("a").resolve("summary.json")), "refused before any run");
        r = Commands.run("diaphragm", "--no-liver", "--out", dir.resolve("b").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].contains("--liver, --no-liver and --lung-probe go with --lungs"), r[2]);
        r = Commands.run("diaphragm", "--mesh", MESH.toString(), "--units", "mm", "--thorax", THORAX.toString(),
                "--lungs", "--no-liver", "--liver-abdomen", "5", "--out", dir.resolve("c").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].contains("--liver-abdomen 5.0") && r[2].contains("with the liver"), r[2]);
    }
}
