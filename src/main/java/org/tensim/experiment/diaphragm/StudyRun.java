package org.tensim.experiment.diaphragm;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.tensim.experiment.SceneGraphSync;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * One timed run of the real-time study: the diaphragm from rest with one integrator, step and thread
 * count, the scene-graph sync after every step, and the displacement field of the diaphragm nodes
 * sampled every {@link #SAMPLE_S} and at the end (outside the timed stepping). The samples of RK2 at a resolution
 * are the reference of the other runs at that resolution ({@link #errorAgainst}).
 *
 * @param run             positions at rest and at the end, for the error against other resolutions
 * @param realtimeWall    simulated seconds per wall second of the stepping loop (steps, projection, sync), from the
 *                        second step on (the first, with its one-off factorisation, is untimed)
 * @param realtimeCpu     simulated seconds per CPU second of the stepping thread(s)
 * @param apexDescentMm   the apex's descent at the end, mm
 * @param productsPerStep CG matrix-vector products per step (0 for explicit methods)
 * @param diverged        whether the divergence checks stopped the run
 * @param samples         displacement fields of the diaphragm nodes (m, 3 per node), one per sample time
 * @param apexSamplesMm   the apex's descent at the sample times, mm
 * @param sampleTimesS    the sample times, s
 */
record StudyRun(ResolutionStudy.Run run, double realtimeWall, double realtimeCpu, double apexDescentMm,
        double productsPerStep, boolean diverged, List<double[]> samples, double[] apexSamplesMm,
        double[] sampleTimesS) {
    /** Interval of the displacement samples, s (a multiple of every large step of the study). */
    static final double SAMPLE_S = 0.05;

    /** Simulated time of the timed run that gives the speed of a reference whose samples were cached, s (at least). */
    static final double SPEED_SPAN_S = 0.02;

    /** Steps of that timed run, at least: a 5 ms reference would otherwise time four steps. */
    static final int SPEED_SPAN_STEPS = 20;

    /** Simulated time of the timed run that gives the speed of a cached reference stepped at {@code dt}, s. */
    static double speedSpanS(double dt) {
        return Math.max(SPEED_SPAN_S, SPEED_SPAN_STEPS * dt);
    }

    /** Sample times of a run of {@code seconds}: every {@link #SAMPLE_S} and the end. */
    static double[] sampleTimes(double seconds) {
        double[] t = new double[(int) Math.ceil(seconds / SAMPLE_S - 1e-9)];
        for (int s = 1; s <= t.length; s++) {
            t[s - 1] = Math.min(s * SAMPLE_S, seconds);
        }
        return t;
    }

    /**
     * The same-mesh reference: its samples from {@code cache} when it holds them (the speed then from a
     * timed run of {@link #speedSpanS}), else a full run whose samples are saved there.
     */
    static StudyRun reference(DiaphragmScene scene, int rings, RealTimeStudy.Config c, double seconds, Path cache,
            java.io.PrintStream log) throws java.io.IOException {
        return reference(scene, "double dome", rings + " rings, " + c.label(), c, seconds, cache, log);
    }

    /** As the overload above for a scene of the given family, the run named by {@code label}. */
    static StudyRun reference(DiaphragmScene scene, String family, RealTimeStudy.Config c, double seconds, Path cache,
            java.io.PrintStream log) throws java.io.IOException {
        return reference(scene, family, c.label(), c, seconds, cache, log);
    }

    private static StudyRun reference(DiaphragmScene scene, String family, String label, RealTimeStudy.Config c,
            double seconds, Path cache, java.io.PrintStream log) throws java.io.IOException {
        int nd = scene.diaphragmNodes();
        int apex = scene.apexNode();
        double[] times = sampleTimes(seconds);
        List<double[]> cached = ReferenceCache.load(cache, nd, apex, times, scene.recommendedTimeStep());
        if (cached == null) {
            StudyRun r = simulate(scene, family, label, c, seconds);
            if (!r.diverged()) {
                ReferenceCache.save(cache, r, apex);
            }
            return r;
        }
        Integrator probe = c.integrator().get();
        double span = speedSpanS(scene.timeStep(probe, c.dt()).seconds());
        if (log != null) {
            log.println(String.format(Locale.ROOT, "reference samples of %s from %s; its speed from a %.3f s run",
                    c.label(), cache, span));
        }
        StudyRun timed = simulate(scene, family, label, c, span);
        double[] apexMm = new double[times.length];
        for (int s = 0; s < times.length; s++) {
            apexMm[s] = -1e3 * cached.get(s)[3 * apex + 2];
        }
        double[] rest = timed.run().rest();
        double[] end = new double[rest.length];
        for (int k = 0; k < end.length; k++) {
            end[k] = rest[k] + cached.get(times.length - 1)[k];
        }
        ResolutionStudy.Run t = timed.run();
        ResolutionStudy.Run r = new ResolutionStudy.Run(t.family(), t.label(), t.nodes(), t.springs(), t.costPerSimS(),
                t.dt(), rest, end, t.upper());
        return new StudyRun(r, timed.realtimeWall(), timed.realtimeCpu(), apexMm[times.length - 1], 0, false, cached,
                apexMm, times);
    }

    /** Runs one configuration for {@code seconds} on the generated double dome of {@code rings} rings. */
    static StudyRun simulate(DiaphragmScene scene, int rings, RealTimeStudy.Config c, double seconds) {
        return simulate(scene, "double dome", rings + " rings, " + c.label(), c, seconds);
    }

    /** Runs one configuration for {@code seconds}; family and label name the run ({@link ResolutionStudy.Run}). */
    static StudyRun simulate(DiaphragmScene scene, String family, String label, RealTimeStudy.Config c,
            double seconds) {
        Simulation sim = scene.newSimulation();
        Integrator in = c.integrator().get();
        sim.setIntegrator(in);
        double dt = scene.timeStep(in, c.dt()).seconds();
        int nd = scene.diaphragmNodes();
        sim.addListener(new SceneGraphSync(sim.state().nodeCount));
        int apex = scene.apexNode();
        double z0 = sim.state().x[3 * apex + 2];
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        boolean cpuTimed = mx.isThreadCpuTimeSupported();
        double[] targets = sampleTimes(seconds);
        int nSamples = targets.length;
        List<double[]> samples = new ArrayList<>();
        double[] apexMm = new double[nSamples];
        double[] times = new double[nSamples];
        long wall = 0;
        long cpu = 0;
        boolean diverged = false;
        double untimedS = 0;
        try (Parallelism par = c.threads() > 1 ? Parallelism.install(sim, c.threads()) : null) {
            long[] ids = par == null ? new long[0] : par.pool().workerThreadIds();
            try {
                if (nSamples > 0 && targets[0] > 1.5 * dt) {
                    // The first step carries one-off work (a prefactored integrator's first factorisation, the
                    // JIT's first pass): untimed, so that the speed is the steady state a user sees after the start,
                    // whatever the run's length (a cached reference is timed over a short run).
                    sim.step(dt);
                    untimedS = sim.time();
                }
                for (int s = 1; s <= nSamples; s++) {
                    long cpu0 = cpuTimed ? cpuOf(mx, ids) : 0;
                    long t0 = System.nanoTime();
                    sim.runUntil(targets[s - 1], dt);
                    wall += System.nanoTime() - t0;
                    cpu += cpuTimed ? cpuOf(mx, ids) - cpu0 : 0;
                    double[] d = new double[3 * nd];
                    for (int k = 0; k < d.length; k++) {
                        d[k] = sim.state().x[k] - sim.state().x0[k];
                    }
                    samples.add(d);
                    apexMm[s - 1] = -1e3 * (sim.state().x[3 * apex + 2] - z0);
                    times[s - 1] = sim.time();
                }
            } catch (SimulationDivergedException e) {
                diverged = true;
            }
        }
        double simulated = sim.time() - untimedS;
        double products = in instanceof ImplicitEuler ie ? ie.matrixVectorProducts()
                : in instanceof PrefactoredBdf2 b ? b.jacobianProducts() : 0;
        boolean[] upper = new boolean[nd];
        for (int v = 0; v < nd; v++) {
            upper[v] = scene.surfaces().isUpper(v);
        }
        ResolutionStudy.Run r = new ResolutionStudy.Run(family, label,
                scene.topology().nodeCount(), scene.topology().springs().size(), wall / 1e9 / simulated, dt,
                Arrays.copyOf(sim.state().x0, 3 * nd), Arrays.copyOf(sim.state().x, 3 * nd), upper);
        return new StudyRun(r, simulated / (wall / 1e9), cpuTimed ? simulated / (cpu / 1e9) : Double.NaN,
                -1e3 * (sim.state().x[3 * apex + 2] - z0), products / Math.max(1, sim.steps()), diverged, samples,
                apexMm, times);
    }

    /**
     * Errors against a reference run at the same resolution: {@code [end, worst, worstTimeS, apexEndMm,
     * apexWorstMm]}. The end error is the relative RMS difference of the displacement fields at the last
     * sample, |d - d_ref| / |d_ref|. The worst is the largest RMS difference over the samples divided by
     * the reference's largest RMS displacement over the run (the amplitude of the motion, at end-inspiration
     * for a breathing cycle): dividing by each moment's own displacement would divide by zero at rest. The
     * apex errors are the difference of the apex's descent at the end and the largest over the samples, mm.
     * A diverged or shorter run has infinite errors.
     */
    double[] errorAgainst(StudyRun ref) {
        int n = ref.samples.size();
        if (diverged || samples.size() < n) {
            double inf = Double.POSITIVE_INFINITY;
            return new double[] {inf, inf, Double.NaN, inf, inf};
        }
        double amplitude = 0;
        for (double[] d : ref.samples) {
            amplitude = Math.max(amplitude, norm(d, null));
        }
        double worst = 0;
        double worstT = 0;
        double apexWorst = 0;
        for (int s = 0; s < n; s++) {
            double e = norm(samples.get(s), ref.samples.get(s)) / amplitude;
            if (e > worst) {
                worst = e;
                worstT = ref.sampleTimesS[s];
            }
            apexWorst = Math.max(apexWorst, Math.abs(apexSamplesMm[s] - ref.apexSamplesMm[s]));
        }
        double end = norm(samples.get(n - 1), ref.samples.get(n - 1)) / norm(ref.samples.get(n - 1), null);
        return new double[] {end, worst, worstT, Math.abs(apexDescentMm - ref.apexDescentMm), apexWorst};
    }

    /** |a - b| (b may be null: |a|). */
    private static double norm(double[] a, double[] b) {
        double sum = 0;
        for (int k = 0; k < a.length; k++) {
            double d = b == null ? a[k] : a[k] - b[k];
            sum += d * d;
        }
        return Math.sqrt(sum);
    }

    /** CPU time of the calling thread plus the given worker threads, ns. */
    private static long cpuOf(ThreadMXBean mx, long[] workers) {
        long t = mx.getCurrentThreadCpuTime();
        for (long id : workers) {
            long w = mx.getThreadCpuTime(id);
            if (w > 0) {
                t += w;
            }
        }
        return t;
    }
}
