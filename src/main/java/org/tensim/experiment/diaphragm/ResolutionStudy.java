package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import org.tensim.io.Json;
import org.tensim.io.ProjectFolder;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.MidpointSubdivision;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.scene.diaphragm.ActionLines;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.Decimation;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;

/**
 * "Model no more than the scene needs": the same scene at several mesh resolutions, each
 * run through one inspiration; each model's displacement field at end-inspiration is
 * compared with its family's finest ({@link ResolutionAnalysis}: error, convergence order),
 * and the coarsest double dome within the tolerance is picked for the interactive uses
 * ({@link ResolutionPick}).
 *
 * <p>Families: without a mesh, the project's double dome at several ring counts (reference:
 * the default 43 rings) and the BodyParts3D diaphragm simplified by vertex clustering, faces
 * kept apart, with BodyParts3D's rib boxes (reference: its finest simplification; only when that
 * mesh is present). With a
 * mesh ({@link #runMesh}), that mesh decimated at the given sizes ({@link Decimation}: vertex clustering
 * or quadric-error edge collapse, faces apart, the muscle's free rim the given mesh's), as given, and
 * refined by midpoint subdivision; the finest is the reference.
 */
public final class ResolutionStudy {
    /** Default relative RMS error under which a resolution is accepted. */
    public static final double TOLERANCE = 0.10;
    /** Ring counts of the parametric family; the last is the reference. */
    static final int[] RINGS = {10, 14, 20, 28, 43};
    /**
     * Clustering cell sizes (mm) for the BodyParts3D family; the last is the reference. The full mesh is
     * not used as reference: its smallest elements force a stable step near 4e-5 s (docs/diaphragm.md).
     */
    static final double[] CELLS_MM = {16, 12, 9, 6.5};
    /** Default clustering cells for {@code --mesh}, as multiples of the mesh's mean edge length. */
    static final double[] CELL_FACTORS = {4, 2.8, 2};
    /** The BodyParts3D mesh, relative to the project folder. */
    public static final Path BODYPARTS_MESH = ProjectFolder.resolve("..", "shared", "meshes", "bodyparts3d",
            "diaphragm-FJ3131-dec28k-mm.obj");

    /**
     * One model's outcome: rest and end positions of its diaphragm nodes (3 per node, m), which of
     * them are on the upper surface, the upper surface's triangles (node ids, 3 each; null: the error
     * falls back to the nearest node), each node's partner across the thickness ({@link TwoSurfaces#partner};
     * null: none, the upper surface carries the fine field alone), its mean edge length (m), apex descent (m,
     * positive down) and cost in wall seconds per simulated second.
     */
    public record Run(String family, String label, int nodes, int springs, double elementSizeM, double costPerSimS,
            double dt, double apexDescentM, double[] rest, double[] end, boolean[] upper, int[] upperTriangles,
            int[] partners) {
        /** A run whose element size, apex descent and triangles are not recorded, for comparisons of fields only. */
        public Run(String family, String label, int nodes, int springs, double costPerSimS, double dt, double[] rest,
                double[] end, boolean[] upper) {
            this(family, label, nodes, springs, Double.NaN, costPerSimS, dt, Double.NaN, rest, end, upper, null, null);
        }

        /** A run of a surface without partners across the thickness. */
        public Run(String family, String label, int nodes, int springs, double elementSizeM, double costPerSimS,
                double dt, double apexDescentM, double[] rest, double[] end, boolean[] upper, int[] upperTriangles) {
            this(family, label, nodes, springs, elementSizeM, costPerSimS, dt, apexDescentM, rest, end, upper,
                    upperTriangles, null);
        }
    }

    /** What the study needs besides the scene: simulated time, tolerance, models, where to write. */
    public record Setup(Map<String, double[]> boxes, DiaphragmParameters p, BoundaryConditions bc,
            BreathingCycle cycle, DiaphragmControls controls, double seconds, double tolerance, PrintStream log,
            Thorax thorax) {
        public Setup {
            if (!(tolerance > 0 && tolerance < 1)) {
                throw new IllegalArgumentException("resolution tolerance must be in (0, 1) (relative RMS error), got "
                        + tolerance);
            }
        }

        /** A study in the cage of boxes, each model with RK2 at its recommended step. */
        public Setup(Map<String, double[]> boxes, DiaphragmParameters p, BoundaryConditions bc, BreathingCycle cycle,
                DiaphragmControls controls, double seconds, double tolerance, PrintStream log) {
            this(boxes, p, bc, cycle, controls, seconds, tolerance, log, null);
        }

        Setup withBoxes(Map<String, double[]> b) {
            return new Setup(b, p, bc, cycle, controls, seconds, tolerance, log, thorax);
        }
    }

    /**
     * A study in a thorax of bone surfaces: every model of the family is built by the scene definition
     * {@code spec} (its tissue, boundary, breathing and contact) with the bones read once, and stepped by a fresh
     * {@code integrator} at {@code dtS} (contact makes RK2's stable step too small to be worth it).
     *
     * @param bones the thorax as read once ({@link DiaphragmSetup#read}); its surfaces are replaced by each model's
     * @param dtS   time step, s (0: the scene's recommended step for the integrator, as a single run chooses)
     */
    public record Thorax(DiaphragmSpec spec, DiaphragmSetup.Inputs bones, Supplier<Integrator> integrator,
            double dtS) {
        public Thorax {
            if (bones.bones() == null) {
                throw new IllegalArgumentException("a thorax study needs a spec with a thorax (--thorax)");
            }
            Check.nonNegative("time step", "s", dtS);
        }
    }

    private ResolutionStudy() {
    }

    /**
     * The default study: the double dome family, then BodyParts3D's when present. Writes
     * resolution.csv/json/png to {@code out} and the pick to {@code pickFile} (the caller's choice:
     * {@code out}/{@value ResolutionPick#NAME} unless the user names another file); the summary names it
     * ({@code "resolution_pick_file"}).
     */
    public static Map<String, Object> run(Setup s, Path out, Path pickFile) throws IOException, MeshFormatException {
        return run(s, out, pickFile, null);
    }

    /**
     * As {@link #run(Setup, Path, Path)}, the pick recording the scene it was measured on ({@link
     * ResolutionPick#sceneOf} of the spec the setup was made from; null: not recorded, and the pick is then refused
     * by {@link ResolutionPick#requireMatches}).
     */
    public static Map<String, Object> run(Setup s, Path out, Path pickFile, Map<String, Object> scene)
            throws IOException, MeshFormatException {
        Files.createDirectories(out);
        List<Run> parametric = new ArrayList<>();
        for (int rings : RINGS) {
            TriangleMesh m = DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings));
            parametric.add(simulate("double dome", rings + " rings", TwoSurfaces.split(m), s));
        }
        List<List<Run>> families = new ArrayList<>(List.of(parametric));
        if (Files.isRegularFile(BODYPARTS_MESH)) {
            TriangleMesh full = MeshLoader.load(BODYPARTS_MESH, MeshUnits.MM).mesh();
            // the mesh with the rib boxes of the same anatomy when they are there
            Setup bp = Files.isRegularFile(DiaphragmSetup.BODYPARTS3D_BOXES) ? s.withBoxes(
                    DiaphragmSetup.boxes(DiaphragmSetup.BODYPARTS3D_BOXES)) : s;
            families.add(decimated("BodyParts3D", TwoSurfaces.split(full), CELLS_MM, Decimation.CLUSTERING, bp));
        }
        ResolutionAnalysis.Transfers transfers = new ResolutionAnalysis.Transfers();
        Map<String, Object> summary = report(families, transfers, s, out);
        ResolutionPick.pick(ResolutionAnalysis.rows(parametric, transfers), RINGS, s, pickFile, scene, summary,
                "./tensim diaphragm resolution-study");
        return summary;
    }

    /**
     * The double dome family at the given ring counts only (ascending; the finest is the reference), for
     * a quicker study than {@link #run}: no BodyParts3D family. Writes resolution.csv/json/png to {@code out}; a pick
     * only when the reference is the paper's {@value ResolutionPick#REFERENCE_RINGS} rings and {@code pickFile} is
     * given.
     */
    public static Map<String, Object> runRings(Setup s, int[] rings, Path out) throws IOException {
        return runRings(s, rings, out, null, null);
    }

    /** As {@link #runRings(Setup, int[], Path)}, writing the pick to {@code pickFile} (null: none) with its scene. */
    public static Map<String, Object> runRings(Setup s, int[] rings, Path out, Path pickFile,
            Map<String, Object> scene) throws IOException {
        Files.createDirectories(out);
        List<Run> family = new ArrayList<>();
        for (int r : rings) {
            TriangleMesh m = DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(r));
            family.add(simulate("double dome", r + " rings", TwoSurfaces.split(m), s));
        }
        ResolutionAnalysis.Transfers transfers = new ResolutionAnalysis.Transfers();
        Map<String, Object> summary = report(List.of(family), transfers, s, out);
        if (pickFile != null && rings[rings.length - 1] == ResolutionPick.REFERENCE_RINGS) {
            ResolutionPick.pick(ResolutionAnalysis.rows(family, transfers), rings, s, pickFile, scene, summary,
                    "./tensim diaphragm resolution-study --study-rings " + java.util.Arrays.stream(rings)
                            .mapToObj(String::valueOf).collect(java.util.stream.Collectors.joining(",")));
        }
        return summary;
    }

    /**
     * The study on a given mesh: decimated by {@code decimation} at {@code cellsMm} (clustering cells or target
     * edge lengths; empty: 4, 2.8 and 2 times its mean edge length), as given, and refined {@code refineLevels}
     * times by midpoint subdivision.
     */
    public static Map<String, Object> runMesh(Path meshFile, MeshUnits units, MeshCleaner.Options cleaning,
            double offsetThicknessM, double[] cellsMm, Decimation decimation, int refineLevels, Setup s, Path out)
            throws IOException, MeshFormatException {
        Files.createDirectories(out);
        TriangleMesh given = MeshLoader.load(meshFile, units, cleaning).mesh();
        TwoSurfaces surfaces = DiaphragmSetup.surfaces(given, offsetThicknessM).surfaces();
        String name = meshFile.getFileName().toString();
        double[] cells = cellsMm;
        if (cells == null || cells.length == 0) {
            double h = meanEdge(given) * 1e3;
            cells = Arrays.stream(CELL_FACTORS).map(f -> Math.round(f * h * 10) / 10.0).toArray();
        }
        List<Run> family = decimated(name, surfaces, cells, decimation, s);
        family.add(simulate(name, "as given", surfaces, s));
        if (refineLevels > 0) {
            for (int level = 1; level <= refineLevels; level++) {
                TriangleMesh fine = MidpointSubdivision.refine(given, level);
                family.add(simulate(name, "refined x" + (1 << level), DiaphragmSetup.surfaces(fine,
                        offsetThicknessM).surfaces(), s));
            }
        }
        ResolutionAnalysis.Transfers transfers = new ResolutionAnalysis.Transfers();
        ResolutionAnalysis.nodesCsv(out.resolve("resolution-nodes.csv"), family, transfers);
        return report(List.of(family), transfers, s, out);
    }

    /** The models decimated from {@code split} at each size ({@link Decimation#coarsen}), coarse first. */
    private static List<Run> decimated(String name, TwoSurfaces split, double[] cellsMm, Decimation d, Setup s) {
        double[] sorted = cellsMm.clone();
        Arrays.sort(sorted);
        List<Run> runs = new ArrayList<>();
        for (int i = sorted.length - 1; i >= 0; i--) { // coarse first
            String label = (d == Decimation.CLUSTERING ? "cells " : "quadric edge ") + sorted[i] + " mm";
            runs.add(simulate(name, label, d.coarsen(split, sorted[i] * 1e-3), s));
        }
        return runs;
    }

    private static Map<String, Object> report(List<List<Run>> families, ResolutionAnalysis.Transfers transfers,
            Setup s, Path out) throws IOException {
        List<Map<String, Object>> rows = new ArrayList<>();
        List<Map<String, Object>> fams = new ArrayList<>();
        for (List<Run> family : families) {
            List<Map<String, Object>> r = ResolutionAnalysis.rows(family, transfers);
            rows.addAll(r);
            Map<String, Object> f = new LinkedHashMap<>();
            f.put("family", family.get(0).family());
            f.put("reference", family.get(family.size() - 1).label());
            double order = ResolutionAnalysis.order(r);
            f.put("order", Double.isNaN(order) ? null : DiaphragmReport.round(order, 3));
            f.put("errors_fall_monotonically", ResolutionAnalysis.monotone(r));
            int pick = ResolutionAnalysis.pick(r, s.tolerance());
            f.put("coarsest_within_tolerance", pick == r.size() - 1 ? null : r.get(pick).get("model"));
            fams.add(f);
            if (s.log() != null) {
                s.log().println(String.format(Locale.ROOT, "%s: order %.2f, errors fall monotonically: %s",
                        f.get("family"), order, f.get("errors_fall_monotonically")));
            }
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("simulated_s_per_model", s.seconds());
        summary.put("tolerance", s.tolerance());
        summary.put("attachment", s.bc().attachment().name().toLowerCase(Locale.ROOT));
        summary.put("muscle_load", s.bc().muscleLoad().name().toLowerCase(Locale.ROOT));
        if (s.thorax() != null) {
            // In a thorax the band's law ties the origins only (docs/thorax.md), not the band near the cage.
            summary.put("attachment", "origins");
            summary.put("thorax", String.valueOf(s.thorax().spec().cage().thorax()));
            summary.put("contact", s.thorax().spec().cage().contact());
            summary.put("integrator", s.thorax().integrator().get().name());
        }
        summary.put("families", fams);
        summary.put("models", rows);
        ResolutionAnalysis.csv(out.resolve("resolution.csv"), rows);
        ResolutionAnalysis.chart(out.resolve("resolution.png"), rows, s.tolerance());
        Json.write(out.resolve("resolution.json"), summary);
        return summary;
    }

    static Run simulate(String family, String label, TwoSurfaces surf, Setup s) {
        return simulate(family, label, surf, s, null);
    }

    /** As {@link #simulate(String, String, TwoSurfaces, Setup)} with the given action lines (null: the default). */
    static Run simulate(String family, String label, TwoSurfaces surf, Setup s, List<ActionLines.Line> lines) {
        Thorax th = s.thorax();
        DiaphragmScene scene;
        if (th == null) {
            scene = DiaphragmScene.build(surf, s.boxes(), s.p(), s.cycle(), s.controls(), lines, s.bc());
        } else {
            DiaphragmSetup.Inputs in = new DiaphragmSetup.Inputs(new DiaphragmSetup.Surfaces(surf,
                    DiaphragmSetup.SurfaceMode.SHELL), null, Map.of(), th.bones().bones(), null, label);
            scene = DiaphragmSetup.build(in, th.spec(), s.controls()).scene();
        }
        Simulation sim = scene.newSimulation();
        double dt = scene.recommendedTimeStep();
        if (th != null) {
            sim.setIntegrator(th.integrator().get());
            dt = scene.timeStep(sim.integrator(), th.dtS()).seconds();
        }
        long t0 = System.nanoTime();
        sim.runUntil(s.seconds(), dt);
        double wall = (System.nanoTime() - t0) / 1e9;
        int nd = scene.diaphragmNodes();
        boolean[] upper = new boolean[nd];
        int[] partners = new int[nd];
        for (int v = 0; v < nd; v++) {
            upper[v] = surf.isUpper(v);
            partners[v] = surf.partner(v);
        }
        int a = scene.apexNode();
        Run r = new Run(family, label, scene.topology().nodeCount(), scene.topology().springs().size(),
                meanEdge(surf.mesh()), wall / sim.time(), dt, sim.state().x0[3 * a + 2] - sim.state().x[3 * a + 2],
                Arrays.copyOf(sim.state().x0, 3 * nd), Arrays.copyOf(sim.state().x, 3 * nd), upper,
                scene.upperTriangles(), partners);
        if (s.log() != null) {
            s.log().println(String.format(Locale.ROOT, "%s, %s: %d nodes, %d springs, mean edge %.2f mm, dt %.2e s,"
                    + " %.2f wall s per simulated s, apex descent %.2f mm", family, label, r.nodes(), r.springs(),
                    r.elementSizeM() * 1e3, dt, r.costPerSimS(), r.apexDescentM() * 1e3));
        }
        return r;
    }

    /** Mean length of the mesh's edges (each counted once), m. */
    static double meanEdge(TriangleMesh m) {
        java.util.Set<Long> seen = new java.util.HashSet<>();
        double sum = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                int i = m.corner(t, k);
                int j = m.corner(t, (k + 1) % 3);
                if (seen.add(((long) Math.min(i, j) << 32) | Math.max(i, j))) {
                    sum += Math.sqrt(sq(m.coord(i, 0) - m.coord(j, 0)) + sq(m.coord(i, 1) - m.coord(j, 1))
                            + sq(m.coord(i, 2) - m.coord(j, 2)));
                }
            }
        }
        return sum / seen.size();
    }

    private static double sq(double x) {
        return x * x;
    }

    /**
     * Relative RMS difference of the end displacement fields over the fine model's upper nodes: the
     * coarse field carried to them by the shell mapping ({@link FieldTransfer}), or, for a run without
     * triangles, taken at the nearest upper node of the coarse model.
     */
    public static double error(Run fine, Run coarse) {
        if (coarse.upperTriangles() != null) {
            return FieldTransfer.relativeRms(fine.rest(), fine.end(), fine.upper(),
                    FieldTransfer.differences(fine, coarse));
        }
        double num = 0;
        double den = 0;
        int nf = fine.rest().length / 3;
        int nc = coarse.rest().length / 3;
        for (int i = 0; i < nf; i++) {
            if (!fine.upper()[i]) {
                continue;
            }
            int best = -1;
            double bd = Double.POSITIVE_INFINITY;
            for (int j = 0; j < nc; j++) {
                if (!coarse.upper()[j]) {
                    continue;
                }
                double d = 0;
                for (int a = 0; a < 3; a++) {
                    double e = fine.rest()[3 * i + a] - coarse.rest()[3 * j + a];
                    d += e * e;
                }
                if (d < bd) {
                    bd = d;
                    best = j;
                }
            }
            for (int a = 0; a < 3; a++) {
                double uf = fine.end()[3 * i + a] - fine.rest()[3 * i + a];
                double uc = coarse.end()[3 * best + a] - coarse.rest()[3 * best + a];
                num += (uc - uf) * (uc - uf);
                den += uf * uf;
            }
        }
        return Math.sqrt(num / den);
    }
}
