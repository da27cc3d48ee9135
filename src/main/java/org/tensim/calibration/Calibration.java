package org.tensim.calibration;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import org.tensim.sweep.PointResult;
import org.tensim.sweep.ResultsFile;
import org.tensim.sweep.SceneRun;
import org.tensim.sweep.SweepEngine;

/**
 * A calibration into a folder: every run appended to {@code evaluations.csv} as it finishes
 * (parameters, status, targets' fields, scene summary fields and the objective), then the
 * files of {@link CalibrationReport}.
 */
public final class Calibration {
    private Calibration() {
    }

    /** Runs the spec on the engine, writes everything into {@code out}, returns the outcome and summary. */
    public static Result run(CalibrationSpec spec, SweepEngine engine, Path out, PrintStream log) throws IOException,
            InterruptedException {
        Files.createDirectories(out);
        Path csv = out.resolve("evaluations.csv");
        Files.deleteIfExists(csv); // a calibration starts afresh: its runs depend on the whole history
        LinkedHashSet<String> fields = new LinkedHashSet<>();
        for (Target t : spec.targets()) {
            fields.addAll(t.fields());
        }
        fields.addAll(SceneRun.knownFields(spec.setup().scene()));
        List<String> outputs = new ArrayList<>(fields);
        outputs.add("objective");
        outputs.add("generation");
        Calibrator.Outcome o;
        try (ResultsFile file = new ResultsFile(csv, spec.names(), outputs)) {
            o = Calibrator.run(spec, engine, e -> {
                Map<String, Double> f = new LinkedHashMap<>(e.result().fields());
                f.put("objective", e.fitness());
                f.put("generation", (double) e.generation());
                PointResult r = e.result();
                file.write(new PointResult(r.id(), r.values(), r.status(), r.message(), f, r.wallS(), r.cpuS()));
            }, log);
        }
        Map<String, Object> summary = CalibrationReport.write(out, spec, o, engine.describe());
        return new Result(o, summary);
    }

    /** The outcome and the summary written to residuals.json. */
    public record Result(Calibrator.Outcome outcome, Map<String, Object> summary) {
    }
}
