package org.tensim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.sweep.LocalEngine;

/**
 * A calibration spec gives the same fit to the last bit on one worker and on two (candidates
 * finish in another order), and the generation limit is part of the strategy, not only a stop:
 * Hipparchus's CMA-ES damps its step size by max(0.3, 1 - n / generations) (Hansen's reference
 * code), so the same spec with another {@code generations} takes another path from its second
 * generation on. That is why a test with 16 generations and a command-line run with 24 once ended
 * at different parameters (docs/calibration.md).
 */
class CalibrationReproducibilityTest {
    @TempDir
    Path dir;

    private CalibrationSpec spec(int generations) throws Exception {
        Path f = dir.resolve("cube-" + generations + ".json");
        Files.writeString(f, "{\"scene\": \"cube\", \"solver\": {\"integrator\": \"implicit-euler-cg1e-3\","
                + " \"dtS\": 0.02, \"seconds\": 2}, \"fixed\": {\"forceAmplitudeN\": 300},"
                + " \"fit\": {\"stiffnessNPerM\": {\"min\": 100, \"max\": 3000, \"start\": 2500}},"
                + " \"optimizer\": {\"population\": 4, \"generations\": " + generations + ", \"sigma\": 0.3,"
                + " \"seed\": 5}, \"targets\": [{\"type\": \"summary\", \"field\": \"mss_peak_y_m\","
                + " \"value\": -0.05, \"tolerance\": 0.001}]}");
        return CalibrationReader.read(f);
    }

    private Calibrator.Outcome run(CalibrationSpec s, int workers, String out) throws Exception {
        try (LocalEngine e = new LocalEngine(workers)) {
            return Calibration.run(s, e, dir.resolve(out), null).outcome();
        }
    }

    @Test
    void oneSpecGivesOneFitAndItsGenerationLimitIsPartOfIt() throws Exception {
        Calibrator.Outcome one = run(spec(6), 1, "one");
        Calibrator.Outcome two = run(spec(6), 2, "two");
        assertEquals(one.evaluations().size(), two.evaluations().size());
        for (int i = 0; i < one.evaluations().size(); i++) {
            assertEquals(bits(one.evaluations().get(i).values()), bits(two.evaluations().get(i).values()), "run " + i);
            assertEquals(Double.doubleToRawLongBits(one.evaluations().get(i).fitness()),
                    Double.doubleToRawLongBits(two.evaluations().get(i).fitness()), "run " + i);
        }
        Calibrator.Outcome longer = run(spec(12), 2, "longer");
        // The start point and the first generation are drawn before the step size is first adapted ...
        int firstDifferent = -1;
        for (int i = 0; i < Math.min(one.evaluations().size(), longer.evaluations().size()); i++) {
            if (!bits(one.evaluations().get(i).values()).equals(bits(longer.evaluations().get(i).values()))) {
                firstDifferent = i;
                break;
            }
        }
        // ... then the damping, which depends on the limit, sends the search elsewhere.
        assertNotEquals(-1, firstDifferent, "another generation limit, another path");
        assertEquals(2, one.evaluations().get(firstDifferent).generation(), "the paths part at the second generation");
    }

    private static List<Long> bits(double[] v) {
        return java.util.Arrays.stream(v).mapToObj(Double::doubleToRawLongBits).toList();
    }
}
