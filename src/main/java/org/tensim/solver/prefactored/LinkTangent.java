package org.tensim.solver.prefactored;

import org.tensim.solver.SystemState;

/**
 * The rigid links as the implicit step of stage 1 sees them: each link (a, b) of length L keeps,
 * to first order over the step, the length it will have, so that the step moves the nodes along
 * the links' tangents only and the projection of stage 2 corrects a second-order remainder.
 *
 * <p>Why: with steps far beyond the stiff springs' periods (h w &gt;&gt; 1), an implicit step that
 * ignores the links lets those springs relax completely across them (the prisms' diagonals thin
 * the shell through its rigid columns) before the projection puts the links back; the projected
 * state is not the constrained one, and the step comes to rest off the constrained equilibrium,
 * by an amount that does not fall with h while h w stays large (on a 20-ring material-model
 * diaphragm at end-inspiration: 6 % from RK2 at 0.25 ms, 24-27 % at 1-20 ms). An explicit step at its stable step moves the
 * links' ends by little each step, so its projection does not have this bias.
 *
 * <p>With the new velocity v as unknown and the positions {@code x = x^ + beta v} (the implicit
 * scheme's), each link's length {@code |x_b - x_a| = L} is linearised at every Newton iterate:
 *
 * <pre>
 *   (dv_b - dv_a) . n = (L - |d|) / beta,   d = x_b - x_a,   n = d / |d|
 * </pre>
 *
 * with x at the iterate for a free end and at its prescribed position at t + h for a fixed or
 * driven one (whose dv is 0). The iterate's velocities are first shifted onto these constraints
 * (mass-weighted, {@link #constrain}), and the Newton increment is then kept in their tangent space
 * by the mass-weighted (M-orthogonal) projector {@code P = I - M^-1 N (N^T M^-1 N)^-1 N^T}, N
 * holding the constraints' gradients: a link's correction moves its ends along n in inverse
 * proportion to their masses, as stage 2 does, so it keeps the momentum. The residual enters as
 * {@code P^T g = M P M^-1 g}: the force along the links is the constraint's, the tangential
 * balance is solved. So Newton converges on the links' lengths too, and stage 2 corrects only what
 * the last iteration leaves (second order in the step). Linearised once at x^ for the whole step
 * instead, the links let a column whose ends are both tied to the ribs spin by 0.5 mm a step (at
 * 0.23 ms on a 14-ring diaphragm). Disjoint links (each node in at most one, as the diaphragm's
 * columns) are projected exactly in one sweep of the links; for links that share nodes the
 * multipliers are solved for by conjugate gradient on the links' Schur complement.
 * Allocation-free after construction.
 */
final class LinkTangent {
    /** Relative residual of the multipliers' CG when links share nodes. */
    private static final double SOLVE_TOLERANCE = 1e-14;

    private final int count; // links with at least one free end
    private final int[] endA; // per link: 3 x compact index of end a, -1 when fixed or driven
    private final int[] endB;
    private final int[] nodeA; // per link: node ids
    private final int[] nodeB;
    private final double[] length;
    private final double[] wA; // inverse masses, 0 for a fixed or driven end
    private final double[] wB;
    private final double[] dir; // per link: n
    private final double[] target; // per link: (L - |d|) / beta, m/s
    private final double[] invMass; // per free node (compact), 1/kg
    private final double[] shift; // compact scratch: the velocity change of constrain()
    private final double[] lambda; // links that share nodes: multipliers and their CG's vectors
    private final double[] res;
    private final double[] cgDir;
    private final double[] cgProduct;
    private final double[] temp; // compact
    private final boolean disjoint;

    LinkTangent(SystemState s, int[] freeIndex, int[] freeNodes) {
        int n = 0;
        for (int i = 0; i < s.linkCount(); i++) {
            if (freeIndex[s.linkA[i]] >= 0 || freeIndex[s.linkB[i]] >= 0) {
                n++;
            }
        }
        count = n;
        endA = new int[n];
        endB = new int[n];
        nodeA = new int[n];
        nodeB = new int[n];
        length = new double[n];
        wA = new double[n];
        wB = new double[n];
        dir = new double[3 * n];
        target = new double[n];
        int[] uses = new int[s.nodeCount];
        boolean shared = false;
        int j = 0;
        for (int i = 0; i < s.linkCount(); i++) {
            int a = s.linkA[i];
            int b = s.linkB[i];
            if (freeIndex[a] < 0 && freeIndex[b] < 0) {
                continue;
            }
            nodeA[j] = a;
            nodeB[j] = b;
            endA[j] = freeIndex[a] < 0 ? -1 : 3 * freeIndex[a];
            endB[j] = freeIndex[b] < 0 ? -1 : 3 * freeIndex[b];
            wA[j] = freeIndex[a] < 0 ? 0 : s.invMass[a];
            wB[j] = freeIndex[b] < 0 ? 0 : s.invMass[b];
            length[j] = s.linkL[i];
            uses[a]++;
            uses[b]++;
            shared |= uses[a] > 1 || uses[b] > 1;
            j++;
        }
        disjoint = !shared;
        shift = new double[3 * freeNodes.length];
        int sharing = disjoint ? 0 : n;
        lambda = new double[sharing];
        res = new double[sharing];
        cgDir = new double[sharing];
        cgProduct = new double[sharing];
        temp = new double[disjoint ? 0 : 3 * freeNodes.length];
        invMass = new double[freeNodes.length];
        for (int k = 0; k < freeNodes.length; k++) {
            invMass[k] = s.invMass[freeNodes[k]];
        }
    }

    /** Whether there is any link to keep. */
    boolean isEmpty() {
        return count == 0;
    }

    /**
     * Linearises the links at the positions {@code x} (full layout: free nodes at the iterate
     * x^ + beta v, fixed and driven ones at t + h): directions, and targets that bring each link to
     * its length to first order.
     *
     * @param beta the implicit scheme's weight of the new velocity in the positions, s
     */
    void linearise(double[] x, double beta) {
        for (int i = 0; i < count; i++) {
            final int a = 3 * nodeA[i];
            final int b = 3 * nodeB[i];
            final double dx = x[b] - x[a];
            final double dy = x[b + 1] - x[a + 1];
            final double dz = x[b + 2] - x[a + 2];
            final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            final double inv = len > 0 ? 1 / len : 0; // coincident ends: no direction, left to stage 2
            dir[3 * i] = dx * inv;
            dir[3 * i + 1] = dy * inv;
            dir[3 * i + 2] = dz * inv;
            target[i] = len > 0 ? (length[i] - len) / beta : 0;
        }
    }

    /**
     * Shifts the free nodes' velocities v (full layout) by the mass-weighted change that meets the
     * linearised constraints: {@code (dv_b - dv_a) . n = target}, the change of v, not v itself,
     * since the positions the targets were measured at already hold v.
     */
    void constrain(double[] v) {
        if (count == 0) {
            return;
        }
        java.util.Arrays.fill(shift, 0);
        sweep(shift, true);
        for (int i = 0; i < count; i++) {
            if (endA[i] >= 0) {
                addShift(v, 3 * nodeA[i], endA[i]);
            }
            if (endB[i] >= 0) {
                addShift(v, 3 * nodeB[i], endB[i]);
            }
        }
    }

    private void addShift(double[] v, int full, int compact) {
        v[full] += shift[compact];
        v[full + 1] += shift[compact + 1];
        v[full + 2] += shift[compact + 2];
        shift[compact] = 0; // a node in several links is shifted once
        shift[compact + 1] = 0;
        shift[compact + 2] = 0;
    }

    /** u = P u: the compact increment u into the constraints' tangent space. */
    void project(double[] u) {
        sweep(u, false);
    }

    /** r = P^T r = M P M^-1 r: a compact force-like vector (a residual) seen in the tangent space. */
    void projectDual(double[] r) {
        if (count == 0) {
            return;
        }
        for (int k = 0; k < invMass.length; k++) {
            final double w = invMass[k];
            r[3 * k] *= w;
            r[3 * k + 1] *= w;
            r[3 * k + 2] *= w;
        }
        sweep(r, false);
        for (int k = 0; k < invMass.length; k++) {
            final double m = 1 / invMass[k];
            r[3 * k] *= m;
            r[3 * k + 1] *= m;
            r[3 * k + 2] *= m;
        }
    }

    private void sweep(double[] u, boolean affine) {
        if (disjoint) {
            for (int i = 0; i < count; i++) {
                correct(u, i, affine);
            }
        } else {
            projectShared(u, affine);
        }
    }

    /**
     * The projection when links share nodes: the multipliers solve {@code (N^T M^-1 N) lambda = N^T u - c}
     * by conjugate gradient (the matrix is the links' Schur complement, symmetric positive semi-definite;
     * Gauss-Seidel sweeps converge at 0.9 a sweep on a rigid triangle), then {@code u -= M^-1 N lambda}.
     */
    private void projectShared(double[] u, boolean affine) {
        double rr = 0;
        for (int i = 0; i < count; i++) {
            lambda[i] = 0;
            res[i] = rate(u, i) - (affine ? target[i] : 0);
            cgDir[i] = res[i];
            rr += res[i] * res[i];
        }
        final double stop = SOLVE_TOLERANCE * SOLVE_TOLERANCE * rr;
        for (int it = 0; it < 2 * count + 10 && rr > stop; it++) {
            java.util.Arrays.fill(temp, 0);
            shift(temp, cgDir, 1);
            double pq = 0;
            for (int i = 0; i < count; i++) {
                cgProduct[i] = -rate(temp, i); // (N^T M^-1 N) p, as shift() moves against N
                pq += cgDir[i] * cgProduct[i];
            }
            if (!(pq > 0)) {
                break;
            }
            final double alpha = rr / pq;
            double rrNew = 0;
            for (int i = 0; i < count; i++) {
                lambda[i] += alpha * cgDir[i];
                res[i] -= alpha * cgProduct[i];
                rrNew += res[i] * res[i];
            }
            final double b = rrNew / rr;
            rr = rrNew;
            for (int i = 0; i < count; i++) {
                cgDir[i] = res[i] + b * cgDir[i];
            }
        }
        shift(u, lambda, 1);
    }

    /** u -= s M^-1 N lambda: each link moves its ends along n, in inverse proportion to their masses. */
    private void shift(double[] u, double[] lam, double sign) {
        for (int i = 0; i < count; i++) {
            final double l = sign * lam[i];
            final int a = endA[i];
            final int b = endB[i];
            for (int c = 0; c < 3; c++) {
                final double n = dir[3 * i + c];
                if (a >= 0) {
                    u[a + c] += wA[i] * l * n;
                }
                if (b >= 0) {
                    u[b + c] -= wB[i] * l * n;
                }
            }
        }
    }

    /** (u_b - u_a) . n of link i, fixed and driven ends counting 0. */
    private double rate(double[] u, int i) {
        final int a = endA[i];
        final int b = endB[i];
        double r = 0;
        for (int c = 0; c < 3; c++) {
            final double n = dir[3 * i + c];
            r += ((b >= 0 ? u[b + c] : 0) - (a >= 0 ? u[a + c] : 0)) * n;
        }
        return r;
    }

    /** One link's M-orthogonal correction of u (exact when no other link shares its nodes). */
    private void correct(double[] u, int i, boolean affine) {
        final double wsum = wA[i] + wB[i];
        final double violation = rate(u, i) - (affine ? target[i] : 0);
        if (wsum > 0 && violation != 0) {
            final double mu = violation / wsum;
            final int a = endA[i];
            final int b = endB[i];
            for (int c = 0; c < 3; c++) {
                final double n = dir[3 * i + c];
                if (a >= 0) {
                    u[a + c] += wA[i] * mu * n;
                }
                if (b >= 0) {
                    u[b + c] -= wB[i] * mu * n;
                }
            }
        }
    }
}
