package org.tensim.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.analysis.lungs.FourDctComparison;
import org.tensim.analysis.lungs.LungPointsFolder;
import org.tensim.analysis.lungs.MeasuredCase;
import org.tensim.analysis.lungs.ModelFigures;
import org.tensim.analysis.lungs.ModelMotion;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.OutFolderOption;
import org.tensim.io.ProjectFolder;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.io.landmarks.LandmarkFormatException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code tensim validate-4dct}: a run's lung motion against the five DIR-Lab patients (docs/lungs.md). The run's
 * points come from its folder ({@link LungPointsFolder}); a run made in the same process hands its
 * {@link ModelMotion} to {@link #validate} instead.
 */
@Command(name = "validate-4dct", mixinStandardHelpOptions = true,
        description = {"Compares a run's lung motion with the DIR-Lab 4D-CT landmarks of five patients, in"
            + " normalised terms (docs/lungs.md).",
            "Reads the run folder's lung-points.csv and its summary.json's lung_points (end-exhale, end-inhale,"
                + " period, superior direction). Per lung and for both: the superior-inferior displacement from"
                + " end-exhale to end-inhale in five bins of normalised height (0 apex, 1 base) as ratios to the"
                + " basal bin, the basal SI and mean 3D displacements, and each phase's share of the end-inhale"
                + " displacement (phase tNN taken NN%% of the period after end-inhale), for the model and each case,"
                + " with the targets' verdicts. Writes validate-4dct.png, caseN.csv and summary.json to --out."})
public final class Validate4dctCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--run", required = true, paramLabel = "DIR", description = "The folder of a run of the lungs:"
            + " its lung-points.csv and summary.json.")
    Path runFolder;

    @Option(names = "--landmarks", paramLabel = "DIR", description = "The folder of the caseN-300-ee-ei.csv and"
            + " caseN-75-six-phases.csv files (default: ../shared/data/4dct-lung-landmarks).")
    Path landmarks;

    @Option(names = "--cases", split = ",", paramLabel = "N[,N...]",
            description = "The cases to compare with, 1 to 5 (default: ${DEFAULT-VALUE}).")
    List<Integer> cases = List.of(1, 2, 3, 4, 5);

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "validate-4dct"));

    /** The name of the command, as its summary says. */
    static final String NAME = "validate-4dct";

    /** The files this command writes into --out besides summary.json (docs/outputs.md). */
    static final List<String> OUTPUTS = List.of(Validate4dctOutputs.CHART, "case1.csv", "case2.csv", "case3.csv",
            "case4.csv", "case5.csv");

    @Override
    public Integer call() throws Exception {
        Path dir = landmarks != null ? landmarks : ProjectFolder.resolve("..", "shared", "data", "4dct-lung-landmarks");
        if (!Files.isDirectory(dir)) {
            throw OptionChecks.usage(spec, "--landmarks " + dir + ": no such folder (expected the folder of the"
                    + " DIR-Lab caseN-300-ee-ei.csv and caseN-75-six-phases.csv files)");
        }
        if (!Files.isDirectory(runFolder)) {
            throw OptionChecks.usage(spec, "--run " + runFolder + ": no such folder (expected the folder of a run"
                    + " of the lungs, with lung-points.csv)");
        }
        for (int n : cases) {
            if (n < 1 || n > 5) {
                throw OptionChecks.usage(spec, "--cases " + n + ": expected a case from 1 to 5");
            }
        }
        ModelMotion motion;
        List<MeasuredCase> measured;
        try {
            motion = LungPointsFolder.read(runFolder);
        } catch (LandmarkFormatException | IllegalArgumentException e) {
            throw OptionChecks.usage(spec, "--run " + runFolder + ": " + e.getMessage());
        }
        try {
            measured = read(dir, cases);
        } catch (LandmarkFormatException e) {
            throw OptionChecks.usage(spec, "--landmarks " + dir + ": " + e.getMessage());
        }
        Path outDir = out.folder(spec);
        PrintWriter pw = spec.commandLine().getOut();
        return RunFolder.run(outDir, NAME, OUTPUTS, out.overwrite(), run -> {
            Map<String, Object> fields = new LinkedHashMap<>();
            fields.put("run", runFolder.toString());
            validate(run, motion, measured, dir, fields, pw);
        });
    }

    /** The measured cases {@code numbers} of {@code folder}. */
    static List<MeasuredCase> read(Path folder, List<Integer> numbers) throws IOException, LandmarkFormatException {
        List<MeasuredCase> list = new ArrayList<>();
        for (int n : numbers) {
            list.add(MeasuredCase.read(folder, n));
        }
        return list;
    }

    /**
     * The comparison of {@code motion} with {@code measured} (read from {@code landmarks}) written into
     * {@code run} (chart, a CSV per case) and finished with the summary: {@code fields} first, then the
     * comparison's figures and verdicts. The seam for a run of the lungs made in this process: it calls this with
     * its own {@link ModelMotion} and folder. Prints the figures and verdicts to {@code out} (may be null), then the summary as one line of JSON.
     */
    public static FourDctComparison validate(RunFolder run, ModelMotion motion, List<MeasuredCase> measured,
            Path landmarks, Map<String, Object> fields, PrintWriter out) throws IOException {
        FourDctComparison c = FourDctComparison.of(ModelFigures.of(motion), measured);
        Validate4dctOutputs.write(run, c);
        Map<String, Object> summary = new LinkedHashMap<>(fields);
        summary.put("landmarks", "DIR-Lab (Castillo et al. 2009, 2010) in " + landmarks);
        summary.put("phase_rule", "phase tNN at end_inhale_s + NN/100 * period_s; shares: least-squares factor of"
                + " the end-exhale-to-end-inhale field of the model's own points");
        summary.putAll(c.toMap());
        Map<String, Object> written = run.finish(RunStatus.OK, summary);
        if (out != null) {
            Validate4dctOutputs.print(out, c);
            out.println("wrote " + run.dir());
            out.println(org.tensim.io.Json.line(written));
            out.flush();
        }
        return c;
    }
}
