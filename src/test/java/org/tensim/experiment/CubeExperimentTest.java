package org.tensim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.scene.CubeParameters;

/** The paper's Fig. 3 regression: the tensegrity cube keeps its shape, the mass-spring cube is crushed. */
class CubeExperimentTest {
    @Test
    void peaksLandNearThePapersAndTensegrityIsFiftyTimesStiffer() throws IOException {
        CubeExperiment.Result r = new CubeExperiment(CubeParameters.paper()).run((t, m, s) -> { });
        assertTrue(r.mssPeakY() >= -10 && r.mssPeakY() <= -6, "MSS peak Y (paper -8 m): " + r.mssPeakY());
        assertTrue(r.tsPeakY() >= -0.1 && r.tsPeakY() <= -0.05, "TS peak Y (paper -0.075 m): " + r.tsPeakY());
        assertTrue(Math.abs(r.tsPeakY()) * 50 <= Math.abs(r.mssPeakY()),
                "TS peak at least 50 times smaller: " + r.mssPeakY() / r.tsPeakY());
        assertTrue(r.tsMaxLinkError() <= 1e-9, "struts keep their length: " + r.tsMaxLinkError());
    }

    @Test
    void resultIsConvergedInTheTimeStep() throws IOException {
        CubeParameters p = CubeParameters.paper().withDuration(2.5);
        CubeExperiment.Result a = new CubeExperiment(p).run((t, m, s) -> { });
        CubeExperiment.Result b = new CubeExperiment(p.withTimeStep(p.dtS() / 2)).run((t, m, s) -> { });
        assertEquals(a.mssPeakY(), b.mssPeakY(), 1e-3 * Math.abs(a.mssPeakY()));
        assertEquals(a.tsPeakY(), b.tsPeakY(), 1e-2 * Math.abs(a.tsPeakY()));
    }

    @Test
    void reportWritesCsvChartAndSummary(@TempDir Path dir) throws Exception {
        CubeParameters p = CubeParameters.paper().withDuration(0.5);
        CubeReport r = CubeReport.run(p, dir);
        List<String> lines = Files.readAllLines(dir.resolve("cube.csv"));
        assertEquals("t_s,mss_dx_m,mss_dy_m,mss_dz_m,ts_dx_m,ts_dy_m,ts_dz_m", lines.get(0));
        assertEquals(p.steps() + 2, lines.size(), "header, t = 0 and one row per step");
        assertTrue(Files.size(dir.resolve("cube.png")) > 1000);
        Map<String, Object> s = Json.readMap(dir.resolve("summary.json"));
        assertEquals("ok", s.get("status"));
        for (String key : List.of("mss_peak_y_m", "ts_peak_y_m", "paper_mss_peak_y_m", "paper_ts_peak_y_m", "steps",
                "dt_s", "wall_s")) {
            assertTrue(s.containsKey(key), "summary has " + key);
        }
        assertEquals(-8.0, ((Number) s.get("paper_mss_peak_y_m")).doubleValue());
        assertEquals(-0.075, ((Number) s.get("paper_ts_peak_y_m")).doubleValue());
        assertEquals(Json.mapper().readValue(r.summaryLine(), Map.class).get("steps"),
                ((Number) s.get("steps")).intValue());
    }

    @Test
    void aDivergingRunStopsCleanlyKeepsItsCsvAndMarksItsChart(@TempDir Path dir) throws Exception {
        // 1 s steps on 100 N/m springs with 1 kg nodes: w h = 10 and more, far beyond any stable step.
        CubeParameters p = CubeParameters.paper().withTimeStep(1.0).withDuration(10_000);
        CubeReport r = CubeReport.run(p, dir);
        assertEquals(org.tensim.io.RunStatus.DIVERGED, r.status());
        Map<String, Object> s = Json.readMap(dir.resolve("summary.json"));
        assertEquals("diverged", s.get("status"));
        String m = s.get("diverged").toString();
        assertTrue(m.contains("diverged at step") && m.contains("node"), m);
        List<String> lines = Files.readAllLines(dir.resolve("cube.csv"));
        assertTrue(lines.size() >= 2, "header and the rows before the divergence are kept");
        assertTrue(lines.get(0).startsWith("t_s,"));
        for (String line : lines.subList(1, lines.size())) {
            assertEquals(7, line.split(",").length, "complete rows only: " + line);
            for (String cell : line.split(",")) {
                assertTrue(Math.abs(Double.parseDouble(cell)) < 1e4, "no runaway value was written: " + line);
            }
        }
        // The chart is marked: its plot background is the diverged pink.
        java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(dir.resolve("cube.png").toFile());
        int pink = new java.awt.Color(255, 225, 225).getRGB();
        int found = 0;
        for (int y = 0; y < img.getHeight(); y += 4) {
            for (int x = 0; x < img.getWidth(); x += 4) {
                found += img.getRGB(x, y) == pink ? 1 : 0;
            }
        }
        assertTrue(found > 1000, "the diverged chart has a pink plot area: " + found + " samples");
    }
}
