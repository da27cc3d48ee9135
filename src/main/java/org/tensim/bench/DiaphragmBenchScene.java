package org.tensim.bench;

import java.nio.file.Files;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;

/**
 * The diaphragm scene of {@code tensim diaphragm}, with that command's defaults: the
 * project's default mesh (or, when it is missing, the generated double dome of 43
 * rings, as the command does), 2.5 mm offset thickness, the parametric rib cage,
 * quiet breathing (4 s period, I:E 1:2), rib amplitude 1, the default muscle action.
 */
final class DiaphragmBenchScene {
    private DiaphragmBenchScene() {
    }

    static DiaphragmScene build() throws Exception {
        DiaphragmParameters p = DiaphragmParameters.defaults();
        BreathingCycle cycle = new BreathingCycle(4, 2);
        DiaphragmControls controls = new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa());
        if (!Files.isRegularFile(DiaphragmSetup.DEFAULT_MESH)) {
            return DiaphragmSetup.generated(43, null, p, cycle, controls).scene();
        }
        return DiaphragmSetup.load(DiaphragmSetup.DEFAULT_MESH, MeshUnits.parse("mm"), 2.5e-3,
                null, p, cycle, controls).scene();
    }
}
