package org.tensim.tuning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.lungs.LungsMuscle;

/**
 * With the lungs the muscle's default fibre stress is the one measured with them, headless and in the window alike;
 * a muscle action the user gives, and the pressure loads (not measured with the lungs), are left as they are.
 */
class LungsMuscleTest {
    @Test
    void theLungsDefaultReplacesOnlyTheFibresOwnDefault() {
        DiaphragmSpec d = DiaphragmSpec.defaults();
        assertEquals(BoundaryConditions.MuscleLoad.FIBRES, d.boundary().muscleLoad());
        assertEquals(LungsMuscle.FIBRE_STRESS_PA, LungsMuscle.applyTo(d).breathing().musclePa());
        DiaphragmSpec given = d.withBreathing(d.breathing().withMusclePa(25_000.0));
        assertEquals(25_000.0, LungsMuscle.applyTo(given).breathing().musclePa());
        DiaphragmSpec pressure = d.withBoundary(d.boundary().withMuscleLoad(BoundaryConditions.MuscleLoad.PRESSURE));
        assertNull(LungsMuscle.applyTo(pressure).breathing().musclePa(), "the pressure load's own default");
        assertEquals(LungsMuscle.FIBRE_STRESS_PA, LungsMuscle.applyTo(d).musclePa(), 0, "the scene starts at it");
        assertEquals(19_000, d.musclePa(), 0, "without the lungs, the diaphragm alone's default");
    }

    @Test
    void theWindowsControlsStartAtItWithTheLungsUnlessTyped() {
        DiaphragmOptions plain = DiaphragmOptions.parse(List.of());
        assertEquals(LungsMuscle.FIBRE_STRESS_PA, plain.controlValues(true).get(DiaphragmViewScene.MUSCLE_ACTION)
                .getValue());
        assertEquals("--lungs", plain.controlValues(true).get(DiaphragmViewScene.MUSCLE_ACTION).getKey());
        assertNull(plain.controlValues(false).get(DiaphragmViewScene.MUSCLE_ACTION), "no lungs: the load's default");
        DiaphragmOptions typed = DiaphragmOptions.parse(List.of("--muscle-action", "22000"));
        assertEquals(22_000, typed.controlValues(true).get(DiaphragmViewScene.MUSCLE_ACTION).getValue());
        DiaphragmOptions pressure = DiaphragmOptions.parse(List.of("--muscle-load", "pressure"));
        assertNull(pressure.controlValues(true).get(DiaphragmViewScene.MUSCLE_ACTION));
    }
}
