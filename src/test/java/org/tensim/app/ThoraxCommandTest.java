package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.io.ProjectFolder;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.ObjWriter;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.mesh.VertexClustering;
import picocli.CommandLine;

/**
 * {@code tensim diaphragm --thorax}: the BodyParts3D diaphragm in the shared thorax at a coarse setting
 * (decimated, a large step), and the options' refusals; skipped, naming the file, where {@code ../shared}
 * is absent.
 */
class ThoraxCommandTest {
    static final Path THORAX = ProjectFolder.resolve("..", "shared", "meshes", "thorax");
    static final Path MESH = ProjectFolder.resolve("..", "shared", "meshes", "bodyparts3d",
            "diaphragm-FJ3131-dec28k-mm.obj");

    @TempDir
    Path dir;

    private static String[] run(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int code = cl.execute(args);
        return new String[] {String.valueOf(code), out.toString(), err.toString()};
    }

    @Test
    void theDecimatedRealDiaphragmBreathesInTheRealThoraxWithoutEnteringTheBones() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        TriangleMesh full = MeshLoader.load(MESH, MeshUnits.parse("mm")).mesh();
        TriangleMesh coarse = VertexClustering.simplify(full, new int[full.vertexCount()], 0.006).mesh();
        Path mesh = dir.resolve("coarse.obj");
        ObjWriter.write(mesh, coarse, MeshUnits.parse("mm"), java.util.List.of(), 4);
        Path out = dir.resolve("run");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--units", "mm", "--thorax", THORAX.toString(),
                "--integrator", "bdf2", "--dt", "0.01", "--seconds", "1.4", "--vtk-per-cycle", "0", "--out",
                out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        System.out.println("coarse BodyParts3D in the thorax: " + s);
        assertEquals("ok", s.get("status"));
        double attached = ((Number) s.get("attached_area_mm2")).doubleValue();
        double area = ((Number) s.get("diaphragm_area_mm2")).doubleValue();
        assertTrue(attached > 0.01 * area && attached < 0.15 * area, "attached " + attached + " of " + area);
        assertTrue(((Number) s.get("contact_pairs")).intValue() > 0);
        // The dome descends, the thorax widens, and no node goes deep into a bone.
        assertTrue(((Number) s.get("dome_excursion_mm")).doubleValue() > 5, s.toString());
        assertTrue(((Number) s.get("ap_extent_change_mm")).doubleValue() > 0, s.toString());
        assertTrue(((Number) s.get("transverse_extent_change_mm")).doubleValue() > 0, s.toString());
        assertTrue(((Number) s.get("max_penetration_past_rest_mm")).doubleValue() < 5, s.toString());
        // The area touching the bones at end-inspiration: some of the muscle, at most the largest over the run.
        double contact = ((Number) s.get("contact_area_mm2")).doubleValue();
        assertTrue(contact > 0 && contact < 0.5 * area, "contact " + contact + " of " + area);
        assertTrue(((Number) s.get("max_contact_area_mm2")).doubleValue() >= contact, s.toString());
        assertTrue(s.containsKey("contact_area_expiration_mm2"), s.toString());
    }

    @Test
    void thoraxOptionsAreCheckedWithClearMessages() {
        String[] r = run("diaphragm", "--model", "paper", "--tissue-model", "springs", "--out",
                dir.resolve("a").toString());
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--model paper sets --tissue-model itself"), r[2]);
        r = run("diaphragm", "--model", "nature", "--out", dir.resolve("b").toString());
        assertTrue(r[2].contains("--model must be default or paper, got 'nature'"), r[2]);
        r = run("diaphragm", "--thorax", dir.toString(), "--boxes", dir.resolve("x.json").toString(), "--out",
                dir.resolve("c").toString());
        assertTrue(r[2].contains("not both"), r[2]);
        r = run("diaphragm", "--thorax", dir.toString(), "--realtime", "--out", dir.resolve("f").toString());
        assertTrue(r[2].contains("--realtime was measured on the double dome"), r[2]);
        r = run("diaphragm", "--newton", "3", "--out", dir.resolve("g").toString());
        assertTrue(r[2].contains("--newton and --cg-iterations apply to --integrator bdf2 only, not rk2"), r[2]);
        r = run("diaphragm", "--tendon-rule", "sphere", "--out", dir.resolve("d").toString());
        assertTrue(r[2].contains("sphere") && r[2].contains("plane, geodesic"), r[2]);
        r = run("diaphragm", "--thorax", dir.resolve("none").toString(), "--seconds", "0.01", "--out",
                dir.resolve("e").toString());
        assertEquals("1", r[0]);
        assertTrue(r[2].contains("parts.json"), r[2]);
        assertFalse(r[2].contains("\tat "), "no stack trace: " + r[2]);
    }
}
