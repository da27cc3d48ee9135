package org.tensim.app;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.calibration.Calibration;
import org.tensim.calibration.CalibrationReader;
import org.tensim.calibration.CalibrationReport;
import org.tensim.calibration.CalibrationSpec;
import org.tensim.calibration.SyntheticTarget;
import org.tensim.cli.OutFolderOption;
import org.tensim.io.Json;
import org.tensim.sweep.SpecReader;
import org.tensim.sweep.SweepEngine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim calibrate}: fits parameters to targets with CMA-ES over the sweep engines. */
@Command(name = "calibrate", mixinStandardHelpOptions = true,
        description = {"Fits chosen parameters within bounds to weighted targets (CMA-ES, Hipparchus).",
            "Each generation's candidates run at once on the sweep engine. The targets are summary figures with"
                + " tolerances, landmark trajectories (CSV id,t,x,y,z) or a target surface at a breathing phase"
                + " (OBJ, STL or OFF; mean and 95th-percentile distance). Writes best-preset.json (for ./tensim gui"
                + " --preset; for a scene file best-set.txt, its --set options), history.csv, convergence.png,"
                + " residuals.json and evaluations.csv to --out.",
            "With --make-target it writes a synthetic target surface instead. Guide: docs/calibration.md."})
public final class CalibrateCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--spec", paramLabel = "FILE", required = true, description = "The calibration spec (JSON).")
    Path specFile;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "calibrate", OutFolderOption.SPEC_NAME));

    @picocli.CommandLine.Mixin
    EngineOptions engines = new EngineOptions();

    @Option(names = "--make-target", paramLabel = "FILE.obj",
            description = "Instead of calibrating: run the spec's scene at --truth and write its surface at --phase-s,"
                    + " with --noise-mm, as an OBJ in mm.")
    Path makeTarget;

    @Option(names = "--truth", paramLabel = "NAME=VALUE[,NAME=VALUE...]", split = ",", hideParamSyntax = true,
            description = "--make-target: parameter values of the run (others: the spec's fixed values or defaults).")
    Map<String, Double> truth = new LinkedHashMap<>();

    @Option(names = "--phase-s", paramLabel = "S", description = "--make-target: time of the surface, s.")
    double phaseS = Double.NaN;

    @Option(names = "--noise-mm", paramLabel = "MM",
            description = "--make-target: Gaussian noise per coordinate, mm (default: ${DEFAULT-VALUE}).")
    double noiseMm = 0;

    @Option(names = "--seed", paramLabel = "N",
            description = "--make-target: seed of the noise (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    /** What a calibration writes into --out (it writes no summary.json: these names tell its folder). */
    static final java.util.List<String> OUTPUTS = java.util.List.of("best-preset.json", "best-set.txt", "history.csv",
            "convergence.png", "residuals.json", "evaluations.csv");

    @Override
    public Integer call() throws Exception {
        if (makeTarget != null) {
            return makeTarget();
        }
        CalibrationSpec s;
        try {
            s = CalibrationReader.read(specFile);
        } catch (SpecReader.SpecException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        Path dir = out.folder(spec, specFile);
        org.tensim.io.FolderClaim.check(dir, "calibrate", OUTPUTS, out.overwrite());
        try (SweepEngine e = engines.create(spec.commandLine())) {
            System.out.println("calibrating " + s.names() + " of " + s.setup().geometry() + " on " + e.describe()
                    + " into " + dir);
            Calibration.Result r = Calibration.run(s, e, dir, System.out);
            boolean file = org.tensim.sweep.SceneFileRun.isFile(s.setup().scene());
            System.out.println("wrote " + dir.resolve(file ? "best-set.txt" : "best-preset.json") + ", history.csv,"
                    + " convergence.png,"
                    + " residuals.json, evaluations.csv");
            for (String w : CalibrationReport.warnings(s.free(), r.summary())) {
                System.err.println("tensim calibrate: " + w);
            }
            System.out.println(Json.line(r.summary()));
        }
        return 0;
    }

    private int makeTarget() {
        org.tensim.sweep.RunSetup setup;
        try {
            setup = CalibrationReader.readSetup(specFile);
        } catch (SpecReader.SpecException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        if (!(phaseS > 0 && phaseS <= setup.seconds())) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--phase-s must be within the"
                    + " spec's run (0, " + setup.seconds() + "] s, got " + phaseS);
        }
        for (Map.Entry<String, Double> e : truth.entrySet()) {
            try {
                org.tensim.sweep.SceneRun.parameter(setup.scene(), e.getKey()).validate(e.getValue(), "--truth");
            } catch (IllegalArgumentException ex) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(), ex.getMessage());
            }
        }
        SyntheticTarget.write(setup, truth, phaseS, noiseMm, seed, makeTarget);
        System.out.println("wrote " + makeTarget);
        return 0;
    }
}
