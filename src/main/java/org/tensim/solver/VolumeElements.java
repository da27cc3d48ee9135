package org.tensim.solver;

import java.util.List;
import org.tensim.model.VolumeElement;
import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * The volume elements of a compiled state ({@link VolumeElement}: {@code W = K V (J - 1)^2 / 2} a cell), in flat
 * arrays allocated once: their forces and energy, and for implicit integrators and the critical step their
 * Gauss-Newton stiffness {@code K V b b^T}, {@code b_n = cof(F) g_n} (the exact Hessian at rest, where J = 1; away
 * from it the term {@code K V (J - 1) d cof/dx} is dropped, which keeps it positive semi-definite, as the triangles'
 * tangent drops their compressive stress), with its damping {@code beta K V b b^T}.
 *
 * <p>Forces (N) on node n of an element: {@code f_n = -K V ((J - 1) + beta dJ/dt) b_n}. Allocation-free.
 */
public final class VolumeElements {
    private final int count;
    private final int[] start;
    private final int[] node3;
    private final double[] grad;
    private final double[] kv;
    private final double[] beta;
    private final boolean damped;
    /** b_n = cof(F) g_n at the last {@link #linearise}, 3 a corner. */
    private final double[] b;
    /** Scratch: F, cof(F), dF/dt (the force pass is serial; no allocation per step). */
    private final double[] fm = new double[9];
    private final double[] cof = new double[9];
    private final double[] dv = new double[9];

    /** Compiles {@code elements} (their node ids index the state's nodes). */
    public VolumeElements(List<VolumeElement> elements) {
        count = elements.size();
        start = new int[count + 1];
        for (int e = 0; e < count; e++) {
            start[e + 1] = start[e] + elements.get(e).size();
        }
        int corners = start[count];
        node3 = new int[corners];
        grad = new double[3 * corners];
        kv = new double[count];
        beta = new double[count];
        b = new double[3 * corners];
        boolean anyDamped = false;
        for (int e = 0; e < count; e++) {
            VolumeElement el = elements.get(e);
            kv[e] = el.modulusPa() * el.restVolumeM3();
            beta[e] = el.dampingS();
            anyDamped |= beta[e] > 0;
            for (int c = 0; c < el.size(); c++) {
                int q = start[e] + c;
                node3[q] = 3 * el.node(c);
                for (int a = 0; a < 3; a++) {
                    grad[3 * q + a] = el.gradient(c, a);
                    b[3 * q + a] = el.gradient(c, a);
                }
            }
        }
        damped = anyDamped;
    }

    /** Number of elements. */
    public int count() {
        return count;
    }

    /** Whether any element is damped (its forces then need the velocities). */
    public boolean damped() {
        return damped;
    }

    /** F = sum_n x_n g_n^T of element e at positions px, into f (row-major 3 x 3). */
    private void gradient(int e, double[] px, double[] f) {
        java.util.Arrays.fill(f, 0, 9, 0);
        for (int q = start[e]; q < start[e + 1]; q++) {
            int o = node3[q];
            double gx = grad[3 * q];
            double gy = grad[3 * q + 1];
            double gz = grad[3 * q + 2];
            for (int a = 0; a < 3; a++) {
                double x = px[o + a];
                f[3 * a] += x * gx;
                f[3 * a + 1] += x * gy;
                f[3 * a + 2] += x * gz;
            }
        }
    }

    /** The cofactor matrix of f (dJ/dF) into c (row-major), returning det f. */
    private static double cofactor(double[] f, double[] c) {
        c[0] = f[4] * f[8] - f[5] * f[7];
        c[1] = f[5] * f[6] - f[3] * f[8];
        c[2] = f[3] * f[7] - f[4] * f[6];
        c[3] = f[2] * f[7] - f[1] * f[8];
        c[4] = f[0] * f[8] - f[2] * f[6];
        c[5] = f[1] * f[6] - f[0] * f[7];
        c[6] = f[1] * f[5] - f[2] * f[4];
        c[7] = f[2] * f[3] - f[0] * f[5];
        c[8] = f[0] * f[4] - f[1] * f[3];
        return f[0] * c[0] + f[1] * c[1] + f[2] * c[2];
    }

    /**
     * Adds the elements' forces at positions px (m) to f (N); with velocities pv (m/s, or null for none) their
     * damping too. Allocation-free; not to be called from two threads at once.
     */
    public void forces(double[] px, double[] pv, double[] f) {
        for (int e = 0; e < count; e++) {
            gradient(e, px, fm);
            double j = cofactor(fm, cof);
            double s = j - 1;
            if (pv != null && beta[e] > 0) {
                gradient(e, pv, dv);
                double rate = 0;
                for (int k = 0; k < 9; k++) {
                    rate += cof[k] * dv[k];
                }
                s += beta[e] * rate;
            }
            s *= -kv[e];
            for (int q = start[e]; q < start[e + 1]; q++) {
                int o = node3[q];
                double gx = grad[3 * q];
                double gy = grad[3 * q + 1];
                double gz = grad[3 * q + 2];
                for (int a = 0; a < 3; a++) {
                    f[o + a] += s * (cof[3 * a] * gx + cof[3 * a + 1] * gy + cof[3 * a + 2] * gz);
                }
            }
        }
    }

    /** Energy {@code sum K V (J - 1)^2 / 2} at positions px, J. */
    public double energy(double[] px) {
        double w = 0;
        for (int e = 0; e < count; e++) {
            gradient(e, px, fm);
            double s = cofactor(fm, cof) - 1;
            w += 0.5 * kv[e] * s * s;
        }
        return w;
    }

    /** The volume ratio J of element e at positions px. */
    public double volumeRatio(int e, double[] px) {
        gradient(e, px, fm);
        return cofactor(fm, cof);
    }

    /** Stores {@code b_n = cof(F) g_n} at positions px for the products below. */
    public void linearise(double[] px) {
        for (int e = 0; e < count; e++) {
            gradient(e, px, fm);
            cofactor(fm, cof);
            for (int q = start[e]; q < start[e + 1]; q++) {
                double gx = grad[3 * q];
                double gy = grad[3 * q + 1];
                double gz = grad[3 * q + 2];
                for (int a = 0; a < 3; a++) {
                    b[3 * q + a] = cof[3 * a] * gx + cof[3 * a + 1] * gy + cof[3 * a + 2] * gz;
                }
            }
        }
    }

    /**
     * {@code y += (stiffness K V + damping beta K V) b (b . z)} element by element, full layout: the stiffness times
     * {@code stiffness} plus the damping times {@code damping} (an implicit step's h^2 and h).
     */
    public void multiplyAdd(double[] z, double[] y, double stiffness, double damping) {
        product(b, z, y, null, stiffness, damping);
    }

    /**
     * As {@link #multiplyAdd(double[], double[], double, double)} on compact vectors: {@code offset[i]} is the index
     * of node i's x in z and y, or -1 for a node left out (its z taken as 0, its y not written); null for the full
     * layout.
     */
    public void multiplyAdd(double[] z, double[] y, int[] offset, double stiffness, double damping) {
        product(b, z, y, offset, stiffness, damping);
    }

    private void product(double[] b, double[] z, double[] y, int[] offset, double stiffness, double damping) {
        for (int e = 0; e < count; e++) {
            double dot = 0;
            for (int q = start[e]; q < start[e + 1]; q++) {
                int o = offset == null ? node3[q] : offset[node3[q] / 3];
                if (o >= 0) {
                    dot += b[3 * q] * z[o] + b[3 * q + 1] * z[o + 1] + b[3 * q + 2] * z[o + 2];
                }
            }
            double s = kv[e] * (stiffness + damping * beta[e]) * dot;
            for (int q = start[e]; q < start[e + 1]; q++) {
                int o = offset == null ? node3[q] : offset[node3[q] / 3];
                if (o >= 0) {
                    y[o] += s * b[3 * q];
                    y[o + 1] += s * b[3 * q + 1];
                    y[o + 2] += s * b[3 * q + 2];
                }
            }
        }
    }

    /**
     * The node-pair weights of the rest stiffness for a preconditioning matrix of one scalar a node pair: for
     * each element and corners (m, n), {@code K V g_m . g_n} (the trace of the 3 x 3 block {@code K V g_m g_n^T},
     * as a spring {@code k u u^T} is given k) and the damping {@code beta K V g_m . g_n}, passed to {@code sink}.
     */
    public void restPairs(PairSink sink) {
        for (int e = 0; e < count; e++) {
            for (int p = start[e]; p < start[e + 1]; p++) {
                for (int q = start[e]; q < start[e + 1]; q++) {
                    double gg = grad[3 * p] * grad[3 * q] + grad[3 * p + 1] * grad[3 * q + 1]
                            + grad[3 * p + 2] * grad[3 * q + 2];
                    sink.add(node3[p] / 3, node3[q] / 3, kv[e] * gg, beta[e] * kv[e] * gg);
                }
            }
        }
    }

    /** How many pairs {@link #restPairs} passes: the sum of the elements' squared corner counts. */
    public int restPairCount() {
        int n = 0;
        for (int e = 0; e < count; e++) {
            n += (start[e + 1] - start[e]) * (start[e + 1] - start[e]);
        }
        return n;
    }

    /** Receives {@link #restPairs}: nodes m, n, stiffness weight (N/m) and damping weight (N s/m). */
    public interface PairSink {
        void add(int m, int n, double stiffness, double damping);
    }

    /** diag += (stiffness + damping beta) K V b_n,a^2: the diagonal of {@link #multiplyAdd}'s operator. */
    public void addDiagonal(double[] diag, double stiffness, double damping) {
        for (int e = 0; e < count; e++) {
            double s = kv[e] * (stiffness + damping * beta[e]);
            for (int q = start[e]; q < start[e + 1]; q++) {
                int o = node3[q];
                for (int a = 0; a < 3; a++) {
                    diag[o + a] += s * b[3 * q + a] * b[3 * q + a];
                }
            }
        }
    }

    /**
     * The stiffness at rest, {@code K V g g^T} (the exact Hessian there), as an {@link ExtraStiffness} for the
     * critical step and for small-displacement statics; it does not change with {@link #linearise}.
     */
    public ExtraStiffness restStiffness() {
        return new ExtraStiffness() {
            @Override
            public void multiplyAdd(double[] z, double[] y) {
                product(grad, z, y, null, 1, 0);
            }

            @Override
            public void addGershgorinRows(double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
                gershgorin(grad, mass, free, form, row);
            }
        };
    }

    /** diag += the rest stiffness's diagonal, {@code K V g_n,a^2}. */
    public void addRestDiagonal(double[] diag) {
        for (int e = 0; e < count; e++) {
            for (int q = start[e]; q < start[e + 1]; q++) {
                for (int a = 0; a < 3; a++) {
                    diag[node3[q] + a] += kv[e] * grad[3 * q + a] * grad[3 * q + a];
                }
            }
        }
    }

    /**
     * Gershgorin rows of {@code K V b b^T}: node blocks {@code K V b_m b_n^T} of Frobenius norm
     * {@code K V |b_m| |b_n|}, added as {@link CriticalTimeStep#gershgorin} adds a spring's stiffness.
     */
    private void gershgorin(double[] b, double[] mass, boolean[] free, CriticalTimeStep.Form form, double[] row) {
        for (int e = 0; e < count; e++) {
            for (int p = start[e]; p < start[e + 1]; p++) {
                int na = node3[p] / 3;
                if (!free[na]) {
                    continue;
                }
                double bp = Math.sqrt(b[3 * p] * b[3 * p] + b[3 * p + 1] * b[3 * p + 1] + b[3 * p + 2] * b[3 * p + 2]);
                for (int q = start[e]; q < start[e + 1]; q++) {
                    int nb = node3[q] / 3;
                    double norm = kv[e] * bp * Math.sqrt(b[3 * q] * b[3 * q] + b[3 * q + 1] * b[3 * q + 1]
                            + b[3 * q + 2] * b[3 * q + 2]);
                    if (form == CriticalTimeStep.Form.ROWS) {
                        row[na] += 0.5 * norm;
                    } else if (nb == na) {
                        row[na] += norm / mass[na];
                    } else if (free[nb]) {
                        row[na] += norm / Math.sqrt(mass[na] * mass[nb]);
                    }
                }
            }
        }
    }
}
