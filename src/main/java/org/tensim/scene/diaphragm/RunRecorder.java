package org.tensim.scene.diaphragm;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import org.tensim.solver.Simulation;

/**
 * Records what bodies added to a diaphragm scene (the organs) do during a headless run, and writes their own
 * outputs into the run's folder: the run calls {@link #begin} once, {@link #afterStep} after every step, then
 * {@link #finish}.
 */
public interface RunRecorder {
    /**
     * Before the first step.
     *
     * @param measuredStartS the measured cycle's start (end-exhale), s
     * @param inspirationEndS the measured cycle's end-inspiration, s
     * @param periodS        the breathing period, s
     */
    void begin(Simulation sim, double measuredStartS, double inspirationEndS, double periodS);

    /** After every step (allocation is the recorder's own business: it runs beside the solver). */
    void afterStep(Simulation sim);

    /** Adds its figures to the run's summary and writes its files into {@code folder}. */
    void finish(Map<String, Object> summary, Path folder) throws IOException;

    /**
     * The names of the files {@link #finish} writes into the run's folder, which the run lists in its manifest
     * before they are written (so that a later run in the folder removes them, and the summary lists them); none
     * by default.
     */
    default java.util.List<String> files() {
        return java.util.List.of();
    }
}
