package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.testsupport.Commands;

/**
 * A diaphragm scene file with probes and extra conditions, run by {@code tensim run} at 6 rings for half of a
 * 0.1 s breathing cycle: the probes' CSV is written as for any file (one row at the start and after every step,
 * the columns' ranges in the summary, {@code expect:} reading them), and the conditions act on the diaphragm's
 * nodes as physics: a downward force on the tendon lowers it, a pressure on the abdominal surface raises it, a
 * fixed tendon does not move while the rest of the dome breathes.
 */
class DiaphragmSceneConditionsTest {
    @TempDir
    Path dir;

    /** The file with {@code regions}, the tendon's probes, the conditions given (none when empty). */
    private Map<String, Object> run(String name, String conditions) throws Exception {
        Path file = Files.writeString(dir.resolve(name + ".yaml"), """
                version: 1
                bodies:
                  d: {type: diaphragm, rings: 6, period: 100 ms}
                regions:
                  tendon: {body: d, part: tendon}
                  lower: {body: d, part: lower}
                %s
                probes:
                  t: {region: tendon, quantity: mean}
                  e: {region: tendon, quantity: extents}
                run: {dt: auto, duration: 0.05 s}
                expect:
                  - {column: t_mean_dz_m, stat: min, between: [-1 m, 1 m]}
                """.formatted(conditions.isEmpty() ? "" : "conditions:\n  - " + conditions));
        Path out = dir.resolve(name);
        String[] r = Commands.run("run", file.toString(), "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        s.put("csv", Files.readAllLines(out.resolve("probes.csv")));
        return s;
    }

    /** The CSV column's values. */
    @SuppressWarnings("unchecked")
    private static double[] column(Map<String, Object> s, String name) {
        List<String> lines = (List<String>) s.get("csv");
        int c = List.of(lines.get(0).split(",")).indexOf(name);
        assertTrue(c >= 0, name + " in " + lines.get(0));
        return lines.stream().skip(1).mapToDouble(l -> Double.parseDouble(l.split(",")[c])).toArray();
    }

    private static double number(Map<String, Object> s, String... path) {
        Object v = s;
        for (String p : path) {
            v = ((Map<?, ?>) v).get(p);
        }
        return ((Number) v).doubleValue();
    }

    private static double last(double[] v) {
        return v[v.length - 1];
    }

    @Test
    void theProbesAreWrittenAndTheConditionsMoveTheTendonAsLoadsDo() throws Exception {
        Map<String, Object> free = run("free", "");
        Map<String, Object> pushed = run("pushed", "{type: force, region: tendon, direction: [0, 0, -1], total: 2 N}");
        Map<String, Object> lifted = run("lifted", "{type: pressure, region: lower, pressure: 2 kPa}");
        double[] dz = column(free, "t_mean_dz_m");
        // One row at the start and one after every step, as SceneRunner writes them; the summary's ranges are the
        // CSV's; the expect block read the column.
        assertEquals(number(free, "steps") + 1, dz.length, 0, "rows");
        assertEquals(0, dz[0], 0, "no displacement at the start");
        assertEquals(java.util.Arrays.stream(dz).min().getAsDouble(), number(free, "columns", "t_mean_dz_m", "min"),
                0, "the summary's range is the CSV's");
        Map<?, ?> check = (Map<?, ?>) ((List<?>) free.get("expectations")).get(0);
        assertEquals(number(free, "columns", "t_mean_dz_m", "min"), ((Number) check.get("measured")).doubleValue(),
                0, "the check read the column");
        double zFree = last(dz);
        double zPushed = last(column(pushed, "t_mean_dz_m"));
        double zLifted = last(column(lifted, "t_mean_dz_m"));
        System.out.printf("diaphragm file, tendon's mean dz at 0.05 s: %.4f mm free, %.4f mm pushed down by 2 N,"
                + " %.4f mm lifted by 2 kPa on the abdominal surface%n", 1e3 * zFree, 1e3 * zPushed, 1e3 * zLifted);
        assertTrue(zFree < -5e-3, "the contracting muscle lowers the tendon: " + zFree);
        assertTrue(zPushed < zFree - 1e-3, "2 N down on the tendon lowers it by more than 1 mm: " + zPushed + " vs "
                + zFree);
        assertTrue(zLifted > zFree + 5e-3, "2 kPa on the abdominal surface lifts the tendon by more than 5 mm: "
                + zLifted + " vs " + zFree);
    }

    @Test
    void theProbesCsvMayNotTakeAFileTheDiaphragmWritesItself() throws Exception {
        Path file = Files.writeString(dir.resolve("clash.yaml"), """
                version: 1
                bodies:
                  d: {type: diaphragm, rings: 6, period: 100 ms}
                probes:
                  apex: {node: 0}
                run: {dt: auto, duration: 0.01 s, csv: probe.csv}
                """);
        String[] r = Commands.run("run", file.toString(), "--out", dir.resolve("clash").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].contains("run.csv probe.csv is a file the diaphragm's run writes itself"), r[2]);
    }

    @Test
    void aFixedTendonDoesNotMoveWhileTheDomeBreathes() throws Exception {
        Map<String, Object> s = run("fixed", "{type: fixed, region: tendon}");
        for (String a : List.of("x", "y", "z")) {
            double[] mean = column(s, "t_mean_d" + a + "_m");
            double[] lo = column(s, "e_min_" + a + "_m");
            double[] hi = column(s, "e_max_" + a + "_m");
            for (int i = 0; i < mean.length; i++) {
                assertEquals(0, mean[i], 0, "the tendon's mean d" + a + ", row " + i);
                assertEquals(lo[0], lo[i], 0, "its extent, row " + i);
                assertEquals(hi[0], hi[i], 0, "its extent, row " + i);
            }
        }
        // The rest of the diaphragm still contracts: the breathing figures move.
        assertTrue(number(s, "vertical_extent_change_mm") != 0 || number(s, "ap_extent_change_mm") != 0,
                "the dome still moves: " + s.get("vertical_extent_change_mm"));
        assertFalse(s.containsKey("diverged"));
    }
}
