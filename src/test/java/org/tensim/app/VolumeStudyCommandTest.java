package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code volume-study}: its files, its summary's figures, and one-line refusals. */
class VolumeStudyCommandTest {
    private static String[] run(String... args) {
        return Commands.runCapturingSystemOut(args);
    }

    @Test
    void writesTheTablesAndASummaryWithTheErrorsAndOrders(@TempDir Path dir) throws Exception {
        String[] r = run("volume-study", "--cantilever-cells", "1,2,4", "--block-cells", "1.5,2.5", "--fits",
                "isotropic", "--out", dir.toString());
        assertEquals("0", r[0], r[2]);
        assertEquals(1 + 3, Files.readAllLines(dir.resolve("volume-cantilever.csv")).size());
        assertEquals(1 + 2, Files.readAllLines(dir.resolve("volume-block.csv")).size());
        assertTrue(Files.size(dir.resolve("volume-convergence.png")) > 1000);
        JsonNode s = new ObjectMapper().readTree(dir.resolve("summary.json").toFile());
        assertEquals("ok", s.get("status").asText());
        JsonNode iso = s.get("isotropic");
        assertEquals(0.25, iso.get("model_poisson").asDouble(), 1e-12);
        JsonNode beam = iso.get("cantilever");
        assertEquals(3, beam.get("error_vs_euler_bernoulli").size());
        double coarse = beam.get("error_vs_euler_bernoulli").get(0).asDouble();
        double fine = beam.get("finest_error").asDouble();
        assertTrue(coarse < fine && fine < 0, "a finer beam is closer to Euler-Bernoulli, from below: " + beam);
        assertTrue(beam.get("observed_order").get(0).asDouble() > 0, beam.toString());
        assertEquals(0.25, iso.get("block").get("measured_poisson").get(1).asDouble(), 0.01);
        assertEquals(0.4, iso.get("block").get("requested_poisson").asDouble(), 0);
    }

    @Test
    void badOptionsAreRefusedInOneLine(@TempDir Path dir) {
        String[] r = run("volume-study", "--cantilever-cells", "2,3", "--out", dir.toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].contains("each twice the last") && !r[2].contains("\tat "), r[2]);
        String[] f = run("volume-study", "--fits", "cubic", "--out", dir.toString());
        assertTrue(f[2].contains("spring fit must be 'isotropic', 'axial' or 'volumetric', got 'cubic'"), f[2]);
        String[] m = run("volume-study", "--mesh", dir.resolve("none.obj").toString(), "--out", dir.toString());
        assertTrue(!"0".equals(m[0]) && m[2].contains("none.obj") && !m[2].contains("\tat "), m[2]);
    }

    @Test
    void theTetrahedralVariantRunsTheSameStudyAndBuildsMeshFiles(@TempDir Path dir) throws Exception {
        String[] r = run("volume-study", "--tets", "--cantilever-cells", "1,2", "--block-cells", "1,2", "--out",
                dir.toString());
        assertEquals("0", r[0], r[2]);
        JsonNode s = new ObjectMapper().readTree(dir.resolve("summary.json").toFile());
        JsonNode tets = s.get("tets-five");
        assertEquals(2, tets.get("cantilever").get("error_vs_euler_bernoulli").size(), tets.toString());
        // five tets a cube: the network's Poisson ratio is below the target's 1/4 (0.172 at 2 cubes across)
        assertEquals(0.172, tets.get("block").get("measured_poisson").get(1).asDouble(), 0.005);
        String[] bad = run("volume-study", "--tets", "seven", "--out", dir.toString());
        assertTrue(bad[2].contains("--tets must be 'six' or 'five', got 'seven'"), bad[2]);
        String[] axial = run("volume-study", "--tets", "--fits", "axial", "--out", dir.toString());
        assertTrue(axial[2].contains("--tets takes the isotropic fit only"), axial[2]);
        String[] jitter = run("volume-study", "--jitter", "0.1", "--out", dir.toString());
        assertTrue(jitter[2].contains("--jitter must be 0 to 0.15, with --tets, got 0.1"), jitter[2]);
        String[] half = run("volume-study", "--tets", "--block-cells", "2.5", "--out", dir.toString());
        assertTrue(half[2].contains("--tets needs whole --block-cells"), half[2]);
        Path msh = Path.of(VolumeStudyCommandTest.class.getResource("/org/tensim/io/mesh/cube5.msh").toURI());
        Path out = dir.resolve("mesh");
        String[] m = run("volume-study", "--mesh", msh.toString(), "--out", out.toString());
        assertEquals("0", m[0], m[2]);
        JsonNode built = new ObjectMapper().readTree(out.resolve("summary.json").toFile()).get("meshes").get(0);
        assertEquals("tets", built.get("variant").asText());
        assertEquals(8, built.get("nodes").asInt());
        assertEquals(18, built.get("springs").asInt(), "the cube's 12 edges and 6 face diagonals");
        assertEquals(1e-3, built.get("mass_kg").asDouble(), 1e-12, "1 cm^3 at 1000 kg/m^3");
    }

    @Test
    void refinesAScenesVolumeBodyAndWritesItsTable(@TempDir Path dir) throws Exception {
        String[] r = run("volume-study", "--scene", "docs/examples/cantilever.yaml", "--refine", "1", "--out",
                dir.toString());
        assertEquals("0", r[0], r[2]);
        assertEquals(1 + 1, Files.readAllLines(dir.resolve("volume-scene.csv")).size());
        JsonNode s = new ObjectMapper().readTree(dir.resolve("summary.json").toFile());
        assertEquals("cantilever", s.get("kind").asText());
        assertEquals(-0.187, s.get("finest_error").asDouble(), 0.01);
        String[] bad = run("volume-study", "--scene", "docs/examples/cube.yaml", "--out", dir.resolve("b").toString());
        assertTrue(!"0".equals(bad[0]) && bad[2].contains("expected one volume body"), bad[2]);
        assertTrue(!bad[2].contains("\tat org."), "no stack trace: " + bad[2]);
        String[] zero = run("volume-study", "--scene", "docs/examples/cantilever.yaml", "--refine", "0,1", "--out",
                dir.resolve("z").toString());
        assertTrue(!"0".equals(zero[0]) && zero[2].contains("--refine must be whole numbers >= 1, got [0, 1]"),
                zero[2]);
    }
}
