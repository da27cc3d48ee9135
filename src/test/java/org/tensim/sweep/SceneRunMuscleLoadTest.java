package org.tensim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * A sweep's {@code muscleLoad} reaches the scene: with the active fibre tension (15 kPa, its default
 * amplitude) the coarse double dome descends by a physiological amount, while the same 15 kPa as the
 * vertical traction of the pressure load drives it several times as far; a spec without a muscle load
 * runs the fibres, the default.
 */
class SceneRunMuscleLoadTest {
    private static RunSetup setup(String muscleLoad) {
        return new RunSetup("diaphragm", muscleLoad == null ? List.of("--rings", "6")
                : List.of("--rings", "6", "--muscle-load", muscleLoad), "implicit-euler-cg1e-3", 0.01, 1.34,
                Map.of(), List.of());
    }

    @Test
    void theFibresLoadIsTheOneRun() {
        List<String> names = List.of("muscleActionPa");
        Point p = new Point(0, new double[] {15000});
        PointResult fibres = SceneRun.run(setup("fibres"), names, p);
        PointResult pressure = SceneRun.run(setup("pressure"), names, p);
        PointResult byDefault = SceneRun.run(setup(null), names, p);
        assertEquals(PointResult.OK, fibres.status(), fibres.message());
        double f = fibres.fields().get("dome_excursion_mm");
        assertTrue(f > 8 && f < 30, "fibres at 15 kPa: dome excursion " + f + " mm");
        // The pressure run must itself succeed: a diverged run is a failure, not an infinite excursion.
        assertEquals(PointResult.OK, pressure.status(), pressure.message());
        double q = pressure.fields().get("dome_excursion_mm");
        assertTrue(Double.isFinite(q), "pressure at 15 kPa: dome excursion " + q + " mm");
        assertTrue(q > 2 * f, "the same 15 kPa as a vertical traction: " + q + " mm against " + f + " mm");
        assertEquals(PointResult.OK, byDefault.status(), byDefault.message());
        assertEquals(f, byDefault.fields().get("dome_excursion_mm"), 0, "no muscleLoad: the fibres, the default");
    }
}
