package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The resolution study's analysis: the order of a known power law, the pick, and the pick file round trip. */
class ResolutionAnalysisTest {
    private static List<Map<String, Object>> rows(double[] h, double[] e) {
        List<Map<String, Object>> rows = new ArrayList<>();
        for (int i = 0; i < h.length; i++) {
            Map<String, Object> r = new LinkedHashMap<>();
            r.put("model", i + "");
            r.put("element_mm", h[i]);
            r.put("relative_rms_error", e[i]);
            rows.add(r);
        }
        return rows;
    }

    @Test
    void theOrderOfAPowerLawIsItsExponent() {
        double[] h = {18, 13, 9, 6.5, 4.4};
        double[] e = new double[h.length];
        for (int i = 0; i + 1 < h.length; i++) {
            e[i] = 0.002 * h[i] * h[i];
        }
        List<Map<String, Object>> r = rows(h, e);
        assertEquals(2, ResolutionAnalysis.order(r), 1e-9);
        assertTrue(ResolutionAnalysis.monotone(r));
        e[2] = e[1] * 1.01;
        assertFalse(ResolutionAnalysis.monotone(rows(h, e)));
    }

    @Test
    void thePickIsTheCoarsestWithinTheToleranceWithEveryFinerOne() {
        double[] h = {18, 13, 9, 6.5, 4.4};
        // 13 mm passes but 9 mm does not: the pick is 6.5 mm, not 13
        assertEquals(3, ResolutionAnalysis.pick(rows(h, new double[] {0.3, 0.08, 0.12, 0.05, 0}), 0.10));
        assertEquals(1, ResolutionAnalysis.pick(rows(h, new double[] {0.3, 0.08, 0.06, 0.05, 0}), 0.10));
        // none: the reference
        assertEquals(4, ResolutionAnalysis.pick(rows(h, new double[] {0.3, 0.2, 0.15, 0.12, 0}), 0.10));
    }

    @Test
    void thePickFileRoundTripsAndAMissingOneIsRefusedByName(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("pick.json");
        IllegalStateException missing = org.junit.jupiter.api.Assertions.assertThrows(IllegalStateException.class,
                () -> ResolutionPick.read(f), "a pick named but absent is an error, not a silent default");
        assertTrue(missing.getMessage().contains(f.toString()) && missing.getMessage().contains("no such file"),
                missing.getMessage());
        new ResolutionPick(20, 0.043, 0.05, "because").write(f, Map.of("nodes", 3766));
        ResolutionPick p = ResolutionPick.read(f);
        assertEquals(20, p.rings());
        assertEquals(0.043, p.error(), 1e-12);
        assertEquals("because", p.reason());
        Files.writeString(f, "{\"rings\": \"many\"}");
        IllegalStateException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalStateException.class,
                () -> ResolutionPick.read(f));
        assertTrue(e.getMessage().contains("pick.json") && e.getMessage().contains("'rings'"), e.getMessage());
    }
}
