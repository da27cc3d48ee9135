package org.tensim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.sweep.LocalEngine;
import org.tensim.sweep.PointResult;
import org.tensim.sweep.SpecReader;
import org.tensim.sweep.Sweep;
import org.tensim.sweep.SweepSpec;

/**
 * One spec gives the same results on the local engine and on Spark {@code local[2]}, to the
 * last bit: for the cube (a grid, with points that diverge), for the diaphragm (a Latin
 * hypercube on a coarse generated dome) and for a scene file's named parameter (the cube example's force).
 */
class SparkEngineTest {
    @TempDir
    Path dir;

    @Test
    void sparkLocal2GivesTheLocalEnginesBits() throws Exception {
        Path cube = dir.resolve("cube.json");
        Files.writeString(cube, "{\"scene\": \"cube\", \"parameters\": {"
                + "\"forceAmplitudeN\": {\"min\": 100, \"max\": 1900, \"steps\": 4},"
                + "\"stiffnessNPerM\": {\"values\": [30, 1000]}}, \"solver\": {\"seconds\": 3, \"dtS\": 0.03,"
                + " \"integrator\": \"euler\"}, \"outputs\": [\"mss_peak_y_m\", \"ts_peak_y_m\", \"steps\"]}");
        Path dia = dir.resolve("dia.json");
        Files.writeString(dia, "{\"scene\": \"diaphragm\", \"mesh\": {\"rings\": 6}, \"parameters\": {"
                + "\"muscleActionPa\": {\"min\": 1000, \"max\": 4000}, \"ribAmplitudeFactor\": {\"min\": 0.5,"
                + " \"max\": 1.5}}, \"sampling\": {\"method\": \"lhs\", \"points\": 4, \"seed\": 7},"
                + " \"solver\": {\"seconds\": 1.4, \"dtS\": 0.01, \"integrator\": \"implicit-euler-cg1e-3\"},"
                + " \"outputs\": [\"dome_excursion_mm\", \"ap_extent_change_mm\", \"transverse_extent_change_mm\"]}");
        // A scene file's named parameter (the cube example's force), its stiffness overridden.
        Path file = dir.resolve("file.json");
        Files.writeString(file, "{\"scene\": \"" + Path.of("docs/examples/cube.yaml").toAbsolutePath() + "\","
                + " \"overrides\": {\"stiffness\": 300}, \"parameters\": {\"force\": {\"min\": 100, \"max\": 900,"
                + " \"steps\": 3}}, \"solver\": {\"seconds\": 1}, \"outputs\": [\"mss_dy_m_min\", \"ts_dy_m_min\"]}");
        try (SparkEngine spark = new SparkEngine("local[2]")) {
            for (Path f : List.of(cube, dia, file)) {
                SweepSpec s = SpecReader.readSweep(f);
                Sweep.Outcome local;
                try (LocalEngine e = new LocalEngine(2)) {
                    local = Sweep.run(s, dir.resolve("local-" + f.getFileName()), e, false, null);
                }
                Sweep.Outcome onSpark = Sweep.run(s, dir.resolve("spark-" + f.getFileName()), spark, false, null);
                assertEquals(local.results().size(), onSpark.results().size());
                assertTrue(local.results().stream().anyMatch(PointResult::ok));
                for (int i = 0; i < local.results().size(); i++) {
                    PointResult a = local.results().get(i);
                    PointResult b = onSpark.results().get(i);
                    assertEquals(a.status(), b.status(), f + " point " + i);
                    assertEquals(a.message(), b.message(), f + " point " + i);
                    assertEquals(a.fields().keySet(), b.fields().keySet());
                    for (String k : a.fields().keySet()) {
                        assertEquals(Double.doubleToRawLongBits(a.field(k)), Double.doubleToRawLongBits(b.field(k)),
                                f + " point " + i + " " + k + ": " + a.field(k) + " vs " + b.field(k));
                    }
                }
                System.out.printf(java.util.Locale.ROOT, "%s: %d points, local(2) %.3f s, spark local[2] %.3f s,"
                        + " overhead %.1f ms per point%n", f.getFileName(), local.ran(), local.wallS(),
                        onSpark.wallS(), 1e3 * (onSpark.wallS() - local.wallS()) / local.ran());
            }
        }
    }
}
