package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;

/**
 * The real-time study on two small models and a short run: every configuration is
 * run and reported, the one-thread RK2 gives the two-thread field (the reference), the
 * sternum's mass scaling leaves the field nearly unchanged (its inertial forces are small),
 * and the reference's samples are kept for the next study.
 */
class RealTimeStudyTest {
    @Test
    @SuppressWarnings("unchecked")
    void reportsEveryConfigurationAndItsErrors(@TempDir Path out) throws IOException {
        // With the pressure load, which the figures below were measured with.
        Map<String, Object> s = RealTimeStudy.run(new int[] {6, 8}, null, null, DiaphragmParameters.defaults(),
                BoundaryConditions.defaults().withMuscleLoad(BoundaryConditions.MuscleLoad.PRESSURE),
                BreathingCycle.quiet(), new DiaphragmControls(1, 2600), 0.4, out, null);
        List<Map<String, Object>> runs = (List<Map<String, Object>>) s.get("runs");
        int configs = RealTimeStudy.configs().size();
        assertEquals(2 * configs, runs.size());
        assertTrue(Files.size(out.resolve("realtime.png")) > 0);
        assertEquals(1 + 2 * configs, Files.readAllLines(out.resolve("realtime.csv")).size());
        assertEquals(0.0, (double) runs.get(0).get("relative_rms_error"), "the reference against itself");
        try (java.util.stream.Stream<Path> files = Files.list(out)) {
            assertEquals(2, files.filter(f -> f.getFileName().toString().startsWith("rk2-reference-")).count(),
                    "the same-mesh references' samples are kept, one file per resolution");
        }
        for (Map<String, Object> r : runs) {
            assertTrue((double) r.get("realtime_factor") > 0, r.toString());
            String config = (String) r.get("config");
            // Every configuration runs to the end, the sternum-scaled RK2 included. With the membrane
            // triangles its step was 2.8-3 times the unscaled one and RK2 diverged there (0.08 s at 8 rings);
            // with the material springs it is 1.47 times, and it ran its 0.4 s at 6 and 8 rings (2026-12-01).
            assertTrue(!(boolean) r.get("diverged"), r.toString());
            double own = (double) r.get("error_vs_rk2_same_resolution");
            double worst = (double) r.get("worst_error_vs_rk2_same_resolution");
            assertTrue(worst >= 0 && Double.isFinite(worst), r.toString());
            if (config.startsWith("rk2 at the stable step / 1 thread")) {
                assertTrue(own < 1e-9 && worst < 1e-9, "thread count changes rounding only: " + r);
            } else if (config.contains("sternum mass")) {
                assertTrue(own < 0.05, "sternum mass scaling changes the field little: " + r);
            } else if (config.startsWith("implicit") || config.startsWith("bdf2")) {
                assertTrue((double) r.get("cg_products_per_step") > 0, r.toString());
            }
            if (config.contains("sternum mass")) {
                // It lifts the sternum's limit on the step: a larger stable step than the unscaled RK2's
                // (1.47 times at 8 rings since the material springs and the attachment band, 2026-11-23: the
                // next modes are not far above the sternum's).
                Map<String, Object> plain = runs.stream().filter(x -> x.get("rings").equals(r.get("rings"))
                        && ((String) x.get("config")).startsWith("rk2 at the stable step / 1")).findFirst().get();
                assertTrue((double) r.get("dt_s") > 1.3 * (double) plain.get("dt_s"), r + " vs " + plain);
            }
        }
    }
}
