package org.tensim.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.bench.RealTimeSetting;
import org.tensim.bench.RealTimeStudy;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.experiment.diaphragm.ResolutionStudy;
import org.tensim.io.Json;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.ActionLines;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim diaphragm}: the paper's second experiment, headless. */
@Command(name = "diaphragm", mixinStandardHelpOptions = true,
        description = {"The paper's diaphragm (section 3.2): muscle as mass-spring, central",
            "tendon as tensegrity, driven by ribs (finite helical axes) and action",
            "lines, for some breathing cycles. Writes PNG displacement slices,",
            "displacements.csv, probe.csv, a VTK series and summary.json to --out and",
            "prints the summary as the last line (JSON). Model: docs/diaphragm.md."})
public final class DiaphragmCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--mesh", paramLabel = "FILE",
            description = "diaphragm mesh (.obj, .stl, .off): a thin closed shell, or one surface to offset"
                    + " (default: ${DEFAULT-VALUE})")
    Path mesh = DiaphragmSetup.DEFAULT_MESH;

    @Option(names = "--units", paramLabel = "mm|m", description = "units of the mesh file (default: ${DEFAULT-VALUE})")
    String units = "mm";

    @Option(names = "--thickness", paramLabel = "MM",
            description = "thickness used when the mesh is a single surface, mm (default: ${DEFAULT-VALUE})")
    double thicknessMm = 2.5;

    @Option(names = "--boxes", paramLabel = "FILE",
            description = "rib and sternum boxes, mm, BodyParts3D frame, e.g. BodyParts3D's"
                    + " ../shared/meshes/bodyparts3d/rib-sternum-bounds-mm.json (default: the project's parametric"
                    + " rib cage, placed on the generated dome)")
    Path boxes;

    @Option(names = "--seconds", paramLabel = "S", description = "simulated time, s (default: ${DEFAULT-VALUE})")
    double seconds = 4;

    @Option(names = "--rib-amplitude", paramLabel = "FACTOR",
            description = "rib rotation, times the quiet-breathing value, 0..3 (default: ${DEFAULT-VALUE})")
    double ribAmplitude = 1;

    @Option(names = "--muscle-force", paramLabel = "PA",
            description = "peak muscle action (force per unit area of diaphragm), Pa, 0..20000"
                    + " (default: ${DEFAULT-VALUE})")
    double musclePa = DiaphragmSetup.DEFAULT_MUSCLE_PA;

    @Option(names = "--period", paramLabel = "S", description = "breathing period, s (default: ${DEFAULT-VALUE})")
    double period = 4;

    @Option(names = "--ie-ratio", paramLabel = "R",
            description = "expiration time over inspiration time, I:E = 1:R (default: ${DEFAULT-VALUE})")
    double ieRatio = 2;

    @Option(names = "--attach-threshold", paramLabel = "MM",
            description = "attach diaphragm nodes closer than this to ribs, cartilage or sternum, mm"
                    + " (default: ${DEFAULT-VALUE})")
    double attachMm = DiaphragmParameters.defaults().attachThresholdM() * 1e3;

    @Option(names = "--weld-tolerance", paramLabel = "MM",
            description = "mesh cleaning: vertices closer than this are merged, mm (default: ${DEFAULT-VALUE})")
    double weldMm = 1e3 * MeshCleaner.Options.defaults().weldToleranceM();

    @Option(names = "--min-piece-fraction", paramLabel = "F",
            description = "mesh cleaning: disconnected pieces with fewer than this fraction of the triangles are"
                    + " dropped; 0 keeps every piece (default: ${DEFAULT-VALUE})")
    double minPieceFraction = MeshCleaner.Options.defaults().minComponentFraction();

    @Option(names = "--tendon-normal", paramLabel = "X,Y,Z", split = ",",
            description = "normal of the muscle/tendon plane, pointing to the tendon (default: 0,0,1, superior)")
    double[] tendonNormal;

    @Option(names = "--tendon-point", paramLabel = "X,Y,Z", split = ",",
            description = "a point of the muscle/tendon plane, mm, mesh frame (default: placed so that the tendon"
                    + " has --tendon-fraction of the upper surface)")
    double[] tendonPointMm;

    @Option(names = "--tendon-fraction", paramLabel = "F",
            description = "share of the upper surface's area given to the tendon when no --tendon-point is given"
                    + " (default: ${DEFAULT-VALUE})")
    double tendonFraction = DiaphragmParameters.defaults().tendonAreaFraction();

    @Option(names = "--action-line", paramLabel = "X,Y,R", converter = ActionLineConverter.class,
            description = "a vertical muscle action line through (X, Y) with radius of action R, mm; repeat for"
                    + " several (default: one through the top of each dome, R = 0.3 x the mesh width)")
    List<ActionLines.Line> actionLines;

    @Option(names = "--integrator", paramLabel = "NAME",
            description = "integrator: euler, symplectic-euler, rk2 (the paper's), heun, verlet, rk4, implicit-euler"
                    + " (default: ${DEFAULT-VALUE})")
    String integrator = "rk2";

    /**
     * Springs from which the automatic thread count uses every core: the real-time study
     * (docs/diaphragm.md) measured two threads 11-24 % faster at 24,733 springs (20 rings) and
     * up, and a third slower at 12,144 (14 rings) and below.
     */
    static final int AUTO_PARALLEL_SPRINGS = 20_000;

    @Option(names = "--threads", paramLabel = "N",
            description = "threads that share each step; 0 = automatic: all cores from "
                    + AUTO_PARALLEL_SPRINGS + " springs, else 1 (default: ${DEFAULT-VALUE})")
    int threads = 0;

    @Option(names = "--cg-tolerance", paramLabel = "R",
            description = "implicit-euler only: relative residual at which each step's CG solve stops"
                    + " (default: 1e-12)")
    Double cgTolerance;

    @Option(names = "--dt", paramLabel = "S",
            description = "time step, s, > 0 and at most one breathing period (default: the stable RK2 step of the scene)")
    Double dtOption;

    @Option(names = "--realtime",
            description = "run the fastest configuration the real-time study measured within 5 %% of RK2 on the"
                    + " default mesh (the large-step BDF2, all cores); the summary names it and its measured error")
    boolean realtime;

    @Option(names = "--study-rings", split = ",", paramLabel = "N[,N...]",
            description = "--realtime-study only: ring counts, ascending (default: 10,14,20,28,43)")
    int[] studyRings;

    @Option(names = "--study-configs", paramLabel = "REGEX",
            description = "--realtime-study only: run the configurations whose label this finds (RK2 on two threads,"
                    + " the reference of each resolution, always runs)")
    String studyConfigs;

    @Option(names = "--vtk-per-cycle", paramLabel = "N",
            description = "VTK frames per breathing cycle, 0 for none (default: ${DEFAULT-VALUE})")
    int vtkPerCycle = 8;

    @Option(names = "--vector-scale", paramLabel = "X",
            description = "scale of the mid-inspiration displacement vectors (default: ${DEFAULT-VALUE}, as Fig. 5)")
    double vectorScale = 100;

    @Option(names = "--csv-times", paramLabel = "S", split = ",",
            description = "times of displacements.csv, s (default: end-inspiration and end of the last cycle)")
    double[] csvTimes;

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default: ${DEFAULT-VALUE})")
    Path out = Path.of("out", "diaphragm");

    @Option(names = "--resolution-study",
            description = "run the resolution study instead (docs/diaphragm.md); uses --seconds per resolution")
    boolean resolutionStudy;

    @Option(names = "--realtime-study",
            description = "run the real-time study instead: 10 to 43 rings, RK2 (1 and 2 threads), implicit Euler"
                    + " at 5, 10, 20 ms and BDF2 at 5-25 ms, --seconds each (at most one period), error against RK2"
                    + " at the same mesh and against the paper's configuration vs speed (docs/diaphragm.md)")
    boolean realtimeStudy;

    @Override
    public Integer call() throws Exception {
        // Options are checked before the mesh is read, which takes seconds.
        org.tensim.solver.Integrator chosen = org.tensim.solver.integrators.Integrators.create(integrator);
        if (cgTolerance != null) {
            if (!(chosen instanceof org.tensim.solver.integrators.ImplicitEuler ie)) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                        "--cg-tolerance applies to --integrator implicit-euler only, not " + integrator);
            }
            ie.setTolerance(cgTolerance);
        }
        if (threads < 0) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--threads must be 0 (automatic) or more, got " + threads);
        }
        if (dtOption != null && !(dtOption > 0 && dtOption <= period)) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--dt must be > 0 s and at most one"
                    + " breathing period (--period " + period + " s), got " + dtOption + " s");
        }
        RealTimeSetting setting = null;
        if (realtime) {
            if (dtOption != null || cgTolerance != null || !integrator.equals("rk2")) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                        "--realtime chooses the integrator and the step itself: leave out --integrator, --dt and"
                                + " --cg-tolerance");
            }
            setting = RealTimeSetting.DEFAULT_MESH;
            chosen = setting.newIntegrator();
        }
        double dt = setting != null ? setting.dtS() : dtOption != null ? dtOption : 0;
        MeshUnits u = MeshUnits.parse(units);
        DiaphragmParameters p = DiaphragmParameters.defaults().withAttachThreshold(attachMm * 1e-3)
                .withTendonAreaFraction(tendonFraction);
        if (tendonNormal != null || tendonPointMm != null) {
            Vec3 normal = tendonNormal == null ? p.tendonNormal() : vector("--tendon-normal", tendonNormal, 1);
            Vec3 point = tendonPointMm == null ? null : vector("--tendon-point", tendonPointMm, 1e-3);
            p = p.withTendonPlane(normal, point);
        }
        MeshCleaner.Options cleaning = new MeshCleaner.Options(weldMm * 1e-3, minPieceFraction);
        List<ActionLines.Line> lines = actionLines == null || actionLines.isEmpty() ? null : actionLines;
        BreathingCycle cycle = new BreathingCycle(period, ieRatio);
        DiaphragmControls controls = new DiaphragmControls(ribAmplitude, musclePa);
        DiaphragmReport.Options o = new DiaphragmReport.Options(seconds, dt, vtkPerCycle, vectorScale, 0.01, csvTimes);
        if (studyRings != null) {
            for (int i = 0; i < studyRings.length; i++) {
                if (studyRings[i] < 4 || (i > 0 && studyRings[i] <= studyRings[i - 1])) {
                    throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--study-rings must be"
                            + " ascending ring counts of 4 or more, got " + java.util.Arrays.toString(studyRings));
                }
            }
        }
        if (realtimeStudy) {
            java.util.regex.Pattern only;
            try {
                only = studyConfigs == null ? null : java.util.regex.Pattern.compile(studyConfigs);
            } catch (java.util.regex.PatternSyntaxException e) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                        "--study-configs is not a regular expression: " + e.getDescription() + " in '" + studyConfigs
                                + "'");
            }
            Map<String, Object> s = RealTimeStudy.run(studyRings != null ? studyRings : RealTimeStudy.RINGS, only,
                    boxes, p, cycle, controls, seconds, out, System.out);
            System.out.println(Json.line(s));
            return 0;
        }
        if (resolutionStudy) {
            Map<String, Object> s = ResolutionStudy.run(boxes, p, cycle, controls, o, out, System.out);
            System.out.println(Json.line(s));
            return 0;
        }
        DiaphragmSetup.Built built;
        if (mesh.equals(DiaphragmSetup.DEFAULT_MESH) && !Files.isRegularFile(mesh)) {
            built = DiaphragmSetup.generated(43, lines, boxes, p, cycle, controls);
        } else {
            built = DiaphragmSetup.load(mesh, u, cleaning, thicknessMm * 1e-3, lines, boxes, p, cycle, controls);
        }
        if (built.meshReport() != null) {
            System.out.println(built.meshReport().describe());
        }
        int n = threads > 0 ? threads
                : setting != null || built.scene().topology().springs().size() >= AUTO_PARALLEL_SPRINGS
                        ? org.tensim.solver.parallel.Parallelism.availableCores() : 1;
        if (setting != null) {
            System.out.println("realtime: " + setting.describe()
                    + (mesh.equals(DiaphragmSetup.DEFAULT_MESH) ? "" : "; this mesh (" + mesh + ") was not measured"));
        }
        Map<String, Object> summary = DiaphragmReport.run(built, o, chosen, n, out, System.out);
        if (setting != null) {
            summary.put("realtime_setting", setting.toMap());
            Json.write(out.resolve("summary.json"), summary);
        }
        System.out.println(Json.line(summary));
        return 0;
    }

    private Vec3 vector(String option, double[] v, double scale) {
        if (v.length != 3) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    option + " needs three numbers X,Y,Z, got " + v.length);
        }
        if (v[0] == 0 && v[1] == 0 && v[2] == 0 && option.equals("--tendon-normal")) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    option + " must not be the zero vector");
        }
        return new Vec3(scale * v[0], scale * v[1], scale * v[2]);
    }

    /** Reads "X,Y,R" in millimetres into an action line in metres. */
    static final class ActionLineConverter implements picocli.CommandLine.ITypeConverter<ActionLines.Line> {
        @Override
        public ActionLines.Line convert(String value) {
            String[] f = value.split(",");
            if (f.length != 3) {
                throw new picocli.CommandLine.TypeConversionException("expected X,Y,R in mm (three numbers), got '"
                        + value + "'");
            }
            double[] d = new double[3];
            for (int i = 0; i < 3; i++) {
                try {
                    d[i] = Double.parseDouble(f[i].trim());
                } catch (NumberFormatException e) {
                    throw new picocli.CommandLine.TypeConversionException("expected X,Y,R in mm, '" + f[i].trim()
                            + "' in '" + value + "' is not a number");
                }
            }
            try {
                return new ActionLines.Line(1e-3 * d[0], 1e-3 * d[1], 1e-3 * d[2]);
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.TypeConversionException(e.getMessage() + " (in '" + value + "')");
            }
        }
    }
}
