package org.tensim.app;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.cli.OutFolderOption;
import org.tensim.experiment.diaphragm.ResolutionPick;
import org.tensim.experiment.diaphragm.ResolutionStudy;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.Decimation;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.tuning.DiaphragmOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/** {@code tensim diaphragm resolution-study}: the same scene at several resolutions against the finest. */
@Command(name = "resolution-study", mixinStandardHelpOptions = true,
        description = {"Runs the diaphragm at several resolutions, each against the finest, and picks the coarsest"
            + " within --tolerance.",
            "It reports the error and the order, and the coarsest model within --tolerance (the pick, written to"
                + " resolution-pick.json in --out or to --pick-out FILE; diaphragm and gui open at it with --pick FILE)."
                + " The models are generated double domes by --study-rings, or --mesh decimated (--cells) and refined"
                + " (--refine); with --thorax every model is in that thorax. Writes resolution.csv, resolution.png and"
                + " resolution.json (docs/diaphragm.md)."})
public final class DiaphragmResolutionCommand implements Callable<Integer> {
    /** Outputs, written by the study into --out. */
    static final List<String> OUTPUTS = List.of("resolution.csv", "resolution.png", "resolution.json",
            ResolutionPick.NAME, "resolution-nodes.csv");

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Mixin
    DiaphragmOptions scene = new DiaphragmOptions();

    @Mixin
    DiaphragmSolverOptions solver = new DiaphragmSolverOptions();

    @Option(names = "--seconds", paramLabel = "S", description = "Simulated time of each model, s, at most one"
            + " inspiration (default: one inspiration).")
    double seconds = 4;

    @Option(names = "--study-rings", split = ",", paramLabel = "N[,N...]", hideParamSyntax = true,
            description = "Ring counts of the generated double domes, ascending, the finest as reference; a pick"
                    + " when the finest is 43 (default: 10,14,20,28,43).")
    int[] studyRings;

    @Option(names = "--tolerance", paramLabel = "E",
            description = "Relative RMS error under which a coarser model is accepted (default: ${DEFAULT-VALUE}).")
    double tolerance = ResolutionStudy.TOLERANCE;

    @Option(names = "--cells", paramLabel = "MM[,MM...]", split = ",", hideParamSyntax = true,
            description = "With --mesh: vertex-clustering cell sizes or, with --decimation quadric, target edge"
                    + " lengths, mm (default: 4, 2.8 and 2 times the mesh's mean edge length).")
    double[] cellsMm;

    @Option(names = "--decimation", paramLabel = "KIND", converter = DecimationConverter.class,
            description = "With --mesh: clustering (--cells are cube sizes) or quadric (edge collapse by quadric"
                    + " error, --cells are target edge lengths) (default: clustering).")
    Decimation decimation = Decimation.CLUSTERING;

    @Option(names = "--refine", paramLabel = "N",
            description = "With --mesh: also the mesh refined 1..N times by midpoint subdivision"
                    + " (default: ${DEFAULT-VALUE}).")
    int refine;

    @Option(names = "--pick-out", paramLabel = "FILE",
            description = "Write the pick (the default study's) to FILE instead of resolution-pick.json in --out.")
    Path pickOut;

    /** Kept for scripts: the pick once also went to the project's meshes folder unless this was given. */
    @Option(names = "--no-pick", hidden = true)
    boolean formerNoPick;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "diaphragm-resolution"));

    @Override
    public Integer call() throws Exception {
        DiaphragmSpec s = CommandChecks.scene(spec, scene, null, DiaphragmSpec.PAPER_RINGS);
        solver.check(spec, s, seconds);
        Path folder = out.folder(spec);
        CommandChecks.positive(spec, "--seconds", seconds, "s");
        DiaphragmCommand.checkRings(spec, studyRings);
        boolean againstPaper = studyRings == null
                || studyRings[studyRings.length - 1] == ResolutionPick.REFERENCE_RINGS;
        if (pickOut != null && (!againstPaper || scene.mesh != null)) {
            throw usage("--pick-out: only a study of the double domes against " + ResolutionPick.REFERENCE_RINGS
                    + " rings makes a pick; leave out " + (scene.mesh != null ? "--mesh" : "--study-rings "
                    + java.util.Arrays.toString(studyRings)) + " or --pick-out");
        }
        if (pickOut != null && (pickOut.toString().isBlank() || java.nio.file.Files.isDirectory(pickOut))) {
            throw usage("--pick-out must name a file to write, got '" + pickOut + "'");
        }
        if (s.mesh().labels() != null) {
            throw usage("--labels cannot go with the resolution study: a label file names the vertices of one mesh,"
                    + " and the study decimates it");
        }
        boolean ownMesh = scene.mesh != null;
        if (s.cage().surfaces()) {
            throw usage("--cage surfaces cannot go with the resolution study yet: its generated models are held by the"
                    + " band on the cage's segments (use --thorax with --mesh for bone surfaces)");
        }
        if (decimation != Decimation.CLUSTERING && !ownMesh) {
            throw usage("--decimation " + decimation.name().toLowerCase(java.util.Locale.ROOT) + " needs --mesh: the"
                    + " generated double domes are generated at each resolution, not decimated");
        }
        if (s.cage().thorax() != null && !ownMesh) {
            throw usage("the resolution study with --thorax needs --mesh: the diaphragm registered to that thorax");
        }
        if (refine < 0 || cellsMm != null && java.util.Arrays.stream(cellsMm).anyMatch(c -> !(c > 0))) {
            throw usage("--refine must be 0 or more and --cells positive sizes in mm, got " + refine + " and "
                    + java.util.Arrays.toString(cellsMm));
        }
        ResolutionStudy.Thorax inThorax = s.cage().thorax() == null ? null : new ResolutionStudy.Thorax(s,
                DiaphragmSetup.read(s), () -> solver.create(s), solver.dt());
        ResolutionStudy.Setup rs;
        try {
            rs = new ResolutionStudy.Setup(DiaphragmSetup.boxes(s.cage().boxes()), s.tissue(), s.boundary(),
                    s.breathing().cycle(), s.newControls(), Math.min(seconds, s.breathing().cycle().inspirationS()),
                    tolerance, System.out, inThorax);
        } catch (IllegalArgumentException e) {
            throw usage("--tolerance: " + e.getMessage());
        }
        DiaphragmSpec.Mesh m = s.mesh();
        return RunFolder.run(folder, "diaphragm resolution-study", OUTPUTS, out.overwrite(), run -> {
            for (String n : OUTPUTS) {
                run.file(n);
            }
            Map<String, Object> r = ownMesh
                    ? ResolutionStudy.runMesh(m.file(), m.units(), m.cleaning(), m.offsetThicknessM(), cellsMm,
                            decimation, refine, rs, folder)
                    : studyRings != null ? ResolutionStudy.runRings(rs, studyRings, folder,
                            againstPaper ? pickFile(folder) : null, pickScene(s))
                    : ResolutionStudy.run(rs, folder, pickFile(folder), pickScene(s));
            System.out.println(Json.line(run.finish(RunStatus.OK, r)));
        });
    }

    /**
     * The scene a pick records: the spec's, with the tendon rule the study's models are built with (the default:
     * the study does not take --tendon-rule).
     */
    static Map<String, Object> pickScene(DiaphragmSpec s) {
        return ResolutionPick.sceneOf(s.withTendonRule(DiaphragmSpec.DEFAULT_TENDON_RULE));
    }

    /** Where the default study writes its pick: {@code --pick-out}, else resolution-pick.json in the run folder. */
    Path pickFile(Path folder) {
        return pickOut != null ? pickOut : folder.resolve(ResolutionPick.NAME);
    }

    /**
     * {@code --decimation}: the model names' one parser ({@link BoundaryConditions#parse}), its message naming the
     * value and the choices.
     */
    static final class DecimationConverter implements picocli.CommandLine.ITypeConverter<Decimation> {
        @Override
        public Decimation convert(String value) {
            try {
                return BoundaryConditions.parse(Decimation.class, value);
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    private ParameterException usage(String message) {
        return new ParameterException(spec.commandLine(), message);
    }
}
