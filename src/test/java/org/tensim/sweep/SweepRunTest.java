package org.tensim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Whole sweeps of the cube: the same results on one and two workers (bit for bit), a
 * killed sweep resumed loses no finished point and reruns only the missing ones, and a
 * point that diverges is recorded as such while the sweep goes on.
 */
class SweepRunTest {
    @TempDir
    Path dir;

    private SweepSpec spec(double seconds, String extra) throws Exception {
        Path f = dir.resolve("cube.json");
        Files.writeString(f, "{\"scene\": \"cube\", \"parameters\": {"
                + "\"forceAmplitudeN\": {\"min\": 100, \"max\": 400, \"steps\": 3},"
                + "\"stiffnessNPerM\": {\"values\": [300, 1000]}}, \"solver\": {\"seconds\": " + seconds + extra + "},"
                + " \"outputs\": [\"mss_peak_y_m\", \"ts_peak_y_m\", \"steps\"]}");
        return SpecReader.readSweep(f);
    }

    @Test
    void oneAndTwoWorkersGiveTheSameBitsAndAResumedSweepLosesNothing() throws Exception {
        SweepSpec s = spec(0.4, "");
        Sweep.Outcome one;
        try (LocalEngine e = new LocalEngine(1)) {
            one = Sweep.run(s, dir.resolve("one"), e, false, null);
        }
        assertEquals(6, one.ran());
        Sweep.Outcome two;
        try (LocalEngine e = new LocalEngine(2)) {
            two = Sweep.run(s, dir.resolve("two"), e, false, null);
        }
        assertSame(one.results(), two.results());
        // peaks grow with the force: the runs did run
        assertTrue(one.results().get(4).field("mss_peak_y_m") < one.results().get(0).field("mss_peak_y_m"));
        assertTrue(Files.isRegularFile(dir.resolve("two/charts/mss_peak_y_m-vs-forceAmplitudeN.png")));

        // A sweep killed after three rows, in the middle of writing the fourth.
        Path csv = dir.resolve("two/results.csv");
        List<String> lines = Files.readAllLines(csv);
        String cut = String.join("\n", lines.subList(0, 4)) + "\n" + lines.get(4).substring(0, 9);
        Files.writeString(csv, cut, StandardCharsets.UTF_8);
        Sweep.Outcome resumed;
        try (LocalEngine e = new LocalEngine(2)) {
            resumed = Sweep.run(s, dir.resolve("two"), e, false, null);
        }
        assertEquals(3, resumed.skipped());
        assertEquals(3, resumed.ran());
        assertSame(one.results(), resumed.results());
        assertEquals(7, Files.readAllLines(csv).size(), "header and six rows, no duplicate");
    }

    @Test
    void aDivergingPointIsRecordedAndTheSweepGoesOn() throws Exception {
        // Explicit Euler with a 50 ms step, beyond its critical step on these springs: these runs blow up.
        SweepSpec s = spec(30, ", \"dtS\": 0.05, \"integrator\": \"euler\"");
        Sweep.Outcome o;
        try (LocalEngine e = new LocalEngine(2)) {
            o = Sweep.run(s, dir.resolve("div"), e, false, null);
        }
        assertEquals(6, o.results().size());
        long diverged = o.results().stream().filter(r -> r.status().equals(PointResult.DIVERGED)).count();
        assertTrue(diverged > 0, "some points diverge: " + o.results());
        for (PointResult r : o.results()) {
            if (!r.ok()) {
                assertFalse(r.message().isEmpty(), "a diverged point says why");
            }
        }
        String text = Files.readString(dir.resolve("div/results.csv"));
        assertTrue(text.contains(",diverged,"), text);
    }

    private static void assertSame(List<PointResult> a, List<PointResult> b) {
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            assertEquals(a.get(i).id(), b.get(i).id());
            assertEquals(a.get(i).status(), b.get(i).status());
            for (String f : List.of("mss_peak_y_m", "ts_peak_y_m", "steps")) {
                assertEquals(Double.doubleToRawLongBits(a.get(i).field(f)), Double.doubleToRawLongBits(b.get(i)
                        .field(f)), "point " + i + " " + f);
            }
        }
    }
}
