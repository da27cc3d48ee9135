package org.tensim.bench;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.experiment.SceneGraphSync;
import org.tensim.model.Topology;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.ShuffledScene;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.Stage;
import org.tensim.solver.SystemState;
import org.tensim.solver.parallel.ParallelSpringPass;
import org.tensim.solver.parallel.Parallelism;

/**
 * Times the force pass and whole steps of one case (a scene, an integrator, a
 * thread count). The benchmark lattice ({@link LatticeScene}: spacing 0.1 m, 1 kg
 * nodes, 1000 N/m springs, no spring damping, gravity, bottom fixed) is built here;
 * other scenes come in as topologies. Reports the best and the median of repeated
 * runs, so that noise from a shared machine shows; the state is reset to rest
 * before each repetition so that long runs of the undamped lattice stay bounded.
 */
public final class LatticeBenchmark {
    /** Lattice spacing, m. */
    public static final double SPACING_M = 0.1;
    /** Node mass, kg. */
    public static final double MASS_KG = 1;
    /** Spring stiffness, N/m: w_max h stays about 0.2 at dt = 1e-3 s. */
    public static final double STIFFNESS_N_PER_M = 1000;
    /** Spring evaluations aimed at per timed repetition: about 0.1-0.3 s of work. */
    static final double WORK_PER_REPEAT = 2e7;

    private LatticeBenchmark() {
    }

    /** The benchmark lattice of n nodes per side, optionally with rigid body diagonals. */
    public static Topology lattice(int n, boolean links) {
        return LatticeScene.build(n, SPACING_M, MASS_KG, STIFFNESS_N_PER_M, 0, links);
    }

    /**
     * One case: what to run and how long. {@code simulation}: a scene's own simulation
     * (its projection settings kept; the integrator is replaced), or null to compile
     * {@code topology}.
     */
    public record Case(String scene, int n, Topology topology, Simulation simulation, boolean shuffled,
            Integrator integrator, int threads, ParallelSpringPass.Order order, boolean builtin, double dt, int steps,
            int repeats) {
    }

    /** Runs one case and returns its figures (keys as printed). */
    public static Map<String, Object> run(Case c) {
        Simulation sim;
        if (c.simulation() != null) {
            sim = c.simulation();
            sim.setIntegrator(c.integrator());
        } else {
            Topology t = c.shuffled() ? ShuffledScene.shuffle(c.topology(), 1234) : c.topology();
            sim = new Simulation(SystemState.compile(t), c.integrator());
        }
        SystemState s = sim.state();
        int ns = Math.max(1, s.springCount());
        int steps = c.steps() > 0 ? c.steps()
                : (int) Math.max(10, Math.min(5000, WORK_PER_REPEAT / ns / c.integrator().forceEvaluationsPerStep()));
        Map<String, Object> m = new LinkedHashMap<>();
        // builtin: the single-threaded loops of ForceModel and RigidLinkProjection, for before/after figures.
        try (Parallelism par = c.builtin() ? null : Parallelism.install(sim, c.threads(), c.order())) {
            ForceModel fm = sim.forces();
            double[] f = new double[s.x.length];

            // Force pass: warm up, then best/median over repeats.
            int passes = (int) Math.max(5, WORK_PER_REPEAT / ns);
            for (int i = 0; i < 2 * passes; i++) {
                fm.computeForces(0, s.x, s.v, f);
            }
            double[] forceRate = new double[c.repeats()];
            for (int r = 0; r < c.repeats(); r++) {
                long t0 = System.nanoTime();
                for (int i = 0; i < passes; i++) {
                    fm.computeForces(0, s.x, s.v, f);
                }
                forceRate[r] = (double) s.springCount() * passes / ((System.nanoTime() - t0) / 1e9);
            }

            // Whole steps (all stages, the scene-graph sync included), after a warm-up.
            SceneGraphSync sync = new SceneGraphSync(s.nodeCount);
            long[] iterations = new long[1];
            sim.addListener(sync);
            sim.addListener(x -> iterations[0] += x.projection().iterations());
            rest(s);
            for (int i = 0; i < Math.max(10, steps / 2); i++) {
                sim.step(c.dt());
            }
            double[] msPerStep = new double[c.repeats()];
            double[] projMs = new double[c.repeats()];
            double[] syncMs = new double[c.repeats()];
            for (int r = 0; r < c.repeats(); r++) {
                rest(s);
                sim.profile().reset();
                sync.reset();
                iterations[0] = 0;
                long t0 = System.nanoTime();
                for (int i = 0; i < steps; i++) {
                    sim.step(c.dt());
                }
                msPerStep[r] = (System.nanoTime() - t0) / 1e6 / steps;
                projMs[r] = sim.profile().meanMillis(Stage.PROJECT);
                syncMs[r] = sync.meanMillis();
            }

            m.put("scene", c.scene());
            m.put("n", c.n());
            m.put("nodes", s.nodeCount);
            m.put("springs", s.springCount());
            m.put("links", s.linkCount());
            m.put("threads", c.builtin() ? 1 : c.threads());
            m.put("solver", c.builtin() ? "builtin" : "parallel");
            m.put("integrator", c.integrator().name());
            m.put("order", c.order().name().toLowerCase());
            m.put("shuffled", c.shuffled());
            m.put("permuted", par != null && par.springPass().permuted());
            m.put("dt_s", c.dt());
            m.put("steps", steps);
            m.put("repeats", c.repeats());
            m.put("ms_per_step", median(msPerStep));
            m.put("ms_per_step_best", min(msPerStep));
            m.put("force_pass_springs_per_s", max(forceRate));
            m.put("force_pass_springs_per_s_median", median(forceRate));
            m.put("step_springs_per_s", s.springCount() / (min(msPerStep) / 1e3));
            m.put("step_springs_per_s_median", s.springCount() / (median(msPerStep) / 1e3));
            m.put("ns_per_spring_step", min(msPerStep) * 1e6 / ns);
            // Simulated seconds per wall-clock second: real time or better when >= 1.
            m.put("realtime_factor", c.dt() / (min(msPerStep) / 1e3));
            m.put("realtime_factor_median", c.dt() / (median(msPerStep) / 1e3));
            m.put("projection_ms_per_step", median(projMs));
            m.put("projection_ms_per_step_best", min(projMs));
            m.put("projection_iterations_per_step", (double) iterations[0] / steps);
            m.put("link_colours", par == null || par.linkSweeps() == null ? 0 : par.linkSweeps().colours());
            m.put("sync_ms_per_step", median(syncMs));
            m.put("sync_ms_per_step_best", min(syncMs));
            m.put("duplicated_springs", par == null ? 0 : par.springPass().duplicatedSprings());
            m.put("load_average", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
        return m;
    }

    /** Back to the initial positions, at rest (outside the timed region). */
    private static void rest(SystemState s) {
        System.arraycopy(s.x0, 0, s.x, 0, s.x.length);
        Arrays.fill(s.v, 0);
    }

    static double median(double[] a) {
        double[] c = a.clone();
        Arrays.sort(c);
        int k = c.length / 2;
        return c.length % 2 == 1 ? c[k] : 0.5 * (c[k - 1] + c[k]);
    }

    static double min(double[] a) {
        return Arrays.stream(a).min().orElse(Double.NaN);
    }

    static double max(double[] a) {
        return Arrays.stream(a).max().orElse(Double.NaN);
    }
}
