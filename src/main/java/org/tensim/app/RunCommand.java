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
                + " and duration come from the file's run block unless given here."})
public final class RunCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "The scene file (.yaml, .yml or .json).")
    Path file;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "run", OutFolderOption.SPEC_NAME));

    @Option(names = "--set", paramLabel = "KEY.PATH=VALUE",
            description = "Replaces one value of the file, for example --set bodies.mss.stiffness=\"200 N/m\""
                    + " (repeatable).")
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
        OptionChecks.stepFits(spec, "--dt", run.dtS(), "--seconds", run.durationS());
        return RunFolder.run(folder, "run", List.of(run.csv()), f -> {
            Map<String, Object> s = SceneRunner.run(scene, run, f);
            System.out.println("wrote " + f.dir().resolve(run.csv()) + ", " + f.dir().resolve(RunFolder.SUMMARY));
            System.out.println(Json.line(s));
        });
    }
}
