package org.tensim.experiment;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.CsvWriter;
import org.tensim.io.FileDigest;
import org.tensim.io.Progress;
import org.tensim.io.RunFolder;
import org.tensim.io.RunSignals;
import org.tensim.io.RunStatus;
import org.tensim.scene.file.CoupledBodies;
import org.tensim.scene.file.RigidBody;
import org.tensim.scene.file.RunSettings;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.SurfaceSliding;
import org.tensim.solver.SystemState;

/**
 * Runs a loaded {@link Scene} headless: each deformable body is its own {@link Simulation} (bodies that touch or
 * slide on each other share one, {@link CoupledBodies}), all stepped in lockstep
 * with the run's integrator and step, and coupled through the scene's rigid bodies, whose surfaces and motions
 * every body's contacts, attachments and slidings share (a rigid body has no state to step: its pose is a function
 * of time); after the start and after every {@code every}-th step one CSV row holds the time
 * ({@code t_s}, the first body's clock) and every probe's values. The summary holds the scene file and its digest,
 * every {@code --set}, the run's settings, each body's node count and each CSV column's minimum and maximum, then,
 * for a scene with an {@code expect:} block, each check's measured value and verdict ({@link SceneExpectations}).
 * A body that diverges ends the run with status "diverged"; the CSV keeps the rows written. A run that ends but
 * fails a check has status "expectation_failed" (exit code 3), its outputs kept.
 */
public final class SceneRunner {
    private SceneRunner() {
    }

    /** Runs the scene with {@code run} (the file's settings, possibly overridden) into the run folder. */
    public static Map<String, Object> run(Scene loaded, RunSettings run, RunFolder folder) throws IOException {
        Scene scene = CoupledBodies.merge(loaded); // bodies touching each other share one simulation
        List<SceneBody> bodies = new ArrayList<>(scene.bodies().values());
        Map<String, Simulation> sims = CoupledBodies.simulations(scene, run.integrator());
        Map<SceneProbe, int[]> springs = energySprings(scene, sims);
        List<String> header = SceneExpectation.columns(scene.probes());
        double[] row = new double[header.size()];
        SceneExpectations.Columns stats = new SceneExpectations.Columns(header);
        Simulation clock = sims.values().iterator().next();
        long steps = run.steps();
        long made = 0;
        SimulationDivergedException diverged = null;
        try (CsvWriter w = folder.csv(run.csv(), header, 1000)) {
            Progress progress = Progress.start("run", run.durationS());
            sample(scene, sims, springs, 0, row);
            stats.add(row);
            w.row(row);
            for (long i = 1; i <= steps; i++) {
                RunSignals.checkStop();
                for (Simulation s : sims.values()) {
                    s.step(run.dtS());
                }
                made = i;
                if (i % run.every() == 0) {
                    sample(scene, sims, springs, clock.time(), row);
                    stats.add(row);
                    w.row(row);
                }
                progress.update(clock.time());
            }
            progress.close();
        } catch (SimulationDivergedException e) {
            diverged = e;
        }
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("scene", scene.file().toString());
        s.put("scene_digest", FileDigest.of(List.of(scene.file())));
        s.put("overrides", scene.overrides());
        s.put("integrator", run.integrator());
        s.put("dt_s", run.dtS());
        s.put("duration_s", run.durationS());
        s.put("steps", made);
        Map<String, Object> nodes = new LinkedHashMap<>();
        for (SceneBody b : bodies) {
            nodes.put(b.name(), b.topology().nodeCount());
        }
        s.put("body_nodes", nodes);
        Map<String, Object> range = new LinkedHashMap<>();
        for (int c = 1; c < header.size(); c++) {
            range.put(header.get(c), Map.of("min", finite(stats.min(c)), "max", finite(stats.max(c))));
        }
        s.put("columns", range);
        if (diverged != null) {
            s.put("diverged", diverged.getMessage());
            s.put("diverged_at_s", diverged.timeSeconds());
        }
        RunStatus status = diverged == null ? RunStatus.OK : RunStatus.DIVERGED;
        if (!scene.expect().isEmpty()) {
            List<Map<String, Object>> outcomes = SceneExpectations.evaluate(scene.expect(), stats, s);
            long failed = SceneExpectations.failed(outcomes);
            s.put("expectations", outcomes);
            s.put("expectations_failed", failed);
            if (failed > 0 && status == RunStatus.OK) {
                status = RunStatus.EXPECTATION_FAILED;
            }
        }
        return folder.finish(status, s);
    }

    /** A figure for the summary: the number, or "none" when it is not finite. */
    static Object finite(double v) {
        return Double.isFinite(v) ? v : "none";
    }

    /** Each energy probe's springs (both ends among its nodes), found once: {@link #sample} reads them. */
    public static Map<SceneProbe, int[]> energySprings(Scene scene, Map<String, Simulation> sims) {
        Map<SceneProbe, int[]> springs = new java.util.HashMap<>();
        for (SceneProbe p : scene.probes()) {
            if (p.quantity().equals("energy")) {
                springs.put(p, springsWithin(sims.get(p.body()).state(), p.nodes()));
            }
        }
        return springs;
    }

    /** The springs of {@code st} with both ends among {@code nodes}. */
    static int[] springsWithin(SystemState st, int[] nodes) {
        java.util.BitSet in = new java.util.BitSet();
        for (int n : nodes) {
            in.set(n);
        }
        return java.util.stream.IntStream.range(0, st.springCount())
                .filter(i -> in.get(st.springA[i]) && in.get(st.springB[i])).toArray();
    }

    /** {@code sum 1/2 k (l - l0)^2} over the springs, J. */
    static double elasticEnergy(SystemState st, int[] springs) {
        double e = 0;
        for (int i : springs) {
            int a = 3 * st.springA[i];
            int b = 3 * st.springB[i];
            double dx = st.x[b] - st.x[a];
            double dy = st.x[b + 1] - st.x[a + 1];
            double dz = st.x[b + 2] - st.x[a + 2];
            double ext = Math.sqrt(dx * dx + dy * dy + dz * dz) - st.springL[i];
            e += 0.5 * st.springK[i] * ext * ext;
        }
        return e;
    }

    /** {@code sum 1/2 m v^2} over the free nodes among {@code nodes}, J. */
    static double kineticEnergy(SystemState st, int[] nodes) {
        double e = 0;
        for (int n : nodes) {
            if (st.invMass[n] != 0) {
                double vx = st.v[3 * n];
                double vy = st.v[3 * n + 1];
                double vz = st.v[3 * n + 2];
                e += 0.5 * st.mass[n] * (vx * vx + vy * vy + vz * vz);
            }
        }
        return e;
    }

    /**
     * A rigid body's pose at t as {c, rotation vector}: 6 values into out[o..], m and rad. The rotation vector is
     * the axis times the angle, {@code theta = acos((tr R - 1) / 2)}, axis from R's antisymmetric part (exact
     * below pi; at pi its axis is not resolved and the vector is zero).
     */
    static void pose(RigidBody b, double t, double[] out, int o) {
        double[] r = new double[9];
        double[] c = new double[3];
        b.motion().pose(t, r, 0, c, 0);
        out[o] = c[0];
        out[o + 1] = c[1];
        out[o + 2] = c[2];
        double wx = r[7] - r[5];
        double wy = r[2] - r[6];
        double wz = r[3] - r[1];
        double cos = Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2));
        double theta = Math.acos(cos);
        double sin = Math.sqrt(wx * wx + wy * wy + wz * wz) / 2;
        double f = sin < 1e-12 ? 0.5 : theta / (2 * sin);
        out[o + 3] = f * wx;
        out[o + 4] = f * wy;
        out[o + 5] = f * wz;
    }

    /**
     * A contact probe's largest penetration {@code max(0, g - d)} and separation {@code max(0, d - g)} over its
     * pairs at time t, m, into out[o], out[o + 1]; d is the node's signed distance to the rigid solid at its pose.
     */
    static void contact(RigidBody b, SceneProbe p, SystemState st, double t, double[] out, int o) {
        double[] r = new double[9];
        double[] c = new double[3];
        double[] g = new double[3];
        b.motion().pose(t, r, 0, c, 0);
        double pen = 0;
        double sep = 0;
        for (int i = 0; i < p.nodes().length; i++) {
            int n = 3 * p.nodes()[i];
            double dx = st.x[n] - c[0];
            double dy = st.x[n + 1] - c[1];
            double dz = st.x[n + 2] - c[2];
            double d = b.surface().distance(r[0] * dx + r[3] * dy + r[6] * dz, r[1] * dx + r[4] * dy + r[7] * dz,
                    r[2] * dx + r[5] * dy + r[8] * dz, g, 0);
            pen = Math.max(pen, p.weights()[i] - d);
            sep = Math.max(sep, d - p.weights()[i]);
        }
        out[o] = pen;
        out[o + 1] = sep;
    }

    /**
     * A contact probe on a coupling of deformable bodies ({@link CoupledBodies}): the largest penetration and
     * separation over the followers of the sliding terms whose followers are the probe's nodes, m, into out[o],
     * out[o + 1].
     */
    static void coupled(Simulation sim, SceneProbe p, double[] out, int o) {
        double pen = 0;
        double sep = 0;
        int seen = 0;
        for (org.tensim.solver.ForceTerm term : sim.forces().terms()) {
            if (term instanceof SurfaceSliding s && covers(p.nodes(), s)) {
                pen = Math.max(pen, s.maxPenetrationM(sim.state().x));
                sep = Math.max(sep, s.maxSeparationM(sim.state().x));
                seen += s.pairCount();
            }
        }
        if (seen != p.nodes().length) {
            throw new IllegalStateException("probe " + p.name() + " reads " + p.nodes().length + " followers but the"
                    + " simulation's sliding terms hold " + seen + " of them");
        }
        out[o] = pen;
        out[o + 1] = sep;
    }

    /** True when every follower of s (every node of a mapped follower) is among the nodes. */
    private static boolean covers(int[] nodes, SurfaceSliding s) {
        java.util.BitSet in = new java.util.BitSet();
        for (int n : nodes) {
            in.set(n);
        }
        org.tensim.model.LinearMapping f = s.followers();
        for (int e = 0; e < s.pairCount(); e++) {
            for (int k = 0; k < f.entries(e); k++) {
                if (!in.get(f.node(e, k))) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * One CSV row of the scene's probes ({@link SceneExpectation#columns}) at time t: the time, then every
     * probe's values from the bodies' simulations (by body name); {@code springs} are the energy probes' springs
     * ({@link #energySprings}), found once before the run.
     */
    public static void sample(Scene scene, Map<String, Simulation> sims, Map<SceneProbe, int[]> springs, double t,
            double[] row) {
        row[0] = t;
        int c = 1;
        double[] d = new double[3];
        for (SceneProbe p : scene.probes()) {
            if (p.quantity().equals("pose")) {
                pose(scene.rigids().get(p.body()), t, row, c);
                c += 6;
                continue;
            }
            SystemState st = sims.get(p.body()).state();
            if (p.quantity().equals("contact") && !scene.rigids().containsKey(p.with())) {
                coupled(sims.get(p.body()), p, row, c);
                c += 2;
                continue;
            }
            if (p.quantity().equals("contact")) {
                contact(scene.rigids().get(p.with()), p, st, t, row, c);
                c += 2;
                continue;
            }
            if (p.quantity().equals("energy")) {
                row[c++] = elasticEnergy(st, springs.get(p));
                row[c++] = kineticEnergy(st, p.nodes());
            } else if (p.quantity().equals("extents")) {
                for (int a = 0; a < 3; a++) {
                    double lo = Double.POSITIVE_INFINITY;
                    double hi = Double.NEGATIVE_INFINITY;
                    for (int n : p.nodes()) {
                        lo = Math.min(lo, st.position(n, a));
                        hi = Math.max(hi, st.position(n, a));
                    }
                    row[c++] = lo;
                    row[c++] = hi;
                }
            } else if (p.nodes().length == 1 && p.quantity().equals("displacement")) {
                st.displacement(p.nodes()[0], d);
                row[c++] = d[0];
                row[c++] = d[1];
                row[c++] = d[2];
            } else {
                // A region's mean, or a surface vertex's weighted sum over the nodes carrying it.
                double[] sum = new double[3];
                for (int i = 0; i < p.nodes().length; i++) {
                    st.displacement(p.nodes()[i], d);
                    double w = p.weights() == null ? 1 : p.weights()[i];
                    sum[0] += w * d[0];
                    sum[1] += w * d[1];
                    sum[2] += w * d[2];
                }
                for (int a = 0; a < 3; a++) {
                    row[c++] = p.weights() == null ? sum[a] / p.nodes().length : sum[a];
                }
            }
        }
    }
}
