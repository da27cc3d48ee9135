package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.analysis.lungs.MeasuredCase;
import org.tensim.analysis.lungs.ModelFigures;
import org.tensim.analysis.lungs.ModelMotion;
import org.tensim.analysis.lungs.SyntheticMotion;
import org.tensim.io.Json;
import org.tensim.testsupport.SharedData;

/** {@code validate-4dct} on a folder written by the lung points' writer: every output and summary key. */
class Validate4dctCommandTest {
    @TempDir
    Path tmp;

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    private static ModelMotion motion() {
        return new SyntheticMotion(0.002, 0.011, 0.009, 0.002).motion(SyntheticMotion.cosine(1, 4), 0.05, 4, 3, 1);
    }

    private static void assumeLandmarks() {
        Path f = SharedData.LUNG_LANDMARKS.resolve("case5-75-six-phases.csv");
        Assumptions.assumeTrue(Files.isRegularFile(f), f.toAbsolutePath() + " not found");
    }

    @Test
    void writesTheChartTheCasesCsvsAndEverySummaryKey() throws Exception {
        assumeLandmarks();
        ModelMotion m = motion();
        Path runDir = SyntheticMotion.writeRun(tmp.resolve("lungs"), m);
        Path out = tmp.resolve("validate");
        String[] r = run("validate-4dct", "--run", runDir.toString(), "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].contains("targets met"), r[1]);
        String[] lines = r[1].trim().split("\\R");
        assertEquals(Json.mapper().readTree(out.resolve("summary.json").toFile()),
                Json.mapper().readTree(lines[lines.length - 1]), "the last line is the summary");
        assertTrue(Files.size(out.resolve("validate-4dct.png")) > 10_000);
        JsonNode s = Json.mapper().readTree(out.resolve("summary.json").toFile());
        assertEquals("ok", s.get("status").asText());
        assertEquals("validate-4dct", s.get("command").asText());
        // The summary's figures are the model's own, as the analysis computes them from the motion read back.
        ModelFigures fig = ModelFigures.of(m);
        for (int b = 0; b < 5; b++) {
            assertEquals(fig.both().ratio()[b], s.at("/model_si_profile_ratio/" + b).asDouble(), 5e-4);
        }
        assertEquals(fig.both().basalSiM() * 1e3, s.get("model_basal_si_mm").asDouble(), 5e-3);
        assertEquals(fig.both().mean3dM() * 1e3, s.get("model_mean_3d_mm").asDouble(), 5e-3);
        for (String key : List.of("model_phase_share", "model_law_share", "model_phase_time_s")) {
            assertEquals(6, s.get(key).size(), key);
        }
        assertEquals(fig.right().basalSiM() * 1e3, s.at("/model_right/basal_si_mm").asDouble(), 5e-3);
        assertEquals(fig.left().basalSiM() * 1e3, s.at("/model_left/basal_si_mm").asDouble(), 5e-3);
        assertEquals(6, s.at("/model_left/phase_share").size());
        List<MeasuredCase> cases = Validate4dctCommand.read(SharedData.LUNG_LANDMARKS, List.of(1, 2, 3, 4, 5));
        for (MeasuredCase c : cases) {
            JsonNode cn = s.at("/cases/case" + c.caseNumber());
            assertEquals(c.both().basalSiM() * 1e3, cn.get("basal_si_mm").asDouble(), 5e-3);
            assertEquals(5, cn.get("si_profile_ratio").size());
            assertTrue(cn.has("low_x") && cn.has("high_x") && cn.has("phase_share"));
            List<String> csv = Files.readAllLines(out.resolve("case" + c.caseNumber() + ".csv"));
            assertEquals(String.join(",", Validate4dctOutputs.CASE_HEADER), csv.get(0));
            assertEquals(1 + 5 + 2 + 6, csv.size());
            assertTrue(csv.get(1).startsWith("si_ratio,bin1,0.00000,0.200000,,,"), csv.get(1));
            assertTrue(csv.get(8).startsWith("phase_share,t00,,,0,"), csv.get(8));
        }
        List<String> names = new ArrayList<>();
        s.get("targets").fieldNames().forEachRemaining(names::add);
        assertEquals(List.of("profile_bin1", "profile_bin2", "profile_bin3", "profile_bin4", "basal_si_mm",
                "mean_3d_mm", "share_t10", "share_t20", "share_t30", "share_t40"), names);
        int passed = 0;
        for (String n : names) {
            JsonNode t = s.at("/targets/" + n);
            double v = t.get("value").asDouble();
            double lo = t.at("/range/0").asDouble();
            double hi = t.at("/range/1").asDouble();
            assertEquals(v >= lo && v <= hi, t.get("pass").asBoolean(), n);
            passed += t.get("pass").asBoolean() ? 1 : 0;
        }
        assertEquals(passed + " of 10", s.get("targets_passed").asText());
        // The profile target's range is the cases' range of that bin, widened by 0.1 either side.
        double lo = cases.stream().mapToDouble(c -> c.both().ratio()[1]).min().orElseThrow();
        assertEquals(lo - 0.1, s.at("/targets/profile_bin2/range/0").asDouble(), 1e-3);
        assertArrayEquals(new double[] {6, 20}, new double[] {s.at("/targets/basal_si_mm/range/0").asDouble(),
            s.at("/targets/basal_si_mm/range/1").asDouble()}, 0);
        List<String> files = new ArrayList<>();
        s.get("files").forEach(f -> files.add(f.asText()));
        assertTrue(files.containsAll(List.of("validate-4dct.png", "case1.csv", "case5.csv")), files.toString());
    }

    @Test
    void aRunWithoutLungPointsAndAMalformedRowAreRefusedInOneLine() throws Exception {
        assumeLandmarks();
        Path none = Files.createDirectories(tmp.resolve("plain"));
        String[] r = run("validate-4dct", "--run", none.toString(), "--out", tmp.resolve("o1").toString());
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--run " + none + ": " + none + " has no lung-points.csv"), r[2]);
        assertTrue(!Files.exists(tmp.resolve("o1")), "no output folder for a refused run");
        Path runDir = SyntheticMotion.writeRun(tmp.resolve("lungs"), motion());
        Path csv = runDir.resolve("lung-points.csv");
        List<String> lines = new ArrayList<>(Files.readAllLines(csv));
        lines.set(6, "0.0,5,left,1,2,x");
        Files.write(csv, lines);
        r = run("validate-4dct", "--run", runDir.toString(), "--out", tmp.resolve("o2").toString());
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("lung-points.csv, line 7: z_mm is 'x', not a number"), r[2]);
        assertTrue(!r[2].contains("Exception") && !r[2].contains("\tat "), r[2]);
        r = run("validate-4dct", "--run", tmp.resolve("absent").toString());
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--run " + tmp.resolve("absent") + ": no such folder"), r[2]);
    }
}
