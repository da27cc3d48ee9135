package org.tensim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * A point's result depends on its values alone, not on what the JVM ran before nor on what runs
 * beside it: the diaphragm at the same values gives the same final positions, bit for bit, as the
 * first scene its factory builds, after a run at other values, and while another point runs on a
 * second worker. (A calibration's test JVM makes its synthetic target before the fit; the command
 * line makes it in another JVM: their fits must agree to the last bit.)
 */
class SceneRunRepeatabilityTest {
    /** Adds every node's final position to the summary as one hash of their bits. */
    private record FinalPositions() implements Measure {
        private static final long serialVersionUID = 1L;

        @Override
        public Probe start(DiaphragmRunView run) {
            return new Probe() {
                private double[] last;

                @Override
                public void afterStep(double t, double[] x) {
                    last = x;
                }

                @Override
                public void finish(Map<String, Double> fields) {
                    fields.put("x_bits_hash", (double) Arrays.hashCode(last));
                    fields.put("x_sum_m", Arrays.stream(last).sum());
                }
            };
        }
    }

    @Test
    void theSameValuesGiveTheSameBitsWhateverRanBeforeOrBeside() throws Exception {
        // 5 rings: a geometry no other test builds, so the first point is its factory's first scene.
        RunSetup setup = new RunSetup("diaphragm", List.of("--rings", "5"), "implicit-euler-cg1e-3", 0.01, 0.3,
                Map.of(), List.of(new FinalPositions()));
        List<String> names = List.of("muscleActionPa", "ribAmplitudeFactor");
        Point a = new Point(0, new double[] {2600, 1.2});
        Point b = new Point(1, new double[] {1500, 0.6});
        List<PointResult> as = new ArrayList<>();
        as.add(SceneRun.run(setup, names, a));
        PointResult other = SceneRun.run(setup, names, b);
        as.add(SceneRun.run(setup, names, a));
        try (LocalEngine e = new LocalEngine(2)) {
            e.run(setup, names, List.of(a, b, a, b), r -> {
                if (r.id() == a.id()) {
                    as.add(r);
                }
            });
        }
        assertEquals(4, as.size());
        assertNotEquals(as.get(0).field("x_sum_m"), other.field("x_sum_m"), "other values move the nodes elsewhere");
        for (PointResult r : as) {
            assertEquals(PointResult.OK, r.status(), r.message());
            for (String f : List.of("x_bits_hash", "x_sum_m", "dome_excursion_mm", "ap_extent_change_mm")) {
                assertEquals(Double.doubleToRawLongBits(as.get(0).field(f)), Double.doubleToRawLongBits(r.field(f)),
                        f + ": " + as.get(0).field(f) + " then " + r.field(f));
            }
        }
    }
}
