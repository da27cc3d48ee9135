package org.tensim.calibration;

import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.hipparchus.optim.InitialGuess;
import org.hipparchus.optim.MaxEval;
import org.hipparchus.optim.PointValuePair;
import org.hipparchus.optim.SimpleBounds;
import org.hipparchus.optim.SimplePointChecker;
import org.hipparchus.optim.nonlinear.scalar.GoalType;
import org.hipparchus.optim.nonlinear.scalar.ObjectiveFunction;
import org.hipparchus.optim.nonlinear.scalar.noderiv.CMAESOptimizer;
import org.hipparchus.random.Well19937c;
import org.tensim.sweep.Point;
import org.tensim.sweep.PointResult;
import org.tensim.sweep.SweepEngine;

/**
 * Fits the spec's free parameters with Hipparchus's {@link CMAESOptimizer}, every generation's
 * candidates evaluated at once through a sweep engine (all local cores, or Spark).
 *
 * <p>Hipparchus's CMA-ES asks for one objective value at a time, but the candidates of a
 * generation are all drawn from the strategy's state before any of them is scored, and its
 * run is a deterministic function of its seed and of the values it is given. So the
 * optimiser is run, from the start, with a memo of the values known so far: a candidate not
 * in the memo is noted and given a placeholder, and at the end of its generation (every
 * lambda-th request; the first request is the start point) the run is abandoned before the
 * placeholders are used. The noted candidates are then evaluated together on the engine and
 * the optimiser is run again, replaying the known values exactly, until it finishes with every
 * value real. The strategy's own arithmetic is microseconds per replay; runs are seconds.
 *
 * <p>The objective is the sum over targets of weight x sum of squared residuals
 * ({@link Target}). A candidate that diverged, was refused, or did not reach a target's phase
 * scores {@link #PENALTY}, above any real score: it ranks last and never stops the fit.
 * Parameters are scaled to [0, 1] over their bounds, so that one step size fits all.
 */
public final class Calibrator {
    /** Score of a candidate that gave no usable result. */
    public static final double PENALTY = 1e12;

    /**
     * One evaluated candidate.
     *
     * @param generation CMA-ES generation (0: the start point)
     * @param fractions  the candidate as the optimiser asked for it: (value - min) / (max - min)
     * @param values     parameter values, in the spec's order and units
     * @param fitness    objective (PENALTY when unusable)
     * @param result     the run's result
     */
    public record Evaluation(int generation, double[] fractions, double[] values, double fitness, PointResult result) {
    }

    /**
     * Progress after one generation.
     *
     * @param generation  generation number (1 includes the start point)
     * @param evaluations runs so far
     * @param best        best fitness of this generation's new runs
     * @param bestSoFar   best fitness so far
     * @param values      parameters of the best so far
     * @param wallS       wall time so far, s
     */
    public record Generation(int generation, int evaluations, double best, double bestSoFar, double[] values,
            double wallS) {
    }

    /** Receives every evaluation as it finishes (e.g. to append it to a file). */
    @FunctionalInterface
    public interface Listener {
        void evaluated(Evaluation e) throws IOException;
    }

    /** What a calibration found. */
    public record Outcome(Evaluation best, List<Evaluation> evaluations, List<Generation> history, double wallS) {
    }

    /** Thrown through the optimiser when a generation has candidates still to evaluate. */
    private static final class Pending extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Pending() {
            super(null, null, false, false);
        }
    }

    private Calibrator() {
    }

    /** The objective of a run: weighted sum of squared residuals, or {@link #PENALTY}. */
    public static double fitness(CalibrationSpec spec, PointResult r) {
        if (!r.ok()) {
            return PENALTY;
        }
        double f = 0;
        for (Target t : spec.targets()) {
            for (double x : t.residuals(r)) {
                if (!Double.isFinite(x)) {
                    return PENALTY;
                }
                f += t.weight() * x * x;
            }
        }
        return f;
    }

    /** Runs the calibration on the engine. */
    public static Outcome run(CalibrationSpec spec, SweepEngine engine, Listener listener, PrintStream log)
            throws IOException, InterruptedException {
        int d = spec.free().size();
        CalibrationSpec.Optimizer o = spec.optimizer();
        Map<List<Double>, Double> memo = new HashMap<>();
        List<Evaluation> all = new ArrayList<>();
        List<Generation> history = new ArrayList<>();
        double[] lo = new double[d];
        double[] hi = new double[d];
        double[] start = new double[d];
        double[] sigma = new double[d];
        for (int i = 0; i < d; i++) {
            hi[i] = 1;
            start[i] = spec.free().get(i).fraction(spec.free().get(i).start());
            sigma[i] = o.sigma();
        }
        long t0 = System.nanoTime();
        Evaluation best = null;
        int generation = 0;
        while (true) {
            List<double[]> pending = new ArrayList<>();
            int[] calls = {0};
            CMAESOptimizer cmaes = new CMAESOptimizer(o.generations(), o.stopFitness(), true, 0, 0,
                    new Well19937c(o.seed()), false, new SimplePointChecker<PointValuePair>(0, o.tolerance()));
            try {
                cmaes.optimize(new MaxEval(Integer.MAX_VALUE), GoalType.MINIMIZE, new InitialGuess(start),
                        new SimpleBounds(lo, hi), new CMAESOptimizer.Sigma(sigma),
                        new CMAESOptimizer.PopulationSize(o.population()), new ObjectiveFunction(u -> {
                            int c = calls[0]++;
                            Double v = memo.get(key(u));
                            if (v == null) {
                                pending.add(u.clone());
                            }
                            if (!pending.isEmpty() && c > 0 && c % o.population() == 0) {
                                throw new Pending();
                            }
                            return v == null ? 0 : v;
                        }));
                break; // every value the optimiser used was real
            } catch (Pending p) {
                generation++;
                double genBest = Double.POSITIVE_INFINITY;
                for (Evaluation e : evaluate(spec, engine, pending, all.size(), generation, listener)) {
                    memo.put(key(e.fractions()), e.fitness());
                    all.add(e);
                    genBest = Math.min(genBest, e.fitness());
                    if (best == null || e.fitness() < best.fitness()) {
                        best = e;
                    }
                }
                double wall = (System.nanoTime() - t0) / 1e9;
                history.add(new Generation(generation, all.size(), genBest, best.fitness(), best.values(), wall));
                if (log != null) {
                    log.printf(java.util.Locale.ROOT, "generation %d: %d runs, best %.6g (so far %.6g at %s), %.1f s%n",
                            generation, all.size(), genBest, best.fitness(), Arrays.toString(best.values()), wall);
                }
            }
        }
        return new Outcome(best, all, history, (System.nanoTime() - t0) / 1e9);
    }

    private static List<Evaluation> evaluate(CalibrationSpec spec, SweepEngine engine, List<double[]> us, int firstId,
            int generation, Listener listener) throws IOException, InterruptedException {
        // The same candidate may be requested twice before it is known (e.g. clipped to a bound): run it once.
        Map<List<Double>, double[]> unique = new java.util.LinkedHashMap<>();
        for (double[] u : us) {
            unique.putIfAbsent(key(u), u);
        }
        List<Point> points = new ArrayList<>();
        Map<Integer, double[]> fractions = new HashMap<>();
        int id = firstId;
        for (double[] u : unique.values()) {
            fractions.put(id, u);
            double[] v = new double[u.length];
            for (int i = 0; i < u.length; i++) {
                v[i] = spec.free().get(i).value(u[i]);
            }
            points.add(new Point(id++, v));
        }
        List<Evaluation> out = new ArrayList<>();
        engine.run(spec.setup(), spec.names(), points, r -> {
            int label = generation == 1 && r.id() == firstId ? 0 : generation; // the start point comes first
            Evaluation e = new Evaluation(label, fractions.get(r.id()), r.values(), fitness(spec, r), r);
            out.add(e);
            if (listener != null) {
                listener.evaluated(e);
            }
        });
        out.sort(java.util.Comparator.comparingInt(e -> e.result().id()));
        return out;
    }

    private static List<Double> key(double[] u) {
        List<Double> k = new ArrayList<>(u.length);
        for (double x : u) {
            k.add(x);
        }
        return k;
    }
}
