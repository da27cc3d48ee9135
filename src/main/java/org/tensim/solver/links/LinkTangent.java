package org.tensim.solver.links;

import org.tensim.solver.SpringKernels;
import org.tensim.solver.SystemState;

/**
 * The rigid links as an implicit step of stage 1 sees them: each link (a, b) of length L keeps,
 * to first order over the step, the length it will have, so that the step moves the nodes along
 * the links' tangents only and the projection of stage 2 corrects a second-order remainder. Used by
 * BDF2 ({@code org.tensim.solver.prefactored}, at every Newton iterate) and implicit Euler
 * ({@code org.tensim.solver.integrators}, once per step).
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
 * scheme's), each link's length {@code |x_b - x_a| = L} is linearised at positions x the caller
 * chooses (BDF2: every Newton iterate; implicit Euler: the start of the step predicted to its end):
 *
 * <pre>
 *   (dv_b - dv_a) . n = (L - |d|) / beta,   d = x_b - x_a,   n = d / |d|
 * </pre>
 *
 * with x at the iterate for a free end and at its prescribed position at t + h for a fixed or
 * driven one (whose dv is 0). The iterate's velocities are first shifted onto these constraints
 * (mass-weighted, {@link #constrain}, or {@link #constrainIncrement} for an increment), and the
 * solver's increments are then kept in their tangent space
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
 *
 * <p>Vectors: positions and velocities ({@link #linearise}, {@link #constrain}) are in the full
 * layout (3 per node, node order); the solver's vectors ({@link #project}, {@link #projectDual},
 * {@link #constrainIncrement}) are in its own layout, given by a slot per node: node i's
 * components at {@code 3 slot[i] .. 3 slot[i] + 2}, slot -1 for a node that does not move within
 * the step (fixed or driven). BDF2 uses compact free-node vectors, implicit Euler the full layout
 * ({@link #fullLayout}), where the slots of fixed and driven nodes are left untouched.
 * Allocation-free after construction.
 */
public final class LinkTangent {
    /** Relative residual of the multipliers' CG when links share nodes. */
    private static final double SOLVE_TOLERANCE = 1e-14;

    private final int count; // links with at least one free end
    private final int[] endA; // per link: 3 x slot of end a, -1 when fixed or driven
    private final int[] endB;
    private final int[] nodeA; // per link: node ids
    private final int[] nodeB;
    private final double[] length;
    private final double[] wA; // inverse masses, 0 for a fixed or driven end
    private final double[] wB;
    private final double[] dir; // per link: n
    private final double[] target; // per link: (L - |d|) / beta, m/s
    private final double[] invMass; // per slot, 1/kg; 0 for a slot of no free node
    private final double[] change; // solver layout scratch: the velocity change of constrain()
    private final double[] lambda; // links that share nodes: multipliers and their CG's vectors
    private final double[] res;
    private final double[] cgDir;
    private final double[] cgProduct;
    private final double[] temp; // solver layout
    private final boolean disjoint;

    /**
     * The links with at least one free end (a node of nonzero inverse mass that has a slot).
     *
     * @param s     the compiled system (links, masses)
     * @param slot  per node: its place in the solver's vectors (in nodes, 3 components each), or -1
     *              for a node the step does not move (fixed or driven)
     * @param slots the solver's vectors' length in nodes (their arrays hold 3 x slots values)
     * @throws IllegalArgumentException if slot does not have one entry per node, or a slot is out of range
     */
    public LinkTangent(SystemState s, int[] slot, int slots) {
        if (slot.length != s.nodeCount) {
            throw new IllegalArgumentException("link tangent: " + slot.length + " slots given for "
                    + s.nodeCount + " nodes (expected one per node)");
        }
        invMass = new double[slots];
        for (int i = 0; i < s.nodeCount; i++) {
            if (slot[i] >= slots || slot[i] < -1) {
                throw new IllegalArgumentException("link tangent: node " + i + " has slot " + slot[i]
                        + " (expected -1 or 0.." + (slots - 1) + ")");
            }
            if (slot[i] >= 0) {
                invMass[slot[i]] = s.invMass[i];
            }
        }
        int n = 0;
        for (int i = 0; i < s.linkCount(); i++) {
            if (moves(s, slot, s.linkA[i]) || moves(s, slot, s.linkB[i])) {
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
            boolean ma = moves(s, slot, a);
            boolean mb = moves(s, slot, b);
            if (!ma && !mb) {
                continue;
            }
            nodeA[j] = a;
            nodeB[j] = b;
            endA[j] = ma ? 3 * slot[a] : -1;
            endB[j] = mb ? 3 * slot[b] : -1;
            wA[j] = ma ? s.invMass[a] : 0;
            wB[j] = mb ? s.invMass[b] : 0;
            length[j] = s.linkL[i];
            uses[a]++;
            uses[b]++;
            shared |= uses[a] > 1 || uses[b] > 1;
            j++;
        }
        disjoint = !shared;
        change = new double[3 * slots];
        int sharing = disjoint ? 0 : n;
        lambda = new double[sharing];
        res = new double[sharing];
        cgDir = new double[sharing];
        cgProduct = new double[sharing];
        temp = new double[disjoint ? 0 : 3 * slots];
    }

    /** The links of s for solver vectors in the full layout (slot = node; fixed and driven nodes have none). */
    public static LinkTangent fullLayout(SystemState s) {
        int[] slot = new int[s.nodeCount];
        for (int i = 0; i < s.nodeCount; i++) {
            slot[i] = s.invMass[i] != 0 ? i : -1;
        }
        return new LinkTangent(s, slot, s.nodeCount);
    }

    private static boolean moves(SystemState s, int[] slot, int node) {
        return slot[node] >= 0 && s.invMass[node] != 0;
    }

    /** Whether there is any link to keep. */
    public boolean isEmpty() {
        return count == 0;
    }

    /**
     * Linearises the links at the positions {@code x} (full layout: free nodes at the iterate
     * x^ + beta v, fixed and driven ones at t + h): directions, and targets that bring each link to
     * its length to first order.
     *
     * @param x    positions, m, full layout (3 per node)
     * @param beta the implicit scheme's weight of the new velocity in the positions, s (&gt; 0)
     */
    public void linearise(double[] x, double beta) {
        for (int i = 0; i < count; i++) {
            final int a = 3 * nodeA[i];
            final int b = 3 * nodeB[i];
            // Coincident ends: no direction (zero), left to stage 2.
            final double len = SpringKernels.direction(x, a, b, dir, 3 * i);
            target[i] = len > 0 ? (length[i] - len) / beta : 0;
        }
    }

    /**
     * Shifts the free nodes' velocities v (full layout) by the mass-weighted change that meets the
     * linearised constraints: {@code (dv_b - dv_a) . n = target}, the change of v, not v itself,
     * since the positions the targets were measured at already hold v.
     */
    public void constrain(double[] v) {
        if (count == 0) {
            return;
        }
        java.util.Arrays.fill(change, 0);
        sweep(change, true);
        for (int i = 0; i < count; i++) {
            if (endA[i] >= 0) {
                addChange(v, 3 * nodeA[i], endA[i]);
            }
            if (endB[i] >= 0) {
                addChange(v, 3 * nodeB[i], endB[i]);
            }
        }
    }

    private void addChange(double[] v, int full, int compact) {
        v[full] += change[compact];
        v[full + 1] += change[compact + 1];
        v[full + 2] += change[compact + 2];
        change[compact] = 0; // a node in several links is shifted once
        change[compact + 1] = 0;
        change[compact + 2] = 0;
    }

    /**
     * u &lt;- the M-nearest velocity change that meets the linearised constraints
     * {@code (u_b - u_a) . n = target} (solver layout, m/s): u's component normal to them replaced,
     * its tangential part kept. For a solver whose unknown is the velocity change over the step,
     * linearised at the positions that change is measured from (implicit Euler's x + h v).
     */
    public void constrainIncrement(double[] u) {
        if (count > 0) {
            sweep(u, true);
        }
    }

    /** u = P u: the increment u (solver layout) into the constraints' tangent space. */
    public void project(double[] u) {
        if (count > 0) {
            sweep(u, false);
        }
    }

    /**
     * r = P^T r = M P M^-1 r: a force-like vector (a residual, solver layout) seen in the tangent
     * space; slots of no free node are left as they are (P is the identity there).
     */
    public void projectDual(double[] r) {
        if (count == 0) {
            return;
        }
        if (disjoint) {
            for (int i = 0; i < count; i++) {
                correctDual(r, i);
            }
            return;
        }
        for (int k = 0; k < invMass.length; k++) {
            final double w = invMass[k];
            if (w != 0) {
                r[3 * k] *= w;
                r[3 * k + 1] *= w;
                r[3 * k + 2] *= w;
            }
        }
        sweep(r, false);
        for (int k = 0; k < invMass.length; k++) {
            final double w = invMass[k];
            if (w != 0) {
                final double m = 1 / w;
                r[3 * k] *= m;
                r[3 * k + 1] *= m;
                r[3 * k + 2] *= m;
            }
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
            shift(temp, cgDir);
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
        shift(u, lambda);
    }

    /** u -= M^-1 N lambda: each link moves its ends along n, in inverse proportion to their masses. */
    private void shift(double[] u, double[] lam) {
        for (int i = 0; i < count; i++) {
            move(u, i, lam[i]);
        }
    }

    /** u -= M^-1 N_i mu for link i alone: end a by +w_a mu n, end b by -w_b mu n. */
    private void move(double[] u, int i, double mu) {
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

    /**
     * One link's part of {@code P^T r = M P M^-1 r} (links that share no node): with u = M^-1 r its
     * correction moves u_a by {@code w_a mu n} and u_b by {@code -w_b mu n}, so r_a by {@code mu n} and
     * r_b by {@code -mu n}; only the link's ends are touched (no pass over every node).
     */
    private void correctDual(double[] r, int i) {
        final double wsum = wA[i] + wB[i];
        final int a = endA[i];
        final int b = endB[i];
        double rate = 0;
        for (int c = 0; c < 3; c++) {
            rate += ((b >= 0 ? wB[i] * r[b + c] : 0) - (a >= 0 ? wA[i] * r[a + c] : 0)) * dir[3 * i + c];
        }
        if (wsum > 0 && rate != 0) {
            final double mu = rate / wsum;
            for (int c = 0; c < 3; c++) {
                final double n = dir[3 * i + c];
                if (a >= 0) {
                    r[a + c] += mu * n;
                }
                if (b >= 0) {
                    r[b + c] -= mu * n;
                }
            }
        }
    }

    /** One link's M-orthogonal correction of u (exact when no other link shares its nodes). */
    private void correct(double[] u, int i, boolean affine) {
        final double wsum = wA[i] + wB[i];
        final double violation = rate(u, i) - (affine ? target[i] : 0);
        if (wsum > 0 && violation != 0) {
            move(u, i, violation / wsum);
        }
    }
}
