package org.tensim.app;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.tensim.experiment.SceneExpectations;
import org.tensim.experiment.SceneProbeRecorder;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.io.FileDigest;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.file.RunSettings;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/**
 * {@code tensim run} of a scene file whose body is a {@code type: diaphragm}: the diaphragm's experiment as
 * {@code tensim diaphragm} runs it ({@link DiaphragmCommand#report}, the same outputs and summary figures), its
 * integrator, step and duration from the file's run block ({@code dt: auto} for the step the time-step policy
 * recommends, the command's default), with the scene file, its digest and the overrides added to the summary.
 * The diaphragm brings its own attachments, loads and outputs: the loader refuses other bodies and zones beside it
 * ({@link org.tensim.scene.file.BodyType#standalone()}); the file's conditions are already on its nodes, and its
 * probes are recorded during the run into the run block's CSV ({@link SceneProbeRecorder}, as {@code tensim run}
 * of any file), their columns' ranges in the summary. Without probes the summary is the command's to the bit. Its
 * {@code expect:} checks read the summary's breathing figures and the probes' columns, and a failed one gives
 * status expectation_failed (exit code 3), its outputs kept.
 */
final class DiaphragmSceneRun {
    private DiaphragmSceneRun() {
    }

    /** The scene's diaphragm body, or null when it has none. */
    static SceneBody diaphragm(Scene scene) {
        for (SceneBody b : scene.bodies().values()) {
            if (b.built() instanceof DiaphragmSetup.Built) {
                return b;
            }
        }
        return null;
    }

    /** Runs the scene's diaphragm into {@code folder}. */
    static int run(CommandSpec spec, Scene scene, SceneBody body, RunSettings run, Path folder, boolean overwrite)
            throws Exception {
        DiaphragmSetup.Built built = (DiaphragmSetup.Built) body.built();
        DiaphragmSpec d = built.scene().spec();
        double period = d.breathing().periodS();
        if (run.dtS() > period) {
            throw new ParameterException(spec.commandLine(), "the step " + run.dtS() + " s is longer than one"
                    + " breathing period (" + period + " s)");
        }
        Integrator integrator = DiaphragmSolverOptions.contactDefaults(Integrators.create(run.integrator()),
                run.integrator(), d);
        DiaphragmReport.Options o = new DiaphragmReport.Options(run.durationS(), run.dtS(), 8, 100, 0.01, null);
        boolean probed = !scene.probes().isEmpty();
        if (probed && DiaphragmReport.OUTPUTS.contains(run.csv())) {
            throw new ParameterException(spec.commandLine(), "run.csv " + run.csv() + " is a file the diaphragm's run"
                    + " writes itself: name the probes' CSV otherwise (default probes.csv)");
        }
        List<String> outputs = new java.util.ArrayList<>(DiaphragmReport.OUTPUTS);
        if (probed) {
            outputs.add(run.csv());
        }
        return RunFolder.run(folder, "run", outputs, overwrite, f -> {
            org.tensim.scene.diaphragm.RunRecorder own = built.scene().recorder();
            SceneProbeRecorder probes = probed ? new SceneProbeRecorder(scene, body.name(), run.every(),
                    f.csv(run.csv(), SceneExpectation.columns(scene.probes()), 1000), own) : null;
            Map<String, Object> fields;
            if (probes == null) {
                fields = DiaphragmCommand.report(f, built, o, integrator, null, 0, null, null);
            } else {
                // The probes are recorded beside the organs' recorder, for this run only.
                built.scene().setRecorder(probes);
                try {
                    fields = DiaphragmCommand.report(f, built, o, integrator, null, 0, null, null);
                } finally {
                    built.scene().setRecorder(own);
                }
            }
            fields.put("scene", scene.file().toString());
            fields.put("scene_digest", FileDigest.of(List.of(scene.file())));
            fields.put("overrides", scene.overrides());
            if (scene.expect().isEmpty()) {
                DiaphragmCommand.finish(spec, f, fields);
                return;
            }
            // The file's checks read the summary's figures and the probes' columns, evaluated as SceneRunner does.
            List<Map<String, Object>> outcomes = SceneExpectations.evaluate(scene.expect(),
                    probes == null ? null : probes.columns(), fields);
            long failed = SceneExpectations.failed(outcomes);
            fields.put("expectations", outcomes);
            fields.put("expectations_failed", failed);
            RunCommand.printExpectations(scene, fields);
            if (fields.containsKey("diverged") || failed == 0) {
                DiaphragmCommand.finish(spec, f, fields);
            } else {
                Map<String, Object> summary = f.finish(RunStatus.EXPECTATION_FAILED, fields);
                System.out.println(Json.line(summary));
            }
        });
    }
}
