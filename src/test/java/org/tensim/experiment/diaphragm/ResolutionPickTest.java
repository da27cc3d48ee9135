package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.PickOption;

/**
 * The pick the mechanics run at: the shipped one is a measured study of the default scene (with its provenance), a
 * pick records the scene it was measured on, and a pick is refused, with a message naming what differs, on a scene
 * no measured study matches.
 */
class ResolutionPickTest {
    @TempDir
    Path dir;

    @Test
    void theShippedPickIsAMeasuredStudyOfTheDefaultSceneWithinItsTolerance() {
        ResolutionPick p = ResolutionPick.shipped();
        assertTrue(p.rings() < ResolutionPick.REFERENCE_RINGS, "a coarser model than the paper's: " + p);
        assertTrue(p.error() > 0 && p.error() <= p.tolerance(), "its measured error within the tolerance: " + p);
        assertEquals(64, p.digest().length());
        assertTrue(p.measured().containsKey("measured_utc") && p.measured().containsKey("command")
                && p.measured().containsKey("load_average"), "its provenance: " + p.measured());
        p.requireMatches(DiaphragmSpec.defaults());
        // the committed 43-ring mesh is the same double dome
        p.requireMatches(DiaphragmSpec.defaults().withMesh(DiaphragmSpec.defaults().mesh().withFile(
                DiaphragmSetup.DEFAULT_MESH, DiaphragmSpec.defaults().mesh().units())));
    }

    @Test
    void anotherToleranceTakesTheCoarsestWithinItFromTheStudysTable() {
        ResolutionPick p = ResolutionPick.shipped();
        for (double tol : new double[] {0.03, 0.05, 0.1, 0.2}) {
            ResolutionPick q = p.within(tol);
            assertTrue(q.error() <= tol, tol + ": " + q);
            // every finer model of the table is within it too, and the next coarser one is not
            boolean seen = false;
            Double coarser = null;
            for (Map<String, Object> row : p.models()) {
                double e = ((Number) row.get("relative_rms_error")).doubleValue();
                if (row.get("model").equals(q.rings() + " rings")) {
                    seen = true;
                } else if (seen) {
                    assertTrue(e <= tol, row.toString());
                } else {
                    coarser = e;
                }
            }
            assertTrue(seen && (coarser == null || coarser > tol), tol + ": " + q.rings() + " rings");
            assertEquals(p.digest(), q.digest(), "the same measured file");
        }
    }

    @Test
    void aPickIsRefusedOnASceneNoMeasuredStudyMatches() {
        ResolutionPick p = ResolutionPick.shipped();
        DiaphragmSpec pressure = DiaphragmSpec.defaults().withBoundary(BoundaryConditions.defaults()
                .withMuscleLoad(BoundaryConditions.MuscleLoad.PRESSURE));
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> p.requireMatches(pressure));
        String m = e.getMessage();
        assertTrue(m.contains("no measured resolution study matches") && m.contains("muscle_load")
                && m.contains("pressure") && m.contains(ResolutionPick.SHIPPED_NAME)
                && m.contains("resolution-study"), m);
        DiaphragmSpec stiffer = DiaphragmSpec.defaults().withTissue(DiaphragmSpec.defaults().tissue()
                .withTissueYoung(80e3));
        assertTrue(assertThrows(IllegalStateException.class, () -> p.requireMatches(stiffer)).getMessage()
                .contains("tissue"));
    }

    @Test
    void aWrittenPickRecordsItsSceneAndOneWithoutIsRefused() throws Exception {
        Path f = dir.resolve("pick.json");
        new ResolutionPick(20, 0.048, 0.05, "because", ResolutionPick.sceneOf(DiaphragmSpec.defaults()), null, null,
                null, null).write(f, Map.of("measured_utc", "2026-12-02T00:00:00Z"));
        ResolutionPick p = ResolutionPick.read(f);
        assertEquals(20, p.rings());
        assertEquals(f.toString(), p.source());
        assertEquals("2026-12-02T00:00:00Z", p.measured().get("measured_utc"));
        p.requireMatches(DiaphragmSpec.defaults());

        Path old = dir.resolve("old.json");
        new ResolutionPick(14, 0.08, 0.1, "an old study").write(old, Map.of());
        String m = assertThrows(IllegalStateException.class, () -> ResolutionPick.read(old).requireMatches(
                DiaphragmSpec.defaults())).getMessage();
        assertTrue(m.contains(old.toString()) && m.contains("does not record the scene"), m);
    }

    @Test
    void withoutAFileTheShippedPickMapsTheDefaultSceneOnlyAndSaysWhyNot() {
        PickOption none = new PickOption();
        DiaphragmOptions defaults = DiaphragmOptions.parse(List.of());
        ResolutionPick p = none.choose(defaults, defaults.spec(null, DiaphragmSpec.PAPER_RINGS), null);
        assertEquals(ResolutionPick.shipped().within(ResolutionPick.DEFAULT_TOLERANCE).rings(), p.rings());
        assertTrue(p.error() <= ResolutionPick.DEFAULT_TOLERANCE, p.toString());

        DiaphragmOptions pressure = DiaphragmOptions.parse(List.of("--muscle-load", "pressure"));
        List<String> notes = new ArrayList<>();
        assertNull(none.choose(pressure, pressure.spec(null, DiaphragmSpec.PAPER_RINGS), notes::add),
                "no study of this scene: the full model");
        assertTrue(notes.size() == 1 && notes.get(0).contains("full model") && notes.get(0).contains("pressure"),
                notes.toString());

        DiaphragmOptions rings = DiaphragmOptions.parse(List.of("--rings", "20"));
        assertNull(none.choose(rings, rings.spec(null, DiaphragmSpec.PAPER_RINGS), null), "--rings runs as asked");
    }
}
