package org.tensim.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.cli.IntegratorOption;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.OutFolderOption;
import org.tensim.cli.TimeStepOption;
import org.tensim.experiment.SceneExpectations;
import org.tensim.experiment.SceneRunner;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.scene.file.RunSettings;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneLoader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code tensim run FILE}: runs a scene file headless and writes its probes' CSV and summary.json. */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Runs a scene file (docs/scenes.md) headless.",
            "It writes to --out the probes' CSV (the run block's csv; units in the column names) and summary.json (the"
                + " file's digest and every --set), and prints the summary as the last line (JSON). Integrator, step"
                + " and duration come from the file's run block unless given here.",
            "The checks of the file's expect block are evaluated after the run: each one's measured value and verdict"
                + " are printed and written to summary.json, and a run that fails one ends with status"
                + " expectation_failed and exit code 3, its outputs kept."})
public final class RunCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "The scene file (.yaml, .yml or .json).")
    Path file;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "run", OutFolderOption.SPEC_NAME));

    @Option(names = "--set", paramLabel = "KEY.PATH=VALUE",
            description = "Replaces one value of the file, for example --set bodies.mss.stiffness=\"200 N/m\", or"
                    + " sets one of its named parameters, for example --set E=8kPa (a bare number is in the"
                    + " parameter's unit, and the value must lie in its range); repeatable.")
    List<String> sets = new ArrayList<>();

    @picocli.CommandLine.Mixin
    IntegratorOption integrator = new IntegratorOption();

    @picocli.CommandLine.Mixin
    TimeStepOption dt = TimeStepOption.chosenByScene("the file's run.dt");

    @Option(names = {"--seconds", "--duration"}, paramLabel = "S",
            description = "Simulated time, s (default: the file's run.duration).")
    Double duration;

    @Override
    public Integer call() throws Exception {
        Path folder = out.folder(spec, file);
        Scene scene = SceneLoader.load(file, sets);
        var parsed = spec.commandLine().getParseResult();
        String name = null;
        if (parsed.hasMatchedOption("--integrator")) {
            integrator.create(spec);
            name = integrator.name();
        }
        double step = dt.seconds(spec);
        if (duration != null) {
            CommandChecks.positive(spec, "--seconds", duration, "s");
        }
        RunSettings run = scene.run().with(name, step > 0 ? step : null, duration);
        var diaphragm = DiaphragmSceneRun.diaphragm(scene);
        if (diaphragm != null) {
            return DiaphragmSceneRun.run(spec, scene, diaphragm, run, folder, out.overwrite());
        }
        OptionChecks.stepFits(spec, "--dt", run.dtS(), "--seconds", run.durationS());
        return RunFolder.run(folder, "run", List.of(run.csv()), f -> {
            Map<String, Object> s = SceneRunner.run(scene, run, f);
            System.out.println("wrote " + f.dir().resolve(run.csv()) + ", " + f.dir().resolve(RunFolder.SUMMARY));
            printExpectations(scene, s);
            System.out.println(Json.line(s));
        });
    }

    /** One line per check of the expect block; a failed one also on standard error. */
    @SuppressWarnings("unchecked")
    static void printExpectations(Scene scene, Map<String, Object> summary) {
        Object outcomes = summary.get("expectations");
        if (!(outcomes instanceof List<?> list)) {
            return;
        }
        for (int i = 0; i < list.size(); i++) {
            String line = SceneExpectations.line(scene.expect().get(i), (Map<String, Object>) list.get(i));
            System.out.println(line);
            if (line.startsWith("FAIL")) {
                System.err.println("tensim run: expectation failed: " + line.substring("FAIL: ".length()));
            }
        }
    }
}
