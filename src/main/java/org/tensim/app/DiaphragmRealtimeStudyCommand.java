package org.tensim.app;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.cli.OutFolderOption;
import org.tensim.experiment.diaphragm.RealTimeStudy;
import org.tensim.experiment.diaphragm.ThoraxRealTimeStudy;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.tuning.DiaphragmOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/** {@code tensim diaphragm realtime-study}: speed against error over resolutions and integrators. */
@Command(name = "realtime-study", mixinStandardHelpOptions = true,
        description = {"Measures speed against error over resolutions and integrators, and picks the fastest setting"
            + " within 5 %% of RK2.",
            "Runs the generated double dome at 10 to 43 rings with RK2 (1 and 2 threads), implicit Euler and bdf2"
                + " at several steps, one inspiration each, and sets the error against the paper's configuration"
                + " against the real-time factor. Writes realtime.csv, realtime.png and realtime.json"
                + " (docs/diaphragm.md).",
            "With --thorax it runs the real-time setting on the mesh in the thorax against the converged contact"
                + " step at 5 ms, and measures its step's cost with and without contact (realtime.csv and"
                + " realtime.json; docs/thorax.md)."})
public final class DiaphragmRealtimeStudyCommand implements Callable<Integer> {
    /** Outputs, written by the study into --out. */
    static final List<String> OUTPUTS = List.of("realtime.csv", "realtime.png", "realtime.json");

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Mixin
    DiaphragmOptions scene = new DiaphragmOptions();

    @Option(names = "--seconds", paramLabel = "S", description = "Simulated time of each run, s (default:"
            + " ${DEFAULT-VALUE}).")
    double seconds = 4;

    @Option(names = "--study-rings", split = ",", paramLabel = "N[,N...]", hideParamSyntax = true,
            description = "Ring counts, ascending (default: 10,14,20,28,43).")
    int[] studyRings;

    @Option(names = "--study-configs", paramLabel = "REGEX",
            description = "Run the configurations whose label this finds (RK2 on two threads, the reference of each"
                    + " resolution, always runs).")
    String studyConfigs;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "diaphragm-realtime"));

    @Override
    public Integer call() throws Exception {
        DiaphragmSpec s = CommandChecks.scene(spec, scene, null, DiaphragmSpec.PAPER_RINGS);
        Path folder = out.folder(spec);
        CommandChecks.positive(spec, "--seconds", seconds, "s");
        DiaphragmCommand.checkRings(spec, studyRings);
        boolean thorax = s.cage().thorax() != null;
        if (thorax && (studyRings != null || !s.cage().contact())) {
            throw usage("with --thorax the real-time study runs the one scene given, with contact: leave out"
                    + (studyRings != null ? " --study-rings" : " --no-contact"));
        }
        if (!thorax && (s.cage().boneSurfaces() || s.mesh().labels() != null || scene.mesh != null)) {
            throw usage("the real-time study runs the generated double dome held by its band at its --study-rings,"
                    + " or a mesh in a thorax (--thorax): leave out --mesh, --cage surfaces and --labels, or add"
                    + " --thorax");
        }
        java.util.regex.Pattern only;
        try {
            only = studyConfigs == null ? null : java.util.regex.Pattern.compile(studyConfigs);
        } catch (java.util.regex.PatternSyntaxException e) {
            throw usage("--study-configs is not a regular expression: " + e.getDescription() + " in '" + studyConfigs
                    + "'");
        }
        if (thorax) {
            final java.util.regex.Pattern configs = only;
            return RunFolder.run(folder, "diaphragm realtime-study", OUTPUTS, out.overwrite(), run -> {
                run.file("realtime.csv");
                run.file("realtime.json");
                DiaphragmSetup.Inputs in = DiaphragmSetup.read(s);
                DiaphragmScene withContact = DiaphragmSetup.build(in, s, s.newControls()).scene();
                DiaphragmSpec off = s.withCage(s.cage().withContact(false));
                DiaphragmScene without = DiaphragmSetup.build(in, off, off.newControls()).scene();
                // The kept reference is named by the definition and the files' contents, so an edited file is seen.
                java.util.List<Path> files = new java.util.ArrayList<>();
                if (!s.mesh().generated()) {
                    files.add(s.mesh().file());
                }
                files.add(s.cage().thorax());
                String definition = s + " " + org.tensim.io.FileDigest.of(files);
                Map<String, Object> r = ThoraxRealTimeStudy.run(withContact, without, in.source(), definition,
                        configs, seconds, folder, System.out);
                System.out.println(Json.line(run.finish(RunStatus.OK, r)));
            });
        }
        return RunFolder.run(folder, "diaphragm realtime-study", OUTPUTS, out.overwrite(), run -> {
            for (String n : OUTPUTS) {
                run.file(n);
            }
            Map<String, Object> r = RealTimeStudy.run(studyRings != null ? studyRings : RealTimeStudy.RINGS, only,
                    s.cage().boxes(), s.tissue(), s.boundary(), s.breathing().cycle(), s.newControls(), seconds, folder,
                    System.out);
            System.out.println(Json.line(run.finish(RunStatus.OK, r)));
        });
    }

    private ParameterException usage(String message) {
        return new ParameterException(spec.commandLine(), message);
    }
}
