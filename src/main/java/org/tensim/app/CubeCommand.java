package org.tensim.app;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.tensim.experiment.CubeReport;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.CubeParameters;
import org.tensim.cli.IntegratorOption;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.OutFolderOption;
import org.tensim.cli.TimeStepOption;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim cube}: the paper's Fig. 3 comparison, scripted. */
@Command(name = "cube", mixinStandardHelpOptions = true,
        description = {"Runs the paper's cube experiment (Fig. 3): a mass-spring and a tensegrity cube under the same"
            + " force.",
            "The two cubes (10 x 10 x 10 m, bottom fixed) are identical but for the six rigid links, under the same"
                + " sinusoidal force on two upper nodes. Writes cube.csv, cube.png and summary.json to --out and"
                + " prints the summary as the last line (JSON). Defaults: docs/cube.md."})
public final class CubeCommand implements Callable<Integer> {
    private static final CubeParameters D = CubeParameters.paper();

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "cube"));

    @Option(names = {"--seconds", "--duration"}, paramLabel = "S",
            description = "Simulated time, s (default: ${DEFAULT-VALUE}).")
    double duration = D.durationS();

    @picocli.CommandLine.Mixin
    TimeStepOption dt = TimeStepOption.fixed(D.dtS());

    @Option(names = "--force", paramLabel = "N",
            description = "Peak of the sinusoidal force on each loaded node, N (default: ${DEFAULT-VALUE}).")
    double force = D.forceAmplitudeN();

    @Option(names = "--frequency", paramLabel = "HZ", description = "Force frequency, Hz (default: ${DEFAULT-VALUE}).")
    double frequency = D.forceFrequencyHz();

    @Option(names = "--tilt", paramLabel = "DEG",
            description = "Force angle from straight down towards +x, degrees (default: ${DEFAULT-VALUE}).")
    double tilt = D.forceTiltDeg();

    @Option(names = "--stiffness", paramLabel = "N/M",
            description = "Spring stiffness, N/m (default: ${DEFAULT-VALUE}).")
    double stiffness = D.stiffnessNPerM();

    @Option(names = "--damping", paramLabel = "NS/M",
            description = "Spring axial damping, N s/m (default: ${DEFAULT-VALUE}).")
    double damping = D.dampingNsPerM();

    @Option(names = "--mass", paramLabel = "KG", description = "Mass of every node, kg (default: ${DEFAULT-VALUE}).")
    double mass = D.nodeMassKg();

    @picocli.CommandLine.Mixin
    IntegratorOption integrator = new IntegratorOption();

    @Override
    public Integer call() throws Exception {
        Path folder = out.folder(spec);
        CommandChecks.positive(spec, "--seconds", duration, "s");
        double step = dt.seconds(spec);
        OptionChecks.stepFits(spec, "--dt", step, "--seconds", duration);
        integrator.create(spec);
        CubeParameters p;
        try {
            p = new CubeParameters(D.sideM(), mass, stiffness, damping, force, frequency, tilt, step, duration);
        } catch (IllegalArgumentException e) {
            throw CommandChecks.usage(spec, e.getMessage());
        }
        return RunFolder.run(folder, "cube", CubeReport.OUTPUTS, out.overwrite(), run -> {
            CubeReport report = CubeReport.run(p, integrator.name(), run);
            System.out.println("wrote " + report.csv() + ", " + report.chart() + ", " + report.summaryFile());
            if (report.status() == RunStatus.DIVERGED) {
                spec.commandLine().getErr().println("tensim cube: " + report.summary().get("diverged")
                        + " (the CSV ends at the last finite step; the chart is marked DIVERGED)");
            }
            System.out.println(report.summaryLine());
        });
    }
}
