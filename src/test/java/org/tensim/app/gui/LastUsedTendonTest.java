package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.Tuning;

/**
 * Last-used parameters tuned with the plane rule's tendon control come back in a window without it (opened with the
 * label file saved from it, or with the geodesic rule): the control is left out, everything else is restored.
 */
class LastUsedTendonTest {
    @TempDir
    Path dir;

    private static Tuning tuning(TendonRule rule, boolean labelled) {
        return new Tuning("diaphragm", DiaphragmViewScene.parameters(BoundaryConditions.MuscleLoad.FIBRES, rule,
                labelled), 0.025, true, Integrators.choices(), org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES);
    }

    @Test
    void aTendonControlTheWindowDoesNotHaveIsLeftOutAndTheRestRestored() throws Exception {
        Tuning plane = tuning(TendonRule.PLANE, false);
        plane.set(DiaphragmViewScene.TENDON_PLANE, 6);
        plane.set(DiaphragmViewScene.MUSCLE_ACTION, 12_000);
        Path file = dir.resolve("last-diaphragm.json");
        PresetFile.write(file, plane.snapshot());

        Tuning labelled = tuning(TendonRule.PLANE, true);
        assertNull(GuiCommand.restore(labelled, file), "restored without a note");
        assertEquals(12_000, labelled.get(DiaphragmViewScene.MUSCLE_ACTION));
        assertFalse(labelled.keys().contains(DiaphragmViewScene.TENDON_PLANE));
        assertTrue(Files.exists(file) && !Files.exists(dir.resolve("last-diaphragm.json.bad")));

        Tuning geodesic = tuning(TendonRule.GEODESIC, false);
        assertNull(GuiCommand.restore(geodesic, file));
        assertEquals(12_000, geodesic.get(DiaphragmViewScene.MUSCLE_ACTION));
        assertEquals(0.12, geodesic.get(DiaphragmViewScene.TENDON_SHARE), "the geodesic share keeps its default");

        // Another unknown parameter is still refused, and the file kept aside.
        Files.writeString(file, Files.readString(file).replace("\"muscleActionPa\"", "\"muscleForcePa\""));
        String note = GuiCommand.restore(tuning(TendonRule.PLANE, false), file);
        assertTrue(note != null && note.contains("muscleForcePa"), note);
    }
}
