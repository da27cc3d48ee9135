package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.shell.TissueModel;
import org.tensim.solver.Simulation;

/**
 * The paper's model by one name ({@link DiaphragmSpec#paper()}): its tissue springs, the threshold
 * attachment and the action lines, run with RK2 at its recommended step through one inspiration,
 * shows the paper's claims (section 4): the thorax's antero-posterior, transverse and vertical
 * dimensions all increase.
 */
class PaperModelTest {
    @Test
    void thePapersModelIsItsTissueAttachmentAndActionLines() {
        DiaphragmSpec paper = DiaphragmSpec.paper();
        assertEquals(TissueModel.PAPER, paper.tissue().tissueModel());
        assertEquals(BoundaryConditions.Attachment.PAPER_THRESHOLD, paper.boundary().attachment());
        assertEquals(BoundaryConditions.MuscleLoad.PAPER_NODES, paper.boundary().muscleLoad());
        assertEquals(DiaphragmSetup.DEFAULT_MUSCLE_PA, paper.musclePa(), 0);
    }

    @Test
    void thePapersModelWidensTheThoraxInAllThreeDimensions() throws Exception {
        DiaphragmSpec spec = DiaphragmSpec.paper().withMesh(DiaphragmSpec.Mesh.defaults().withRings(10));
        DiaphragmScene scene = DiaphragmSetup.build(spec).scene();
        Simulation sim = scene.newSimulation();
        double seconds = scene.cycle().inspirationS() + 0.01;
        BreathingMetrics metrics = new BreathingMetrics(scene, seconds);
        double dt = scene.recommendedTimeStep();
        metrics.begin(sim);
        while (sim.time() < seconds - 0.5 * dt) {
            sim.step(dt);
            metrics.afterStep(sim);
        }
        Map<String, Double> f = metrics.fields();
        System.out.println("paper model, 10 rings, end-inspiration: " + f);
        assertTrue(metrics.complete());
        assertTrue(f.get("ap_extent_change_mm") > 0, "antero-posterior: " + f);
        assertTrue(f.get("transverse_extent_change_mm") > 0, "transverse: " + f);
        assertTrue(f.get("thorax_vertical_change_mm") > 0, "vertical (the dome descends): " + f);
    }
}
