package org.tensim.experiment;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.CsvWriter;
import org.tensim.scene.diaphragm.RunRecorder;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;

/**
 * Records a scene file's probes during a run that is not {@link SceneRunner}'s (the diaphragm's own,
 * {@code tensim run} of a {@code type: diaphragm} file) exactly as SceneRunner does: one CSV row of every probe's
 * values ({@link SceneRunner#sample}) at the start and after every {@code every}-th step, the columns' minimum and
 * maximum added to the summary as {@code columns}, and the rows' statistics kept for the file's {@code expect:}
 * checks ({@link #columns()}). It runs beside the run's own recorder, if any, which it calls first.
 */
public final class SceneProbeRecorder implements RunRecorder {
    private final Scene scene;
    private final String body;
    private final long every;
    private final CsvWriter csv;
    private final RunRecorder inner;
    private final double[] row;
    private final SceneExpectations.Columns stats;
    private final List<String> header;
    private Map<SceneProbe, int[]> springs;
    private long steps;

    /**
     * @param scene the loaded file (its probes are read on {@code body})
     * @param body  the name of the body the run simulates
     * @param every a row every this many steps (&gt;= 1)
     * @param csv   the CSV, its header {@link SceneExpectation#columns} of the scene's probes; closed by
     *              {@link #finish}
     * @param inner the run's own recorder, or null
     */
    public SceneProbeRecorder(Scene scene, String body, long every, CsvWriter csv, RunRecorder inner) {
        if (every < 1) {
            throw new IllegalArgumentException("a probe row every " + every + " steps: expected at least 1");
        }
        this.scene = scene;
        this.body = body;
        this.every = every;
        this.csv = csv;
        this.inner = inner;
        this.header = SceneExpectation.columns(scene.probes());
        this.row = new double[header.size()];
        this.stats = new SceneExpectations.Columns(header);
    }

    @Override
    public void begin(Simulation sim, double measuredStartS, double inspirationEndS, double periodS) {
        if (inner != null) {
            inner.begin(sim, measuredStartS, inspirationEndS, periodS);
        }
        springs = SceneRunner.energySprings(scene, Map.of(body, sim));
        steps = 0;
        sample(sim);
    }

    @Override
    public void afterStep(Simulation sim) {
        if (inner != null) {
            inner.afterStep(sim);
        }
        if (++steps % every == 0) {
            sample(sim);
        }
    }

    private void sample(Simulation sim) {
        SceneRunner.sample(scene, Map.of(body, sim), springs, sim.time(), row);
        stats.add(row);
        try {
            csv.row(row);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + csv.path(), e);
        }
    }

    /** The files of the recorder it wraps (its own CSV is the run folder's already). */
    @Override
    public java.util.List<String> files() {
        return inner == null ? java.util.List.of() : inner.files();
    }

    /** Closes the CSV and puts each column's minimum and maximum under {@code columns}, as SceneRunner's summary. */
    @Override
    public void finish(Map<String, Object> summary, Path folder) throws IOException {
        if (inner != null) {
            inner.finish(summary, folder);
        }
        csv.close();
        Map<String, Object> range = new LinkedHashMap<>();
        for (int c = 1; c < header.size(); c++) {
            range.put(header.get(c), Map.of("min", SceneRunner.finite(stats.min(c)), "max",
                    SceneRunner.finite(stats.max(c))));
        }
        summary.put("columns", range);
    }

    /** The rows' statistics, for the file's column checks ({@link SceneExpectations#evaluate}). */
    public SceneExpectations.Columns columns() {
        return stats;
    }
}
