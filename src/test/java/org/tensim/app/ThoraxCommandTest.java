package org.tensim.app;

import org.tensim.testsupport.Commands;
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
import org.tensim.testsupport.CoarseMeshes;

/**
 * {@code tensim diaphragm --thorax}: the BodyParts3D diaphragm in the shared thorax at a coarse setting
 * (decimated, a large step), and the options' refusals; skipped, naming the file, where {@code ../shared}
 * is absent.
 */
class ThoraxCommandTest {
    static final Path THORAX = org.tensim.testsupport.SharedData.THORAX;
    static final Path MESH = org.tensim.testsupport.SharedData.BODYPARTS3D_DIAPHRAGM;

    @TempDir
    Path dir;

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    /**
     * The mesh decimated face by face (the two faces of the 3 mm shell must not merge: a single group would
     * fold them into a non-manifold sheet), at a large step with the thorax's default converged bdf2.
     */
    private Path coarseMesh() throws Exception {
        return CoarseMeshes.faceByFace(MESH, 0.006, dir.resolve("coarse.obj"));
    }

    private Map<String, Object> inspire(Path mesh, String name, String... extra) throws Exception {
        Path out = dir.resolve(name);
        java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("diaphragm", "--mesh",
                mesh.toString(), "--units", "mm", "--thorax", THORAX.toString(), "--integrator", "bdf2", "--dt",
                "0.01", "--seconds", "1.4", "--vtk-per-cycle", "0", "--out", out.toString()));
        args.addAll(java.util.List.of(extra));
        String[] r = run(args.toArray(String[]::new));
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        System.out.println("coarse BodyParts3D in the thorax (" + name + "): " + s);
        assertEquals("ok", s.get("status"));
        return s;
    }

    private static double num(Map<String, Object> s, String key) {
        return ((Number) s.get(key)).doubleValue();
    }

    @Test
    void theDecimatedRealDiaphragmBreathesInTheRealThoraxWithoutEnteringTheBones() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        Path mesh = coarseMesh();
        Map<String, Object> s = inspire(mesh, "breathing");
        assertEquals(PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS, ((Number) s.get("newton_iterations")).intValue());
        double attached = num(s, "attached_area_mm2");
        double area = num(s, "diaphragm_area_mm2");
        assertTrue(attached > 0.01 * area && attached < 0.15 * area, "attached " + attached + " of " + area);
        assertTrue(((Number) s.get("contact_pairs")).intValue() > 0);
        // The dome descends, the thorax widens, the ribs lift the cartilage, and no node goes into a bone
        // further than the penalty's few tenths of a millimetre past where it started.
        assertTrue(num(s, "right_dome_descent_mm") > 3, s.toString());
        assertTrue(num(s, "left_dome_descent_mm") > 1, s.toString());
        assertTrue(num(s, "ap_extent_change_mm") > 0, s.toString());
        assertTrue(num(s, "transverse_extent_change_mm") > 0, s.toString());
        assertTrue(num(s, "cartilage_marker_cranial_mm") > 0 && num(s, "cartilage_marker_ventral_mm") > 0,
                s.toString());
        assertTrue(num(s, "max_penetration_past_rest_mm") < 1, s.toString());
        // The area touching the bones at end-inspiration: some of the muscle, at most the largest over the run.
        double contact = num(s, "contact_area_mm2");
        assertTrue(contact > 0 && contact < 0.5 * area, "contact " + contact + " of " + area);
        assertTrue(num(s, "max_contact_area_mm2") >= contact, s.toString());
        assertTrue(s.containsKey("contact_area_expiration_mm2"), s.toString());
        // displacements.csv gives each node's distance to its nearest bone: at rest within the 15 mm contact range
        // for every node that has one, and no deeper than the registration's overlap plus the penetration past it.
        java.util.List<String> lines = Files.readAllLines(dir.resolve("breathing").resolve("displacements.csv"));
        java.util.List<String> header = java.util.List.of(lines.get(0).split(","));
        int gapAt = header.indexOf("bone_gap_m");
        int restAt = header.indexOf("bone_gap_rest_m");
        assertTrue(gapAt > 0 && restAt > 0, lines.get(0));
        int withGap = 0;
        for (String line : lines.subList(1, lines.size())) {
            String[] c = line.split(",");
            double gap = Double.parseDouble(c[gapAt]);
            double rest = Double.parseDouble(c[restAt]);
            assertEquals(Double.isNaN(gap), Double.isNaN(rest), line);
            if (!Double.isNaN(rest)) {
                withGap++;
                assertTrue(rest < 0.015, line);
                assertTrue(gap > Math.min(0, rest) - 1e-3 * (num(s, "max_penetration_past_rest_mm") + 0.01), line);
            }
        }
        assertTrue(withGap > 0 && withGap < lines.size() - 1, withGap + " of " + (lines.size() - 1));
        // With the muscle off and the ribs breathing, the converged step keeps the dome's top where the ribs
        // leave it (lifted by a millimetre or so with the costal margin): the single-iteration step let it
        // sink 3.5 mm by 1.4 s under the contact's residual.
        Map<String, Object> still = inspire(mesh, "ribs-only", "--muscle-force", "0");
        for (String dome : new String[] {"right_dome_descent_mm", "left_dome_descent_mm"}) {
            assertTrue(num(still, dome) < 0.5 && num(still, dome) > -2, dome + ": " + still);
        }
        assertTrue(num(s, "right_dome_descent_mm") > 3 * Math.abs(num(still, "right_dome_descent_mm")));
    }

    @Test
    void theResolutionStudyRunsInTheThoraxWithTheSceneDefinitionAndTheGivenStep() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        Path mesh = coarseMesh();
        Path out = dir.resolve("study");
        String[] r = run("diaphragm", "resolution-study", "--mesh", mesh.toString(), "--units", "mm", "--thorax",
                THORAX.toString(), "--integrator", "bdf2", "--dt", "0.01", "--decimation", "quadric", "--cells", "12",
                "--seconds", "0.3", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("resolution.json"));
        assertEquals(THORAX.toString(), s.get("thorax"));
        assertEquals("bdf2", s.get("integrator"));
        java.util.List<?> models = (java.util.List<?>) s.get("models");
        assertEquals(2, models.size(), s.toString());
        for (Object m : models) {
            Map<?, ?> row = (Map<?, ?>) m;
            // every model in the thorax breathes at the step given, not RK2's stable step
            assertEquals(0.01, ((Number) row.get("dt_s")).doubleValue(), 1e-12, row.toString());
        }
        assertEquals("quadric edge 12.0 mm", ((Map<?, ?>) models.get(0)).get("model"));
        // where the coarse model's error sits: cells with shares of it, largest first, together at most all of it
        java.util.List<?> hot = (java.util.List<?>) ((Map<?, ?>) models.get(0)).get("error_hotspots");
        assertTrue(hot != null && !hot.isEmpty(), models.get(0).toString());
        double sum = 0;
        double last = 1;
        for (Object cell : hot) {
            double share = ((Number) ((Map<?, ?>) cell).get("share")).doubleValue();
            assertTrue(share > 0 && share <= last, hot.toString());
            last = share;
            sum += share;
        }
        assertTrue(sum <= 1 + 1e-9, hot.toString());
        assertTrue(Files.readAllLines(out.resolve("resolution-nodes.csv")).get(0).endsWith(
                ",difference_mm quadric edge 12.0 mm"), "the nodes file's columns");
        r = run("diaphragm", "resolution-study", "--thorax", THORAX.toString(), "--out",
                dir.resolve("no-mesh").toString());
        assertTrue(r[2].contains("the resolution study with --thorax needs --mesh"), r[2]);
        r = run("diaphragm", "resolution-study", "--mesh", mesh.toString(), "--labels", mesh.toString(), "--out",
                dir.resolve("labels").toString());
        assertTrue(r[2].contains("--labels cannot go with the resolution study"), r[2]);
        r = run("diaphragm", "resolution-study", "--mesh", mesh.toString(), "--decimation", "octree", "--out",
                dir.resolve("octree").toString());
        assertTrue(r[2].contains("unknown Decimation model 'octree'; expected one of clustering, quadric"), r[2]);
        r = run("diaphragm", "resolution-study", "--decimation", "quadric", "--out", dir.resolve("quadric").toString());
        assertTrue(r[2].contains("--decimation quadric needs --mesh"), r[2]);
    }

    /**
     * {@code --realtime} takes the swept cage (with the contact projection the real-time step keeps the diaphragm out
     * of the bones, docs/thorax.md): the real-time setting's one Newton iteration of four CG iterations at 25 ms,
     * the nodes no deeper than 0.1 mm past their rest into a bone (the converged step went 0.3 mm in before the
     * projection, the real-time step 1.0 mm).
     */
    @Test
    void realTimeRunsTheSweptCage() throws Exception {
        Path out = dir.resolve("rt-surfaces");
        String[] r = run("diaphragm", "--cage", "surfaces", "--realtime", "--rings", "12", "--seconds", "1.4",
                "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("ok", s.get("status"));
        assertEquals(PrefactoredBdf2.NAME, s.get("integrator"));
        assertEquals(0.025, ((Number) s.get("dt_s")).doubleValue(), 1e-12);
        assertEquals(PrefactoredBdf2.DEFAULT_KRYLOV_ITERATIONS, ((Number) s.get("cg_iterations_cap")).intValue());
        assertTrue(s.containsKey("realtime_setting"), s.toString());
        double past = ((Number) s.get("max_penetration_past_rest_mm")).doubleValue();
        double apex = ((Number) s.get("apex_descent_mm")).doubleValue();
        assertTrue(past <= 0.1, "past rest into a bone: " + past + " mm");
        assertTrue(apex > 3, "the dome descends: " + apex + " mm");
    }

    /**
     * {@code --realtime} in the thorax runs its own setting ({@code bdf2-contact-realtime}: 1 Newton x 8 CG at 25 ms,
     * the links tied in the preconditioner), and the real-time study with {@code --thorax} compares it with the
     * converged contact step at 5 ms and times it with and without contact, on the coarse mesh.
     */
    @Test
    void realTimeAndItsStudyRunInTheThorax() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        Path mesh = coarseMesh();
        Path out = dir.resolve("rt");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--units", "mm", "--thorax", THORAX.toString(),
                "--realtime", "--seconds", "1.4", "--vtk-per-cycle", "0", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        assertEquals("ok", s.get("status"));
        assertEquals(org.tensim.solver.integrators.Integrators.CONTACT_REAL_TIME_NEWTON,
                ((Number) s.get("newton_iterations")).intValue(), s.toString());
        assertEquals(org.tensim.solver.integrators.Integrators.CONTACT_REAL_TIME_KRYLOV,
                ((Number) s.get("cg_iterations_cap")).intValue(), s.toString());
        Map<?, ?> setting = (Map<?, ?>) s.get("realtime_setting");
        assertTrue(setting.get("link_coupling") instanceof Number, setting.toString());
        assertEquals(org.tensim.solver.integrators.Integrators.CONTACT_REAL_TIME, setting.get("integrator"));
        assertEquals(1.0, ((Number) setting.get("link_coupling")).doubleValue(), setting.toString());
        assertTrue(num(s, "max_penetration_past_rest_mm") < 1, s.toString());
        assertTrue(num(s, "right_dome_descent_mm") > 3, s.toString());

        Path study = dir.resolve("rt-study");
        r = run("diaphragm", "realtime-study", "--mesh", mesh.toString(), "--units", "mm", "--thorax",
                THORAX.toString(), "--seconds", "0.2", "--study-configs", "contact-realtime", "--out",
                study.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> j = Json.readMap(study.resolve("realtime.json"));
        java.util.List<?> rows = (java.util.List<?>) j.get("runs");
        java.util.List<Object> labels = new java.util.ArrayList<>();
        for (Object row : rows) {
            labels.add(((Map<?, ?>) row).get("config"));
        }
        assertEquals(java.util.List.of("bdf2-contact at 5 ms / 2 threads (reference)",
                "bdf2-contact-realtime at 25 ms / 2 threads", "bdf2-contact-realtime at 25 ms without tied links / 2"
                        + " threads", "bdf2-contact-realtime at 25 ms without contact / 2 threads"), labels);
        Map<?, ?> ref = (Map<?, ?>) rows.get(0);
        assertTrue(ref.get("error_vs_reference") instanceof Number, ref.toString());
        assertEquals(0.0, ((Number) ref.get("error_vs_reference")).doubleValue(), ref.toString());
        Map<?, ?> rt = (Map<?, ?>) j.get("realtime_setting");
        for (String key : new String[] {"error_vs_reference", "worst_error_vs_reference", "ms_per_step",
            "ms_per_step_without_contact", "realtime_factor", "realtime_factor_without_contact"}) {
            assertTrue(rt.get(key) instanceof Number, key + " " + j);
            double v = ((Number) rt.get(key)).doubleValue();
            assertTrue(Double.isFinite(v) && v >= 0, key + " " + rt);
        }
        assertTrue(((Number) rt.get("ms_per_step")).doubleValue() > 0, rt.toString());
        assertEquals(5, Files.readAllLines(study.resolve("realtime.csv")).size(), "a header and four rows");
        try (var kept = Files.list(study)) {
            assertEquals(1, kept.filter(f -> f.getFileName().toString().startsWith("bdf2-contact-reference-")).count(),
                    "the reference's samples kept for the next study");
        }
        r = run("diaphragm", "realtime-study", "--mesh", mesh.toString(), "--units", "mm", "--thorax",
                THORAX.toString(), "--study-rings", "10,14", "--out", dir.resolve("rings").toString());
        assertTrue(r[2].contains("with --thorax the real-time study runs the one scene given, with contact: leave out"
                + " --study-rings"), r[2]);
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
        r = run("diaphragm", "--thorax", dir.toString(), "--realtime", "--muscle-load", "pressure", "--out",
                dir.resolve("f").toString());
        assertTrue(r[2].contains("--realtime: no real-time setting was measured in a thorax with the pressure load;"
                + " use --muscle-load fibres"), r[2]);
        // The swept cage has bone surfaces and contact too: the band's studies do not take it.
        r = run("diaphragm", "realtime-study", "--cage", "surfaces", "--out", dir.resolve("i").toString());
        assertTrue(r[2].contains("leave out --mesh, --cage surfaces and --labels, or add --thorax"), r[2]);
        r = run("diaphragm", "resolution-study", "--cage", "surfaces", "--out", dir.resolve("j").toString());
        assertTrue(r[2].contains("--cage surfaces cannot go with the resolution study"), r[2]);
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
