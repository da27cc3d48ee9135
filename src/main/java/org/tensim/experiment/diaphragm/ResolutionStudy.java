package org.tensim.experiment.diaphragm;

import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.io.ProjectFolder;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.tensim.io.Charts;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.mesh.VertexClustering;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;
import org.tensim.scene.diaphragm.TwoSurfaces;
import org.tensim.solver.Simulation;

/**
 * "Model no more than the scene needs": the same scene at several mesh
 * resolutions, each run through one inspiration; the displacement field at
 * end-inspiration is compared with the finest one's, and plotted against the cost
 * (wall seconds per simulated second).
 *
 * <p>Error measure: for every upper-surface node of the finest model, the nearest
 * upper-surface node (at rest) of the coarser one is taken, and
 * {@code e = sqrt(sum |u_coarse - u_fine|^2 / sum |u_fine|^2)} (relative RMS; the
 * nearest-node transfer itself adds an error of the order of the displacement
 * gradient times the coarse edge length).
 *
 * <p>Two families: the project's double dome at several ring counts (reference:
 * the default 43 rings), and the BodyParts3D diaphragm simplified by vertex
 * clustering, faces kept apart (reference: its finest simplification); the latter
 * only when that mesh is present.
 */
public final class ResolutionStudy {
    /** Relative RMS error under which a resolution is accepted. */
    public static final double TOLERANCE = 0.10;
    /** Ring counts of the parametric family; the last is the reference. */
    static final int[] RINGS = {10, 14, 20, 28, 43};
    /**
     * Clustering cell sizes (mm) for the imported mesh; the last is the reference. The full mesh is not
     * used as reference: its smallest elements force a stable step near 1.3e-5 s (docs/diaphragm.md).
     */
    static final double[] CELLS_MM = {16, 12, 9, 6.5};
    /** The BodyParts3D mesh, relative to the project folder. */
    public static final Path BODYPARTS_MESH = ProjectFolder.resolve("..", "shared", "meshes", "bodyparts3d",
            "diaphragm-FJ3131-dec28k-mm.obj");

    /**
     * One model's outcome: rest and end positions of its diaphragm nodes (3 per node, m),
     * which of them are on the upper surface, and its cost in wall seconds per simulated second.
     */
    public record Run(String family, String label, int nodes, int springs, double costPerSimS, double dt, double[] rest,
            double[] end, boolean[] upper) {
    }

    private ResolutionStudy() {
    }

    public static Map<String, Object> run(Path boxes, DiaphragmParameters p, BreathingCycle cycle,
            DiaphragmControls controls, DiaphragmReport.Options o, Path out, PrintStream log)
            throws IOException, MeshFormatException {
        Files.createDirectories(out);
        double seconds = Math.min(o.seconds(), cycle.inspirationS());
        Map<String, double[]> box = DiaphragmSetup.boxes(boxes);
        List<Run> parametric = new ArrayList<>();
        for (int rings : RINGS) {
            TriangleMesh m = DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings));
            parametric.add(simulate("double dome", rings + " rings", TwoSurfaces.split(m), box, p, cycle, controls,
                    seconds, log));
        }
        List<Run> imported = new ArrayList<>();
        if (Files.isRegularFile(BODYPARTS_MESH)) {
            TriangleMesh full = MeshLoader.load(BODYPARTS_MESH, MeshUnits.MM).mesh();
            TwoSurfaces split = TwoSurfaces.split(full);
            int[] groups = new int[full.vertexCount()];
            for (int v = 0; v < groups.length; v++) {
                groups[v] = split.isUpper(v) ? 1 : 0;
            }
            for (double cell : CELLS_MM) {
                TwoSurfaces s = split;
                if (cell > 0) {
                    VertexClustering.Result r = VertexClustering.simplify(full, groups, cell * 1e-3);
                    boolean[] up = new boolean[r.groups().length];
                    for (int v = 0; v < up.length; v++) {
                        up[v] = r.groups()[v] == 1;
                    }
                    s = TwoSurfaces.of(r.mesh(), up);
                }
                imported.add(simulate("BodyParts3D", cell > 0 ? "cells " + cell + " mm" : "full", s, box, p, cycle,
                        controls, seconds, log));
            }
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        List<Map<String, Object>> rows = new ArrayList<>();
        try (CsvWriter csv = new CsvWriter(out.resolve("resolution.csv"), List.of("family", "nodes", "springs",
                "dt_s", "wall_s_per_simulated_s", "relative_rms_error"), 1)) {
            for (List<Run> fam : List.of(parametric, imported)) {
                if (fam.isEmpty()) {
                    continue;
                }
                Run ref = fam.get(fam.size() - 1);
                for (Run r : fam) {
                    double e = r == ref ? 0 : error(ref, r);
                    Map<String, Object> row = new LinkedHashMap<>();
                    row.put("family", r.family());
                    row.put("model", r.label());
                    row.put("nodes", r.nodes());
                    row.put("springs", r.springs());
                    row.put("dt_s", r.dt());
                    row.put("wall_s_per_simulated_s", DiaphragmReport.round(r.costPerSimS(), 3));
                    row.put("relative_rms_error", DiaphragmReport.round(e, 4));
                    rows.add(row);
                    csv.row(fam == parametric ? 0 : 1, r.nodes(), r.springs(), r.dt(), r.costPerSimS(), e);
                }
            }
        }
        // The reference itself (error 0) is not a candidate: when no coarser model is within the
        // tolerance, none is chosen and the reference resolution stays the default.
        String chosen = null;
        for (int i = 0; i + 1 < parametric.size(); i++) {
            Map<String, Object> row = rows.get(i);
            if ((double) row.get("relative_rms_error") <= TOLERANCE) {
                chosen = (String) row.get("model");
                break;
            }
        }
        summary.put("simulated_s_per_model", seconds);
        summary.put("tolerance", TOLERANCE);
        summary.put("coarsest_double_dome_within_tolerance", chosen);
        summary.put("models", rows);
        chart(out.resolve("resolution.png"), rows);
        Json.write(out.resolve("resolution.json"), summary);
        return summary;
    }

    private static Run simulate(String family, String label, TwoSurfaces s, Map<String, double[]> box,
            DiaphragmParameters p, BreathingCycle cycle, DiaphragmControls controls, double seconds, PrintStream log) {
        DiaphragmScene scene = DiaphragmScene.build(s, box, p, cycle, controls, null);
        Simulation sim = scene.newSimulation();
        double dt = scene.recommendedTimeStep();
        long t0 = System.nanoTime();
        sim.runUntil(seconds, dt);
        double wall = (System.nanoTime() - t0) / 1e9;
        int nd = scene.diaphragmNodes();
        boolean[] upper = new boolean[nd];
        for (int v = 0; v < nd; v++) {
            upper[v] = s.isUpper(v);
        }
        Run r = new Run(family, label, scene.topology().nodeCount(), scene.topology().springs().size(),
                wall / sim.time(), dt, java.util.Arrays.copyOf(sim.state().x0, 3 * nd),
                java.util.Arrays.copyOf(sim.state().x, 3 * nd), upper);
        if (log != null) {
            log.println(String.format(Locale.ROOT, "%s, %s: %d nodes, %d springs, dt %.2e s, %.2f wall s per"
                    + " simulated s", family, label, r.nodes(), r.springs(), dt, r.costPerSimS()));
        }
        return r;
    }

    /** Relative RMS difference of the end displacement fields, nearest upper node of the coarse model. */
    public static double error(Run fine, Run coarse) {
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

    private static void chart(Path png, List<Map<String, Object>> rows) throws IOException {
        XYChart c = Charts.lineChart("Resolution study: error against the finest model vs cost",
                "wall seconds per simulated second", "relative RMS displacement error at the end of the run", 900, 600);
        c.getStyler().setXAxisLogarithmic(true);
        for (String fam : List.of("double dome", "BodyParts3D")) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (Map<String, Object> r : rows) {
                if (r.get("family").equals(fam) && (double) r.get("relative_rms_error") > 0) {
                    x.add((double) r.get("wall_s_per_simulated_s"));
                    y.add((double) r.get("relative_rms_error"));
                }
            }
            if (!x.isEmpty()) {
                XYSeries s = c.addSeries(fam, x, y);
                s.setMarker(SeriesMarkers.CIRCLE);
            }
        }
        double[] all = rows.stream().mapToDouble(r -> (double) r.get("wall_s_per_simulated_s")).toArray();
        double lo = java.util.Arrays.stream(all).min().orElse(0.01);
        double hi = java.util.Arrays.stream(all).max().orElse(1);
        Charts.addLine(c, "tolerance " + TOLERANCE, new double[] {lo, hi}, new double[] {TOLERANCE, TOLERANCE});
        c.getStyler().setMarkerSize(7);
        Charts.savePng(c, png);
    }
}
