package org.tensim.app;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.tensim.cli.OutFolderOption;
import org.tensim.io.Json;
import org.tensim.sweep.SpecReader;
import org.tensim.sweep.Sweep;
import org.tensim.sweep.SweepEngine;
import org.tensim.sweep.SweepSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim sweep}: a parameter sweep of headless runs, on all local cores or on Spark. */
@Command(name = "sweep", mixinStandardHelpOptions = true,
        description = {"Runs a parameter sweep: every point of a grid or Latin hypercube is an independent headless"
            + " run.",
            "Each point is a run of a scene with the GUI's parameters and ranges. Writes results.csv as points"
                + " finish (parameters, summary fields, status ok, diverged or refused with its message, wall time),"
                + " charts/OUTPUT-vs-PARAMETER.png and sweep.json to --out. Started again on the same --out it"
                + " resumes, skipping the points already done. Spec format and engines: docs/scaling.md."})
public final class SweepCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--spec", paramLabel = "FILE", required = true, description = "The sweep spec (JSON).")
    Path specFile;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "sweep", OutFolderOption.SPEC_NAME));

    @picocli.CommandLine.Mixin
    EngineOptions engines = new EngineOptions();

    /** What a sweep writes into --out (it writes no summary.json: these names tell its folder, which it resumes). */
    static final java.util.List<String> OUTPUTS = java.util.List.of("results.csv", "charts", "sweep.json");

    @Override
    public Integer call() throws Exception {
        SweepSpec s;
        try {
            s = SpecReader.readSweep(specFile);
        } catch (SpecReader.SpecException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        Path dir = out.folder(spec, specFile);
        org.tensim.io.FolderClaim.check(dir, "sweep", OUTPUTS, out.overwrite());
        try (SweepEngine e = engines.create(spec.commandLine())) {
            System.out.println("sweep of " + s.setup().geometry() + " on " + e.describe() + " into " + dir);
            Sweep.Outcome o = Sweep.run(s, dir, e, System.console() != null, System.out);
            System.out.println("wrote " + dir.resolve("results.csv") + ", charts/, sweep.json");
            System.out.println(Json.line(o.summary()));
        }
        return 0;
    }
}
