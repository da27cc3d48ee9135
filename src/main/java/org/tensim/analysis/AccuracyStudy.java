package org.tensim.analysis;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.tensim.model.Topology;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.integrators.Integrators;

/**
 * Work-precision study of one scene: every integrator on a ladder of time steps,
 * each run from the scene's initial state to its end time through the whole
 * {@link Simulation} (integrator, rigid-link projection, velocity update, checks).
 *
 * <p>Error: the largest node position error at the end time, m, against
 * <ul>
 * <li>the exact solution when the scene has one ({@code exact});</li>
 * <li>otherwise, without rigid links, Hipparchus' Dormand-Prince 8(5,3) at
 * relative and absolute tolerance 1e-12 ({@code dormand-prince-853});</li>
 * <li>with rigid links, RK4 (the most accurate method here) at a sixteenth of the
 * ladder's finest step ({@code rk4-finest}); its own error is estimated by the
 * difference with RK4 at twice that step (an overestimate unless the scheme is
 * first order, which it is with rigid links: see docs/accuracy.md).</li>
 * </ul>
 * Cost: the wall time of the run (after a warm-up, best of up to 5 repeats within 0.3 s)
 * and the force evaluations counted by the force model (plus, for implicit Euler,
 * its CG matrix-vector products, each about one spring pass).
 *
 * <p>Measured order: the least-squares slope of log(error) against log(dt) over
 * the (up to 4) finest consecutive rungs whose error lies in the asymptotic range:
 * above the floor (10 times the reference's own error, and 1e-10 of the scene's
 * size, below which round-off rules), below the ceiling (10 % of the largest
 * end displacement, above which the error is no longer small), and with a time
 * step within the integrator's critical step estimate.
 */
public final class AccuracyStudy {
    /** Rungs used at most for the order fit. */
    public static final int FIT_POINTS = 4;

    /**
     * One run.
     *
     * @param integrator        integrator name
     * @param dtS               time step, s
     * @param errorM            largest node position error at the end time, m (NaN when diverged)
     * @param wallS             wall time of the run, s
     * @param forceEvaluations  force passes made
     * @param linearProducts    CG matrix-vector products (implicit Euler), else 0
     * @param steps             steps made
     * @param beyondCriticalStep whether dt was beyond the integrator's critical step estimate
     * @param diverged          whether the run was stopped by the divergence checks
     */
    public record Run(String integrator, double dtS, double errorM, double wallS, long forceEvaluations,
            long linearProducts, long steps, boolean beyondCriticalStep, boolean diverged) {
    }

    /**
     * The study of one scene.
     *
     * @param scene          the scene
     * @param reference      how the reference was obtained: exact, dormand-prince-853 or rk4-finest
     * @param referenceErrorM estimate of the reference's own error, m
     * @param floorM         errors below are round-off or reference error, m
     * @param ceilingM       errors above are outside the asymptotic range, m
     * @param runs           all runs, integrator by integrator, largest dt first
     * @param measuredOrder  measured order per integrator (NaN when fewer than 2 rungs are usable)
     * @param expectedOrder  theoretical order per integrator
     */
    public record Result(AccuracyScene scene, String reference, double referenceErrorM, double floorM,
            double ceilingM, List<Run> runs, Map<String, Double> measuredOrder, Map<String, Integer> expectedOrder) {
    }

    private AccuracyStudy() {
    }

    /** Runs the study with the given integrator names, reporting progress lines to {@code progress}. */
    public static Result run(AccuracyScene scene, List<String> integrators, Consumer<String> progress) {
        Topology t = scene.topology().get();
        double[] ladder = scene.ladder();
        double end = scene.endTimeS();
        SystemState initial = SystemState.compile(t);
        double[] ref;
        String kind;
        double refErr;
        if (scene.exact() != null) {
            ref = new double[initial.x.length];
            scene.exact().positions(end, ref);
            kind = "exact";
            refErr = 0;
        } else if (t.rigidLinks().isEmpty()) {
            ref = ReferenceSolution.solve(t, end, ReferenceSolution.DEFAULT_TOLERANCE);
            kind = "dormand-prince-853";
            double[] loose = ReferenceSolution.solve(t, end, 100 * ReferenceSolution.DEFAULT_TOLERANCE);
            refErr = maxDistance(ref, loose) / 100; // error scales about with the tolerance
        } else {
            double fine = ladder[ladder.length - 1] / 16;
            ref = finalPositions(scene, Integrators.create("rk4"), fine);
            kind = "rk4-finest";
            refErr = maxDistance(ref, finalPositions(scene, Integrators.create("rk4"), 2 * fine));
        }
        progress.accept(scene.name() + ": reference " + kind + " (own error about " + refErr + " m)");

        double size = 0;
        double disp = 0;
        for (int k = 0; k < ref.length; k++) {
            size = Math.max(size, Math.abs(initial.x0[k]));
        }
        for (int i = 0; i < initial.nodeCount; i++) {
            disp = Math.max(disp, distance(ref, initial.x0, i));
        }
        double floor = Math.max(10 * refErr, 1e-10 * Math.max(size, 1));
        double ceiling = 0.1 * Math.max(disp, 1e-3 * Math.max(size, 1));

        List<Run> runs = new ArrayList<>();
        Map<String, Double> orders = new LinkedHashMap<>();
        Map<String, Integer> expected = new LinkedHashMap<>();
        for (String name : integrators) {
            // Warm-up (JIT) on the largest step, so that the first timed rung is not the slowest.
            for (int w = 0; w < 3; w++) {
                oneRun(scene, name, ladder[0], ref);
            }
            double[] err = new double[ladder.length];
            for (int r = 0; r < ladder.length; r++) {
                Run run = timedRun(scene, name, ladder[r], ref);
                runs.add(run);
                // A run beyond the critical step is outside the asymptotic range, whatever its error.
                err[r] = run.diverged() || run.beyondCriticalStep() ? Double.NaN : run.errorM();
                progress.accept(String.format("%s %-16s dt %.3e s  error %.3e m  %8.4f s  %d force passes%s",
                        scene.name(), name, ladder[r], run.errorM(), run.wallS(), run.forceEvaluations(),
                        run.diverged() ? "  DIVERGED" : run.beyondCriticalStep() ? "  (beyond critical step)" : ""));
            }
            orders.put(name, measuredOrder(ladder, err, floor, ceiling));
            expected.put(name, Integrators.create(name).order());
        }
        return new Result(scene, kind, refErr, floor, ceiling, runs, orders, expected);
    }

    /**
     * Slope of log(err) against log(dt) over the finest consecutive usable rungs
     * (at most {@link #FIT_POINTS}); NaN when fewer than two are usable.
     *
     * @param dt  time steps, largest first
     * @param err errors (NaN for failed runs)
     */
    public static double measuredOrder(double[] dt, double[] err, double floor, double ceiling) {
        int last = -1;
        for (int i = dt.length - 1; i >= 0; i--) {
            if (usable(err[i], floor, ceiling)) {
                last = i;
                break;
            }
        }
        if (last < 0) {
            return Double.NaN;
        }
        int first = last;
        while (first - 1 >= 0 && last - first + 1 < FIT_POINTS && usable(err[first - 1], floor, ceiling)) {
            first--;
        }
        int n = last - first + 1;
        if (n < 2) {
            return Double.NaN;
        }
        double sx = 0;
        double sy = 0;
        double sxx = 0;
        double sxy = 0;
        for (int i = first; i <= last; i++) {
            double lx = Math.log(dt[i]);
            double ly = Math.log(err[i]);
            sx += lx;
            sy += ly;
            sxx += lx * lx;
            sxy += lx * ly;
        }
        return (n * sxy - sx * sy) / (n * sxx - sx * sx);
    }

    private static boolean usable(double e, double floor, double ceiling) {
        return Double.isFinite(e) && e > floor && e < ceiling;
    }

    /**
     * One run, timed: repeated (best time kept, which is the least disturbed by other
     * work on the machine) up to 5 times while the runs so far took under 0.3 s.
     */
    static Run timedRun(AccuracyScene scene, String integrator, double dt, double[] ref) {
        Run best = null;
        double spent = 0;
        for (int rep = 0; rep < 5 && spent < 0.3; rep++) {
            Run r = oneRun(scene, integrator, dt, ref);
            spent += r.wallS();
            if (best == null || r.wallS() < best.wallS()) {
                best = r;
            }
        }
        return best;
    }

    private static Run oneRun(AccuracyScene scene, String name, double dt, double[] ref) {
        Integrator integrator = Integrators.create(name);
        Simulation sim = new Simulation(SystemState.compile(scene.topology().get()), integrator);
        sim.setWarningSink(m -> { }); // beyond-critical steps are read from the counter below
        sim.apply(sim.settings().withProjectionFailureSeverity(org.tensim.solver.Severity.IGNORE));
        long t0 = System.nanoTime();
        boolean diverged = false;
        try {
            sim.runUntil(scene.endTimeS(), dt);
        } catch (SimulationDivergedException e) {
            diverged = true;
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        double err = diverged ? Double.NaN : maxDistance(sim.state().x, ref);
        long products = integrator instanceof ImplicitEuler ie ? ie.matrixVectorProducts()
                : integrator instanceof org.tensim.solver.prefactored.PrefactoredBdf2 b ? b.jacobianProducts() : 0;
        return new Run(name, dt, err, wall, sim.forces().evaluations(), products, sim.steps(),
                sim.stepLimitWarnings() > 0, diverged);
    }

    /** Positions at the scene's end time with one integrator and step. */
    static double[] finalPositions(AccuracyScene scene, Integrator integrator, double dt) {
        Simulation sim = new Simulation(SystemState.compile(scene.topology().get()), integrator);
        sim.setWarningSink(m -> { });
        sim.runUntil(scene.endTimeS(), dt);
        return sim.state().x.clone();
    }

    /** Largest distance between corresponding nodes of two position arrays, m. */
    public static double maxDistance(double[] a, double[] b) {
        double worst = 0;
        for (int i = 0; i < a.length / 3; i++) {
            double d = distance(a, b, i);
            if (!(d <= worst)) {
                worst = d;
            }
        }
        return worst;
    }

    private static double distance(double[] a, double[] b, int i) {
        double dx = a[3 * i] - b[3 * i];
        double dy = a[3 * i + 1] - b[3 * i + 1];
        double dz = a[3 * i + 2] - b[3 * i + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
