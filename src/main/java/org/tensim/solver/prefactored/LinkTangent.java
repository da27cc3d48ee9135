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
 * by an amount that does not fall with h while h w stays large (on a material-model diaphragm:
 * 6 % from RK2 at 0.25 ms, 25-30 % at 1-20 ms). An explicit step at its stable step moves the
 * links' ends by little each step, so its projection does not have this bias.
 *
 * <p>With the new velocity v as unknown and the positions {@code x = x^ + beta v} (the implicit
 * scheme's), each link gets the linear constraint
 *
 * <pre>
 *   (v_b - v_a) . n = (L - |d|) / beta,   d = p_b - p_a,   n = d / |d|
 * </pre>
 *
 * where p is x^ for a free end and the prescribed position at t + h for a fixed or driven one,
 * whose v counts as 0 (its motion is in p). The Newton increments are kept in the constraints'
 * tangent space by the mass-weighted (M-orthogonal) projector
 * {@code P = I - M^-1 N (N^T M^-1 N)^-1 N^T}, N holding the constraints' gradients: a link's
 * correction moves its ends along n in inverse proportion to their masses, as stage 2 does, so it
 * keeps the momentum. The step's Newton residual then enters as {@code P^T g = M P M^-1 g}: the
 * force along the links is the constraint's, and the tangential balance is solved. Disjoint
 * links (each node in at most one, as the diaphragm's columns) are projected exactly in one
 * sweep; links that share nodes are swept (Gauss-Seidel: alternating M-orthogonal projections)
 * until the constraints hold to 1e-12 of their first correction, or {@link #MAX_SWEEPS}.
 * Allocation-free after construction.
 */
final class LinkTangent {
    /** Cap on sweeps for links that share nodes. */
    static final int MAX_SWEEPS = 200;
    private static final double SWEEP_TOLERANCE = 1e-12;

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
        double first = -1;
        for (int it = 0; it < MAX_SWEEPS; it++) {
            double worst = 0;
            for (int i = 0; i < count; i++) {
                final double c = correct(u, i, affine);
                worst = Math.max(worst, Math.abs(c));
            }
            if (disjoint || worst == 0) {
                return;
            }
            if (first < 0) {
                first = worst;
            } else if (worst <= SWEEP_TOLERANCE * first) {
                return;
            }
        }
    }

    /** One link's M-orthogonal correction of u; returns the constraint's violation before it, m/s. */
    private double correct(double[] u, int i, boolean affine) {
        final double wa = wA[i];
        final double wb = wB[i];
        final double wsum = wa + wb;
        final int a = endA[i];
        final int b = endB[i];
        final double nx = dir[3 * i];
        final double ny = dir[3 * i + 1];
        final double nz = dir[3 * i + 2];
        double rel = 0;
        if (b >= 0) {
            rel += u[b] * nx + u[b + 1] * ny + u[b + 2] * nz;
        }
        if (a >= 0) {
            rel -= u[a] * nx + u[a + 1] * ny + u[a + 2] * nz;
        }
        final double violation = rel - (affine ? target[i] : 0);
        if (wsum == 0 || violation == 0) {
            return violation;
        }
        final double mu = violation / wsum;
        if (a >= 0) {
            u[a] += wa * mu * nx;
            u[a + 1] += wa * mu * ny;
            u[a + 2] += wa * mu * nz;
        }
        if (b >= 0) {
            u[b] -= wb * mu * nx;
            u[b + 1] -= wb * mu * ny;
            u[b + 2] -= wb * mu * nz;
        }
        return violation;
    }
}
