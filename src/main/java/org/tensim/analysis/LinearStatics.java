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
import org.tensim.solver.ShearStiffness;
import org.tensim.solver.SystemState;
import org.tensim.solver.TriangleTangent;

/**
 * Small-displacement statics of a spring network about its rest state: solves {@code K u = f}
 * with Hipparchus' conjugate gradients (Jacobi preconditioner), K applied spring by spring,
 * {@code K_ij = -k n n^T} for a spring of stiffness k along the unit vector n between its nodes
 * (no prestress: every spring at its rest length), and the membrane triangles' linear
 * constant-strain stiffness ({@link TriangleTangent} at rest) and the transverse shear elements'
 * {@code k grad g grad g^T} ({@link ShearStiffness} at rest) and the volume elements' {@code K V g g^T}
 * ({@code VolumeElements#restStiffness}). Fixed degrees of freedom have u = 0.
 * Rigid links (disjoint) are kept to first order, {@code n . (u_b - u_a) = 0}, by tying the
 * component of u_b along the link's direction n to u_a's: CG runs on {@code T^T K T} with
 * {@code u = T z}.
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
        Ties ties = new Ties(t, fixed);
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
        SystemState compiled = SystemState.compile(t);
        TriangleTangent triangles = t.triangles().isEmpty() ? null : new TriangleTangent(compiled);
        if (triangles != null) {
            triangles.addDiagonal(diag, 1, 0);
        }
        ShearStiffness shears = new ShearStiffness(compiled.shears, compiled.x0);
        shears.addDiagonal(diag, 1);
        compiled.volumes.addRestDiagonal(diag);
        org.tensim.solver.stability.ExtraStiffness volumes = compiled.volumes.restStiffness();
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
                double[] z = v.toArray();
                double[] x = ties.expand(z);
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
                    x[i] = fixed[i] ? 0 : x[i];
                }
                if (triangles != null) {
                    triangles.multiplyAdd(x, y, null);
                }
                shears.multiplyAdd(x, y, null, 1);
                volumes.multiplyAdd(x, y);
                ties.reduce(y, z);
                for (int i = 0; i < n; i++) {
                    if (fixed[i]) {
                        y[i] = z[i];
                    }
                }
                return new ArrayRealVector(y, false);
            }
        };
        double[] rhs = forceN.clone();
        for (int i = 0; i < n; i++) {
            rhs[i] = fixed[i] ? 0 : rhs[i];
        }
        ties.reduce(rhs, new double[n]);
        int cap = 20 * n + 1000;
        IterationManager im = new IterationManager(cap);
        ConjugateGradient cg = new ConjugateGradient(im, tolerance, false);
        RealVector u = cg.solve(k, new JacobiPreconditioner(diag, false), new ArrayRealVector(rhs, false));
        return new Solution(ties.expand(u.toArray()), im.getIterations());
    }

    /** The rigid links as ties: u = T z and T^T y, in place of the links' lower ends' components along n. */
    private static final class Ties {
        private final int[] a;
        private final int[] b;
        private final double[] dir;

        Ties(Topology t, boolean[] fixed) {
            int m = t.rigidLinks().size();
            a = new int[m];
            b = new int[m];
            dir = new double[3 * m];
            boolean[] used = new boolean[t.nodeCount()];
            for (int i = 0; i < m; i++) {
                a[i] = t.rigidLinks().get(i).a();
                b[i] = t.rigidLinks().get(i).b();
                if (used[a[i]] || used[b[i]]) {
                    throw new IllegalArgumentException("rigid link " + i + " shares a node with another link; the "
                            + "statics solver needs disjoint links");
                }
                used[a[i]] = true;
                used[b[i]] = true;
                org.tensim.model.Vec3 d = t.node(b[i]).position().minus(t.node(a[i]).position()).normalized();
                dir[3 * i] = d.x();
                dir[3 * i + 1] = d.y();
                dir[3 * i + 2] = d.z();
                for (int k = 0; k < 3; k++) {
                    if (fixed[3 * b[i] + k] && !fixed[3 * a[i] + k]) {
                        throw new IllegalArgumentException("node " + b[i] + " is fixed but its link's other end " + a[i]
                                + " is not: fix the link's first node");
                    }
                }
            }
        }

        /** x = T z: the lower ends take the upper ends' components along the links. */
        double[] expand(double[] z) {
            double[] x = z.clone();
            for (int i = 0; i < a.length; i++) {
                double s = 0;
                for (int k = 0; k < 3; k++) {
                    s += dir[3 * i + k] * (z[3 * a[i] + k] - z[3 * b[i] + k]);
                }
                for (int k = 0; k < 3; k++) {
                    x[3 * b[i] + k] += dir[3 * i + k] * s;
                }
            }
            return x;
        }

        /** y = T^T y, plus the identity on each tied-away direction (z's) so that the operator stays definite. */
        void reduce(double[] y, double[] z) {
            for (int i = 0; i < a.length; i++) {
                double s = 0;
                double dead = 0;
                for (int k = 0; k < 3; k++) {
                    s += dir[3 * i + k] * y[3 * b[i] + k];
                    dead += dir[3 * i + k] * z[3 * b[i] + k];
                }
                for (int k = 0; k < 3; k++) {
                    y[3 * a[i] + k] += dir[3 * i + k] * s;
                    y[3 * b[i] + k] += dir[3 * i + k] * (dead - s);
                }
            }
        }
    }

    private static double dof(double[] x, boolean[] fixed, int i) {
        return fixed[i] ? 0 : x[i];
    }
}
