package org.tensim.analysis;

import java.util.List;
import org.hipparchus.linear.ArrayRealVector;
import org.hipparchus.linear.ConjugateGradient;
import org.hipparchus.linear.JacobiPreconditioner;
import org.hipparchus.linear.RealLinearOperator;
import org.hipparchus.linear.RealVector;
import org.hipparchus.util.IterationManager;
import org.tensim.model.Spring;
import org.tensim.model.Topology;

/**
 * Small-displacement statics of a spring network about its rest state: solves {@code K u = f}
 * with Hipparchus' conjugate gradients (Jacobi preconditioner), K applied spring by spring,
 * {@code K_ij = -k n n^T} for a spring of stiffness k along the unit vector n between its nodes
 * (no prestress: every spring at its rest length). Fixed degrees of freedom have u = 0.
 */
public final class LinearStatics {
    /**
     * @param displacementM     u, 3 per node, m
     * @param iterations        CG iterations made
     */
    public record Solution(double[] displacementM, int iterations) {
    }

    private LinearStatics() {
    }

    /**
     * Solves for the displacements under {@code forceN} (3 per node, N).
     *
     * @param fixed     fixed degrees of freedom, 3 per node
     * @param tolerance CG stops when the residual is below this fraction of |f|
     * @throws IllegalStateException naming the iteration cap when CG does not converge
     */
    public static Solution solve(Topology t, boolean[] fixed, double[] forceN, double tolerance) {
        int n = 3 * t.nodeCount();
        List<Spring> springs = t.springs();
        int m = springs.size();
        int[] a = new int[m];
        int[] b = new int[m];
        double[] kn = new double[6 * m]; // k n_x n_x, k n_x n_y, k n_x n_z, k n_y n_y, k n_y n_z, k n_z n_z
        double[] diag = new double[n];
        for (int s = 0; s < m; s++) {
            Spring sp = springs.get(s);
            a[s] = sp.a();
            b[s] = sp.b();
            double[] d = {t.node(b[s]).position().x() - t.node(a[s]).position().x(),
                t.node(b[s]).position().y() - t.node(a[s]).position().y(),
                t.node(b[s]).position().z() - t.node(a[s]).position().z()};
            double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            int q = 0;
            for (int i = 0; i < 3; i++) {
                for (int j = i; j < 3; j++) {
                    kn[6 * s + q++] = sp.stiffness() * d[i] * d[j] / len2;
                }
                double kii = sp.stiffness() * d[i] * d[i] / len2;
                diag[3 * a[s] + i] += kii;
                diag[3 * b[s] + i] += kii;
            }
        }
        for (int i = 0; i < n; i++) {
            if (fixed[i] || diag[i] == 0) {
                diag[i] = 1;
            }
        }
        RealLinearOperator k = new RealLinearOperator() {
            @Override
            public int getRowDimension() {
                return n;
            }

            @Override
            public int getColumnDimension() {
                return n;
            }

            @Override
            public RealVector operate(RealVector v) {
                double[] x = v.toArray();
                double[] y = new double[n];
                for (int s = 0; s < m; s++) {
                    double dx = dof(x, fixed, 3 * b[s]) - dof(x, fixed, 3 * a[s]);
                    double dy = dof(x, fixed, 3 * b[s] + 1) - dof(x, fixed, 3 * a[s] + 1);
                    double dz = dof(x, fixed, 3 * b[s] + 2) - dof(x, fixed, 3 * a[s] + 2);
                    int o = 6 * s;
                    double fx = kn[o] * dx + kn[o + 1] * dy + kn[o + 2] * dz;
                    double fy = kn[o + 1] * dx + kn[o + 3] * dy + kn[o + 4] * dz;
                    double fz = kn[o + 2] * dx + kn[o + 4] * dy + kn[o + 5] * dz;
                    y[3 * a[s]] -= fx;
                    y[3 * a[s] + 1] -= fy;
                    y[3 * a[s] + 2] -= fz;
                    y[3 * b[s]] += fx;
                    y[3 * b[s] + 1] += fy;
                    y[3 * b[s] + 2] += fz;
                }
                for (int i = 0; i < n; i++) {
                    if (fixed[i]) {
                        y[i] = x[i];
                    }
                }
                return new ArrayRealVector(y, false);
            }
        };
        double[] rhs = forceN.clone();
        for (int i = 0; i < n; i++) {
            rhs[i] = fixed[i] ? 0 : rhs[i];
        }
        int cap = 20 * n + 1000;
        IterationManager im = new IterationManager(cap);
        ConjugateGradient cg = new ConjugateGradient(im, tolerance, false);
        RealVector u = cg.solve(k, new JacobiPreconditioner(diag, false), new ArrayRealVector(rhs, false));
        return new Solution(u.toArray(), im.getIterations());
    }

    private static double dof(double[] x, boolean[] fixed, int i) {
        return fixed[i] ? 0 : x[i];
    }
}
