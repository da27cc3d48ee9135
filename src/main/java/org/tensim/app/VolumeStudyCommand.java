package org.tensim.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.knowm.xchart.XYChart;
import org.tensim.analysis.VolumeStudy;
import org.tensim.cli.OutFolderOption;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TetMesh;
import org.tensim.io.mesh.TetMeshReaders;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;
import org.tensim.scene.volume.VolumeBody;
import org.tensim.scene.volume.VolumeReport;
import org.tensim.solver.SystemState;
import org.tensim.scene.volume.BoxTets;
import org.tensim.scene.volume.SpringFit;
import org.tensim.scene.volume.VolumeParameters;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim volume-study}: the volume body against the cantilever and the compressed block, under refinement. */
@Command(name = "volume-study", mixinStandardHelpOptions = true,
        description = {"Measures the volume body (docs/volume.md) against known answers, under refinement.",
            "A lattice clipped to a closed surface, or with --tets a structured tetrahedral mesh, is solved by"
                + " small-displacement statics at each resolution given: a cantilever of depth D and length 10 D"
                + " clamped at one end with a tip load, against Euler-Bernoulli's F L^3 / (3 E I) (and"
                + " Timoshenko's); and a block compressed on rollers (uniaxial stress) against -sigma / E, its"
                + " lateral strain against nu. Prints the tables and the measured orders, and writes"
                + " volume-cantilever.csv, volume-block.csv and volume-convergence.png to --out. The last line is"
                + " one JSON object with, per spring fit, the errors, the orders and the lateral strains (the"
                + " summary's fields). With --mesh, fills each surface at each --cell size (or builds each"
                + " tetrahedral mesh) instead and reports the builds (volume-meshes.csv)."})
public final class VolumeStudyCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--cantilever-cells", split = ",", paramLabel = "N[,N...]",
            description = "Cells across the beam's depth, each twice the last (default: ${DEFAULT-VALUE}).")
    List<Integer> cantileverCells = List.of(2, 4, 8);

    @Option(names = "--block-cells", split = ",", paramLabel = "N[,N...]",
            description = "Cells across the block's side; a half cell more leaves its last layer half full, a"
                    + " clipped lattice (default: 2.5,4.5,8.5; with --tets, whole cubes: 2,4,8).")
    List<Double> blockCells;

    @Option(names = "--tets", arity = "0..1", fallbackValue = "five", paramLabel = "SPLIT",
            description = "A structured tetrahedral mesh instead of the lattice, its cubes cut in five tets (the"
                    + " default) or six, its springs by Lloyd et al.'s identification (the isotropic fit only).")
    String tetSplit;

    @Option(names = "--jitter", paramLabel = "FRACTION", description = "With --tets, moves the mesh's interior"
            + " nodes by up to this fraction of a cube along each axis (0 to 0.15, seeded), for tets of many shapes"
            + " (default: ${DEFAULT-VALUE}).")
    double jitter;

    private VolumeStudy.Tets tets;

    @Option(names = "--young", paramLabel = "PA", description = "Young's modulus E, Pa (default: ${DEFAULT-VALUE}).")
    double youngPa = 1e3;

    @Option(names = "--poisson", paramLabel = "NU", description = "Poisson's ratio asked for (default: "
            + "${DEFAULT-VALUE}; the isotropic fit gives 1/4 whatever is asked).")
    double poisson = 0.4;

    @Option(names = "--density", paramLabel = "KG_M3", description = "Density, kg/m^3 (default: ${DEFAULT-VALUE};"
            + " statics does not depend on it, --mesh's critical time step does).")
    double densityKgPerM3 = 1000;

    @Option(names = "--fits", split = ",", paramLabel = "FIT[,FIT...]",
            description = "Spring fits: isotropic, axial (default: both; with --tets, isotropic).")
    List<String> fits;

    @Option(names = "--sliding-root", description = "Hold the cantilever's root only along the beam (and its"
            + " mid-planes across), so that it contracts sideways freely, as the beam theories' root does.")
    boolean slidingRoot;

    @Option(names = "--mesh", split = ",", paramLabel = "FILE[,FILE...]",
            description = "Closed surfaces (OBJ, STL, OFF) to fill at each --cell size, or tetrahedral meshes (Gmsh"
                    + " .msh, legacy VTK .vtk) to build as they are, reporting the builds instead of the known"
                    + " answers.")
    List<Path> meshes = List.of();

    @Option(names = "--units", paramLabel = "UNITS", description = "Length unit of --mesh files: mm or m (default:"
            + " ${DEFAULT-VALUE}).")
    String units = "mm";

    @Option(names = "--cell", split = ",", paramLabel = "M[,M...]",
            description = "Cell sizes for --mesh, m (default: ${DEFAULT-VALUE}).")
    List<Double> cells = List.of(0.01, 0.005);

    @Option(names = "--scene", paramLabel = "FILE", description = "A scene file whose volume body is run as tensim"
            + " run runs it, at its own cell and at the cell divided by each --refine factor, with the file's total"
            + " load at each; its load's displacement is compared with its shape's known answer (a cantilever's"
            + " Euler-Bernoulli tip deflection, a block's uniaxial strain, with lateral strains against nu) instead"
            + " of the built-in studies (volume-scene.csv).")
    Path scene;

    @Option(names = "--refine", split = ",", paramLabel = "F[,F...]", description = "With --scene, the whole numbers"
            + " the file's cell size is divided by (default: ${DEFAULT-VALUE}).")
    List<Integer> refine = List.of(1, 2, 4);

    @Option(names = "--body", paramLabel = "NAME", description = "With --scene, the volume body to refine (default:"
            + " the file's only one).")
    String body;

    @Option(names = "--set", paramLabel = "KEY.PATH=VALUE", description = "With --scene, replaces one value of the"
            + " file before it is refined, as tensim run's --set does (repeatable).")
    List<String> sets = new ArrayList<>();

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "volume-study"));

    /** The files this command writes into --out (docs/outputs.md). */
    static final List<String> OUTPUTS = List.of("volume-cantilever.csv", "volume-block.csv",
            "volume-convergence.png", "volume-meshes.csv", VolumeSceneStudy.CSV);

    /** Beam depth, m, and tip force, N (linear statics: the errors do not depend on them). */
    private static final double DEPTH_M = 0.02;
    private static final double FORCE_N = 1e-4;
    /** Block side, m, and pressure, Pa. */
    private static final double SIDE_M = 0.02;
    private static final double PRESSURE_PA = 10;

    @Override
    public Integer call() throws Exception {
        if (scene != null) {
            if (refine.isEmpty() || refine.stream().anyMatch(f -> f < 1)) {
                throw new IllegalArgumentException("--refine must be whole numbers >= 1, got " + refine);
            }
            return RunFolder.run(out.folder(spec), "volume-study", OUTPUTS,
                    run -> VolumeSceneStudy.run(run, scene, body, refine, sets));
        }
        if (tetSplit != null) {
            switch (tetSplit.trim().toLowerCase(java.util.Locale.ROOT)) {
                case "six":
                    tets = new VolumeStudy.Tets(BoxTets.Split.SIX, jitter);
                    break;
                case "five":
                    tets = new VolumeStudy.Tets(BoxTets.Split.FIVE, jitter);
                    break;
                default:
                    throw new IllegalArgumentException("--tets must be 'six' or 'five', got '" + tetSplit + "'");
            }
        }
        if (!(jitter >= 0 && jitter <= 0.15) || jitter > 0 && tets == null) {
            throw new IllegalArgumentException("--jitter must be 0 to 0.15, with --tets, got " + jitter);
        }
        if (blockCells == null) {
            blockCells = tets != null ? List.of(2.0, 4.0, 8.0) : List.of(2.5, 4.5, 8.5);
        }
        if (fits == null) {
            fits = tets != null ? List.of("isotropic") : List.of("isotropic", "axial");
        }
        if (tets != null && fits.stream().anyMatch(f -> SpringFit.parse(f) != SpringFit.ISOTROPIC)) {
            throw new IllegalArgumentException("--tets takes the isotropic fit only (the axial fit needs a lattice's"
                    + " axes), got --fits " + String.join(",", fits));
        }
        if (tets != null && blockCells.stream().anyMatch(c -> c != Math.rint(c))) {
            throw new IllegalArgumentException("--tets needs whole --block-cells, got " + blockCells);
        }
        List<VolumeParameters> params = new ArrayList<>();
        for (String f : fits) {
            params.add(VolumeParameters.of(0.01, youngPa, poisson, densityKgPerM3).withFit(SpringFit.parse(f)));
        }
        for (int i = 0; i < cantileverCells.size(); i++) {
            if (cantileverCells.get(i) < 1 || i > 0 && cantileverCells.get(i) != 2 * cantileverCells.get(i - 1)) {
                throw new IllegalArgumentException("--cantilever-cells must be whole numbers >= 1, each twice the"
                        + " last, got " + cantileverCells);
            }
        }
        if (slidingRoot && cantileverCells.stream().anyMatch(n -> n % 2 != 0)) {
            throw new IllegalArgumentException("--sliding-root needs even --cantilever-cells, got " + cantileverCells);
        }
        for (double c : blockCells) {
            if (!(c > 0)) {
                throw new IllegalArgumentException("--block-cells must be > 0, got " + c);
            }
        }
        if (!meshes.isEmpty()) {
            MeshUnits u = MeshUnits.parse(units);
            for (double c : cells) {
                if (!(c > 0)) {
                    throw new IllegalArgumentException("--cell must be > 0 m, got " + c);
                }
            }
            return RunFolder.run(out.folder(spec), "volume-study", OUTPUTS, run -> fill(run, params, u));
        }
        return RunFolder.run(out.folder(spec), "volume-study", OUTPUTS, run -> study(run, params));
    }

    /** Fills each mesh at each cell size with the first fit, and reports the builds. */
    private void fill(RunFolder run, List<VolumeParameters> params, MeshUnits u) throws Exception {
        List<Map<String, Object>> rows = new ArrayList<>();
        try (CsvWriter csv = run.csv("volume-meshes.csv", List.of("mesh", "cell_m", "nodes", "springs", "cells",
                "crossed_cells", "boundary_edges", "max_winding_deviation", "lattice_volume_m3", "surface_volume_m3",
                "critical_step_s", "build_s"), 1)) {
            for (Path file : meshes) {
                boolean tetFile = isTetMesh(file);
                TriangleMesh mesh = tetFile ? null : MeshLoader.load(file, u).mesh();
                TetMesh tetMesh = tetFile ? TetMeshReaders.read(file, u).mesh() : null;
                for (double c : tetFile ? List.of(Double.NaN) : cells) {
                    long t0 = System.nanoTime();
                    Topology t = new Topology();
                    VolumeBody body = tetFile ? VolumeBody.buildTets(t, tetMesh, params.get(0), file.toString())
                            : VolumeBody.build(t, mesh, params.get(0).withCellSize(c), file.toString());
                    double seconds = (System.nanoTime() - t0) * 1e-9;
                    VolumeReport r = body.report();
                    // the leapfrog limit 2 / w_max of the free lattice (power iteration): what an explicit step meets
                    double critical = SystemState.compile(t).criticalTimeStep().stepSeconds();
                    double cell = tetFile ? r.cellSizeM() : c;
                    csv.rowText(file.getFileName().toString(), Double.toString(cell), Integer.toString(r.nodes()),
                            Integer.toString(r.springs()), Integer.toString(r.cells()),
                            Integer.toString(r.crossedCells()), Integer.toString(r.boundaryEdges()),
                            Double.toString(r.maxWindingDeviation()), Double.toString(r.latticeVolumeM3()),
                            Double.toString(r.surfaceVolumeM3()), Double.toString(critical),
                            Double.toString(seconds));
                    System.out.printf("%s at %.3g mm (%.1f s): %s; critical (leapfrog) step %.3g ms%n",
                            file.getFileName(), cell * 1e3, seconds, r.describe(), critical * 1e3);
                    Map<String, Object> m = new LinkedHashMap<>();
                    m.put("mesh", file.toString());
                    m.put("build_s", seconds);
                    m.put("critical_step_s", critical);
                    m.putAll(r.toMap());
                    rows.add(m);
                }
            }
        }
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("meshes", rows);
        run.finish(RunStatus.OK, json);
        System.out.println(Json.line(json));
    }

    private void study(RunFolder run, List<VolumeParameters> params) throws IOException {
        Map<String, Object> json = new LinkedHashMap<>();
        XYChart chart = Charts.lineChart("Volume body: error against the known answer", "cell size / depth or side",
                "|relative error|", 900, 600);
        Charts.logLog(chart);
        try (CsvWriter beam = run.csv("volume-cantilever.csv", List.of("fit", "cells_across", "cell_m", "nodes",
                "springs", "deflection_m", "euler_bernoulli_m", "timoshenko_m", "error_vs_euler_bernoulli",
                "cg_iterations"), 1);
                CsvWriter block = run.csv("volume-block.csv", List.of("fit", "cells_across", "cell_m", "nodes",
                        "axial_strain", "expected_strain", "strain_error", "lateral_strain", "measured_poisson",
                        "model_poisson", "requested_poisson", "cg_iterations"), 1)) {
            for (VolumeParameters p : params) {
                String fit = label(p);
                Map<String, Object> e = new LinkedHashMap<>();
                e.put("model_poisson", p.material().modelPoisson());
                e.put("shear_modulus_pa", p.material().shearModulusPa());
                e.put("young_along_diagonal_pa", p.material().youngAlongPa(1, 1, 1));
                e.put("cantilever", cantilever(p, beam, chart));
                e.put("block", block(p, block, chart));
                json.put(fit, e);
            }
        }
        Charts.savePng(chart, run.file("volume-convergence.png"));
        run.finish(RunStatus.OK, json);
        System.out.println(Json.line(json));
    }

    private Map<String, Object> cantilever(VolumeParameters p, CsvWriter csv, XYChart chart) throws IOException {
        String fit = label(p);
        List<Double> q = new ArrayList<>();
        List<Double> err = new ArrayList<>();
        List<Double> size = new ArrayList<>();
        for (int n : cantileverCells) {
            VolumeStudy.Cantilever c = VolumeStudy.cantilever(p, DEPTH_M, FORCE_N, n, slidingRoot, tets);
            csv.rowText(fit, Integer.toString(n), Double.toString(c.cellM()), Integer.toString(c.nodes()),
                    Integer.toString(c.springs()), Double.toString(c.deflectionM()),
                    Double.toString(c.eulerBernoulliM()), Double.toString(c.timoshenkoM()),
                    Double.toString(c.errorAgainstEulerBernoulli()), Integer.toString(c.iterations()));
            System.out.printf("%-9s cantilever %3d cells across (%6d nodes): tip %.6g m, Euler-Bernoulli %.6g m"
                    + " (%+.2f %%), Timoshenko %.6g m (%+.2f %%)%n", fit, n, c.nodes(), c.deflectionM(),
                    c.eulerBernoulliM(), 100 * c.errorAgainstEulerBernoulli(), c.timoshenkoM(),
                    100 * (c.deflectionM() / c.timoshenkoM() - 1));
            q.add(c.deflectionM());
            err.add(c.errorAgainstEulerBernoulli());
            size.add(1.0 / n);
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("root", slidingRoot ? "sliding" : "clamped");
        m.put("cells_across", cantileverCells);
        m.put("error_vs_euler_bernoulli", err);
        m.put("finest_error", err.get(err.size() - 1));
        List<Double> observed = new ArrayList<>();
        List<Double> against = new ArrayList<>();
        for (int i = 2; i < q.size(); i++) {
            observed.add(VolumeStudy.observedOrder(q.get(i - 2), q.get(i - 1), q.get(i), 2));
        }
        for (int i = 1; i < q.size(); i++) {
            against.add(VolumeStudy.orderAgainst(err.get(i - 1), err.get(i), size.get(i - 1), size.get(i)));
        }
        m.put("observed_order", observed);
        m.put("order_vs_euler_bernoulli", against);
        System.out.println(fit + " cantilever: observed order " + observed + ", against Euler-Bernoulli " + against);
        plot(chart, fit + " cantilever", size, err);
        return m;
    }

    private Map<String, Object> block(VolumeParameters p, CsvWriter csv, XYChart chart) throws IOException {
        String fit = label(p);
        List<Double> err = new ArrayList<>();
        List<Double> nu = new ArrayList<>();
        List<Double> size = new ArrayList<>();
        for (double n : blockCells) {
            VolumeStudy.Block b = VolumeStudy.block(p, SIDE_M, PRESSURE_PA, n, tets);
            csv.rowText(fit, Double.toString(n), Double.toString(b.cellM()), Integer.toString(b.nodes()),
                    Double.toString(b.axialStrain()), Double.toString(b.expectedStrain()),
                    Double.toString(b.strainError()), Double.toString(b.lateralStrain()),
                    Double.toString(b.measuredPoisson()), Double.toString(b.modelPoisson()),
                    Double.toString(b.requestedPoisson()), Integer.toString(b.iterations()));
            System.out.printf("%-9s block %5.1f cells across (%6d nodes): strain %.6g against %.6g (%+.3f %%),"
                    + " lateral %.6g: nu %.4f (the %s %.3f, asked %.3f)%n", fit, n, b.nodes(),
                    b.axialStrain(), b.expectedStrain(), 100 * b.strainError(), b.lateralStrain(),
                    b.measuredPoisson(), tets != null ? "springs' target" : "lattice's", b.modelPoisson(),
                    b.requestedPoisson());
            err.add(b.strainError());
            nu.add(b.measuredPoisson());
            size.add(1 / n);
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("cells_across", blockCells);
        m.put("strain_error", err);
        m.put("finest_error", err.get(err.size() - 1));
        List<Double> order = new ArrayList<>();
        for (int i = 1; i < err.size(); i++) {
            order.add(VolumeStudy.orderAgainst(err.get(i - 1), err.get(i), size.get(i - 1), size.get(i)));
        }
        m.put("order", order);
        // from three resolutions in a constant ratio, needing no exact answer (the tets converge to their own)
        List<Double> observed = new ArrayList<>();
        for (int i = 2; i < err.size(); i++) {
            double ratio = size.get(i - 1) / size.get(i);
            if (Math.abs(size.get(i - 2) / size.get(i - 1) - ratio) < 1e-9 * ratio) {
                observed.add(VolumeStudy.observedOrder(err.get(i - 2), err.get(i - 1), err.get(i), ratio));
            }
        }
        m.put("observed_order", observed);
        m.put("measured_poisson", nu);
        m.put("requested_poisson", p.poisson());
        System.out.println(fit + " block: order " + order + ", observed order " + observed);
        plot(chart, fit + " block", size, err);
        return m;
    }

    /** Whether {@code file} is a volume mesh (Gmsh .msh, legacy VTK .vtk) rather than a surface. */
    private static boolean isTetMesh(Path file) {
        String n = file.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
        return n.endsWith(".msh") || n.endsWith(".vtk");
    }

    /** The name of a series: the fit's, or "tets" for the tetrahedral variant. */
    private String label(VolumeParameters p) {
        return tets != null ? "tets-" + tets.split().name().toLowerCase(java.util.Locale.ROOT)
                + (jitter > 0 ? "-jitter" : "") : p.fit().key();
    }

    private static void plot(XYChart chart, String name, List<Double> size, List<Double> err) {
        List<double[]> pts = new ArrayList<>();
        for (int i = 0; i < size.size(); i++) {
            if (err.get(i) != 0 && Double.isFinite(err.get(i))) {
                pts.add(new double[] {size.get(i), Math.abs(err.get(i))});
            }
        }
        if (!pts.isEmpty()) {
            chart.addSeries(name, pts.stream().mapToDouble(a -> a[0]).toArray(),
                    pts.stream().mapToDouble(a -> a[1]).toArray());
        }
    }
}
