package org.tensim.bench;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.model.Topology;
import org.tensim.scene.LatticeScene;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.Stage;
import org.tensim.solver.SystemState;

/**
 * Times the force pass and whole steps on the benchmark lattice
 * ({@link LatticeScene}: spacing 0.1 m, 1 kg nodes, 1000 N/m springs, no spring
 * damping, gravity, bottom fixed). Reports the best and the median of repeated
 * runs, so that noise from a shared machine shows.
 */
public final class LatticeBenchmark {
    /** Lattice spacing, m. */
    public static final double SPACING_M = 0.1;
    /** Node mass, kg. */
    public static final double MASS_KG = 1;
    /** Spring stiffness, N/m: w_max h stays about 0.2 at dt = 1e-3 s. */
    public static final double STIFFNESS_N_PER_M = 1000;

    private LatticeBenchmark() {
    }

    /**
     * Runs one case and returns its figures (keys as printed).
     *
     * @param n         nodes per side
     * @param links     add a rigid link along one body diagonal of every cell
     * @param dt        time step, s
     * @param steps     timed steps per repetition
     * @param repeats   repetitions (best and median are reported)
     */
    public static Map<String, Object> run(int n, boolean links, Integrator integrator, double dt, int steps,
            int repeats) {
        Topology t = LatticeScene.build(n, SPACING_M, MASS_KG, STIFFNESS_N_PER_M, 0, links);
        SystemState s = SystemState.compile(t);
        Simulation sim = new Simulation(s, integrator);
        ForceModel fm = sim.forces();
        double[] f = new double[s.x.length];

        // Force pass: warm up, then best/median over repeats of enough passes for ~0.2 s.
        int passes = (int) Math.max(5, 4e7 / Math.max(1, s.springCount()));
        for (int i = 0; i < 3 * passes; i++) {
            fm.computeForces(0, s.x, s.v, f);
        }
        double[] forceRate = new double[repeats];
        for (int r = 0; r < repeats; r++) {
            long t0 = System.nanoTime();
            for (int i = 0; i < passes; i++) {
                fm.computeForces(0, s.x, s.v, f);
            }
            forceRate[r] = (double) s.springCount() * passes / ((System.nanoTime() - t0) / 1e9);
        }

        // Whole steps (all stages), after a warm-up.
        for (int i = 0; i < Math.min(steps, 50); i++) {
            sim.step(dt);
        }
        double[] msPerStep = new double[repeats];
        double[] projMs = new double[repeats];
        for (int r = 0; r < repeats; r++) {
            sim.profile().reset();
            long t0 = System.nanoTime();
            for (int i = 0; i < steps; i++) {
                sim.step(dt);
            }
            msPerStep[r] = (System.nanoTime() - t0) / 1e6 / steps;
            projMs[r] = sim.profile().meanMillis(Stage.PROJECT);
        }

        Map<String, Object> m = new LinkedHashMap<>();
        m.put("scene", "lattice");
        m.put("n", n);
        m.put("nodes", s.nodeCount);
        m.put("springs", s.springCount());
        m.put("links", s.linkCount());
        m.put("threads", 1);
        m.put("integrator", integrator.name());
        m.put("dt_s", dt);
        m.put("steps", steps);
        m.put("repeats", repeats);
        m.put("ms_per_step", median(msPerStep));
        m.put("ms_per_step_best", min(msPerStep));
        m.put("force_pass_springs_per_s", max(forceRate));
        m.put("force_pass_springs_per_s_median", median(forceRate));
        m.put("step_springs_per_s", s.springCount() / (min(msPerStep) / 1e3));
        m.put("step_springs_per_s_median", s.springCount() / (median(msPerStep) / 1e3));
        m.put("projection_ms_per_step", median(projMs));
        m.put("projection_iterations_last", sim.projection().iterations());
        return m;
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
