package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.testsupport.SharedData;

/** {@code lung-landmarks}: the measured cases' figures as its JSON line gives them, and one-line refusals. */
class LungLandmarksCommandTest {
    @TempDir
    Path tmp;

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    @Test
    void printsTheCasesFiguresWithAJsonLastLine() throws Exception {
        Path f = SharedData.LUNG_LANDMARKS.resolve("case1-300-ee-ei.csv");
        Assumptions.assumeTrue(Files.isRegularFile(f), f.toAbsolutePath() + " not found");
        String[] r = run("lung-landmarks", "--cases", "1,4");
        assertEquals("0", r[0], r[2]);
        String[] lines = r[1].trim().split("\\R");
        JsonNode json = Json.mapper().readTree(lines[lines.length - 1]);
        assertEquals(7.56, json.at("/cases/case1/basal_si_mm").asDouble(), 1e-9);
        assertEquals(14.74, json.at("/cases/case4/basal_si_mm").asDouble(), 1e-9);
        assertEquals(3.89, json.at("/cases/case1/mean_3d_mm").asDouble(), 1e-9);
        assertEquals(5, json.at("/cases/case4/si_profile_ratio").size());
        assertEquals(1.0, json.at("/cases/case4/phase_share/t00").asDouble(), 1e-12);
        assertTrue(json.at("/cases/case1/low_x/points").asInt() + json.at("/cases/case1/high_x/points").asInt()
                == 300);
        assertTrue(r[1].contains("   1  both       300"), r[1]);
    }

    @Test
    void aMissingFolderAndAMalformedFileAreRefusedInOneLine() throws Exception {
        String[] r = run("lung-landmarks", "--landmarks", tmp.resolve("none").toString());
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--landmarks " + tmp.resolve("none") + ": no such folder"), r[2]);
        Files.write(tmp.resolve("case1-300-ee-ei.csv"), List.of(
                "landmark,ee_x_mm,ee_y_mm,ee_z_mm,ei_x_mm,ei_y_mm,ei_z_mm", "1,1,2,3,1,2,x"));
        Files.write(tmp.resolve("case1-75-six-phases.csv"), List.of("landmark"));
        r = run("lung-landmarks", "--landmarks", tmp.toString(), "--cases", "1");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("case1-300-ee-ei.csv, line 2: ei_z_mm is 'x', not a number"), r[2]);
        assertTrue(!r[2].contains("Exception") && !r[2].contains("\tat "), r[2]);
        r = run("lung-landmarks", "--landmarks", tmp.toString(), "--cases", "6");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--cases 6: expected a case from 1 to 5"), r[2]);
    }
}
