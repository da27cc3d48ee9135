package org.tensim.solver.integrators;

import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.SystemState;
import org.tensim.solver.stability.ButcherTableau;
import org.tensim.solver.stability.LinearStability;

/**
 * Any explicit Runge-Kutta method, driven by its {@link ButcherTableau} (after
 * Hipparchus's {@code RungeKuttaIntegrator}), on the first-order system
 * (x' = v, v' = f / m). Stage i, for the free nodes:
 *
 * <pre>
 *   X_i = x + sum_j (h a_ij) V_j,      V_i = v + sum_j (h a_ij) w F_j      (V_1 = v, X_1 = x)
 *   F_i = f(t + c_i h, X_i, V_i)
 *   x  &lt;- x + (h / D) sum_j beta_j V_j,   v &lt;- v + (h / D) sum_j beta_j w F_j
 * </pre>
 *
 * with w = 1/m and b_j = beta_j / D (integer beta_j). Each stage is one node loop
 * run by {@link ForceModel#nodeLoops()}, so the method runs on as many threads as are
 * installed, to the same bits.
 *
 * <p>The order of the floating-point operations is fixed, and is that of the
 * hand-written loops it replaces (results are unchanged to the last bit): when the
 * non-zero weights are equal, w multiplies the sum of the forces once
 * ({@code (h / D w) (F_1 + F_2)}, Heun); otherwise each force is weighted by
 * {@code beta_j w} (RK4). Nodes with w = 0 (fixed and driven) are not integrated:
 * their stage states are copies and their updates are skipped, which also keeps an
 * infinite force on a fixed node from turning into 0 * inf = NaN. Driven nodes then
 * get their motions at every stage time.
 *
 * <p>Scratch: one position array, one velocity array per later stage and one force
 * array per stage whose force is still needed (a force used only by the next stage
 * shares its array with that stage's), allocated on the first step.
 */
public class ExplicitRungeKutta implements Integrator {
    private final String name;
    private final int order;
    private final ButcherTableau tableau;
    /** Per stage: the stages j with a non-zero a_ij. */
    private final int[][] terms;
    /** Per stage: the integer weight beta_j (b_j = beta_j / D). */
    private final double[] beta;
    /** The stages with a non-zero weight, ascending. */
    private final int[] weighted;
    private final int[] forceSlot;
    private final int slots;
    private final NodeLoops.Body stageBody = this::stageRange;
    private final NodeLoops.Body finalBody = this::finalRange;
    private final double[] scratch = new double[6];
    /** Per stage and term: h a_ij of the current step. */
    private final double[][] coef;
    private double[] xs;
    private double[][] vs;
    private double[][] fs;
    private SystemState s;
    private double h;
    private int stage;

    /**
     * @param name    the registry name
     * @param order   the global order of accuracy on smooth problems (checked by IntegratorOrderTest)
     * @param tableau the method
     */
    public ExplicitRungeKutta(String name, int order, ButcherTableau tableau) {
        this.name = name;
        this.order = order;
        this.tableau = tableau;
        int st = tableau.stages();
        terms = new int[st][];
        beta = new double[st];
        for (int i = 0; i < st; i++) {
            terms[i] = tableau.terms(i);
            beta[i] = tableau.weight(i);
        }
        weighted = java.util.stream.IntStream.range(0, st).filter(j -> beta[j] != 0).toArray();
        forceSlot = new int[st];
        int next = 0;
        for (int j = 0; j < st; j++) {
            forceSlot[j] = j > 0 && deadAfterNextStage(j - 1) ? forceSlot[j - 1] : next++;
        }
        slots = next;
        coef = new double[st][];
        for (int i = 0; i < st; i++) {
            coef[i] = new double[terms[i].length];
        }
    }

    /** Whether F_j is read by stage j + 1 at most: no weight, no later row. */
    private boolean deadAfterNextStage(int j) {
        if (beta[j] != 0) {
            return false;
        }
        for (int i = j + 2; i < terms.length; i++) {
            for (int t : terms[i]) {
                if (t == j) {
                    return false;
                }
            }
        }
        return true;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public int order() {
        return order;
    }

    @Override
    public int forceEvaluationsPerStep() {
        return tableau.stages();
    }

    /** The tableau: its stability polynomial and the same arithmetic on the test oscillator. */
    @Override
    public LinearStability stability() {
        return tableau;
    }

    @Override
    public void step(ForceModel model, double t, double dt) {
        SystemState st = model.state();
        int n3 = 3 * st.nodeCount;
        int stages = tableau.stages();
        if (xs == null || xs.length != n3) {
            xs = new double[n3];
            vs = new double[stages][];
            for (int i = 1; i < stages; i++) {
                vs[i] = new double[n3];
            }
            fs = new double[slots][n3];
        }
        s = st;
        h = dt;
        vs[0] = st.v;
        for (int i = 1; i < stages; i++) {
            for (int term = 0; term < coef[i].length; term++) {
                coef[i][term] = tableau.stepCoefficient(i, term, dt);
            }
        }
        NodeLoops loops = model.nodeLoops();
        model.computeForces(t, st.x, st.v, fs[forceSlot[0]]);
        for (stage = 1; stage < stages; stage++) {
            double ti = tableau.stageTime(stage, t, dt);
            loops.run(st.nodeCount, stageBody);
            st.applyMotions(ti, xs, vs[stage], scratch);
            model.computeForces(ti, xs, vs[stage], fs[forceSlot[stage]]);
        }
        loops.run(st.nodeCount, finalBody);
        st.applyMotions(t + dt, st.x, st.v, scratch);
        vs[0] = null;
        s = null;
    }

    /** X_i and V_i of the current stage for the nodes [lo, hi). */
    private void stageRange(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double[] xo = xs;
        final double[] vo = vs[stage];
        final int[] terms = this.terms[stage];
        final double[] cf = coef[stage];
        if (terms.length == 1) {
            // One term, as in every classic method: X = x + (h a) V_j, V = v + (h a) w F_j.
            final double[] vj = vs[terms[0]];
            final double[] fj = fs[forceSlot[terms[0]]];
            final double c = cf[0];
            for (int i = lo; i < hi; i++) {
                final double w = im[i];
                final boolean free = w != 0;
                for (int k = 3 * i; k < 3 * i + 3; k++) {
                    xo[k] = free ? x[k] + c * vj[k] : x[k];
                    vo[k] = free ? v[k] + c * w * fj[k] : v[k];
                }
            }
            return;
        }
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            final boolean free = w != 0 && terms.length > 0;
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                if (!free) {
                    xo[k] = x[k];
                    vo[k] = v[k];
                    continue;
                }
                double dx = cf[0] * vs[terms[0]][k];
                double dv = cf[0] * w * fs[forceSlot[terms[0]]][k];
                for (int t = 1; t < terms.length; t++) {
                    dx += cf[t] * vs[terms[t]][k];
                    dv += cf[t] * w * fs[forceSlot[terms[t]]][k];
                }
                xo[k] = x[k] + dx;
                vo[k] = v[k] + dv;
            }
        }
    }

    /** The end of the step for the free nodes of [lo, hi): x += (h / D) sum beta V, v += ... w F. */
    private void finalRange(int lo, int hi) {
        if (weighted.length > 4) {
            finalRangeGeneral(lo, hi);
            return;
        }
        // Up to four weighted stages (every classic method): the arrays in locals and the
        // stage count as loop-invariant tests, which the JIT hoists out of the loop.
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double hb = h / tableau.weightDenominator();
        final boolean factored = tableau.equalWeights();
        final int m = weighted.length;
        final double[] va = vs[weighted[0]];
        final double[] fa = fs[forceSlot[weighted[0]]];
        final double ba = beta[weighted[0]];
        final double[] vb = m > 1 ? vs[weighted[1]] : null;
        final double[] fb = m > 1 ? fs[forceSlot[weighted[1]]] : null;
        final double bb = m > 1 ? beta[weighted[1]] : 0;
        final double[] vc = m > 2 ? vs[weighted[2]] : null;
        final double[] fc = m > 2 ? fs[forceSlot[weighted[2]]] : null;
        final double bc = m > 2 ? beta[weighted[2]] : 0;
        final double[] vd = m > 3 ? vs[weighted[3]] : null;
        final double[] fd = m > 3 ? fs[forceSlot[weighted[3]]] : null;
        final double bd = m > 3 ? beta[weighted[3]] : 0;
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                double sx = ba * va[k];
                double sf = factored ? fa[k] : ba * w * fa[k];
                if (m > 1) {
                    sx += bb * vb[k];
                    sf += factored ? fb[k] : bb * w * fb[k];
                }
                if (m > 2) {
                    sx += bc * vc[k];
                    sf += factored ? fc[k] : bc * w * fc[k];
                }
                if (m > 3) {
                    sx += bd * vd[k];
                    sf += factored ? fd[k] : bd * w * fd[k];
                }
                x[k] += hb * sx;
                v[k] += factored ? hb * w * sf : hb * sf;
            }
        }
    }

    /** As {@link #finalRange} for any number of weighted stages. */
    private void finalRangeGeneral(int lo, int hi) {
        final double[] x = s.x;
        final double[] v = s.v;
        final double[] im = s.invMass;
        final double hb = h / tableau.weightDenominator();
        final boolean factored = tableau.equalWeights();
        for (int i = lo; i < hi; i++) {
            final double w = im[i];
            if (w == 0) {
                continue;
            }
            for (int k = 3 * i; k < 3 * i + 3; k++) {
                double sx = 0;
                double sf = 0;
                for (int t = 0; t < weighted.length; t++) {
                    final int j = weighted[t];
                    final double fj = fs[forceSlot[j]][k];
                    final double bv = beta[j] * vs[j][k];
                    final double bf = factored ? fj : beta[j] * w * fj;
                    sx = t == 0 ? bv : sx + bv;
                    sf = t == 0 ? bf : sf + bf;
                }
                x[k] += hb * sx;
                v[k] += factored ? hb * w * sf : hb * sf;
            }
        }
    }
}
