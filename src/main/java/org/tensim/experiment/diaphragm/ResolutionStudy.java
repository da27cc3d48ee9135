package org.tensim.experiment.diaphragm;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Map;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;

/** Placeholder replaced below. */
public final class ResolutionStudy {
    private ResolutionStudy() {
    }

    public static Map<String, Object> run(Path boxes, DiaphragmParameters p, BreathingCycle c, DiaphragmControls k,
            DiaphragmReport.Options o, Path out, PrintStream log) {
        throw new UnsupportedOperationException("resolution study not written yet");
    }
}
