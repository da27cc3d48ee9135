package org.tensim.solver;

import java.util.List;
import org.tensim.model.ContactBody;
import org.tensim.model.ContactPair;
import org.tensim.model.LinearMapping;

/**
 * Contact of a surface carried by the nodes ({@link LinearMapping}: a fine mesh on a coarse mechanical model) with
 * moving rigid bodies, as a {@link ForceTerm}: the fine surface's points are what touch the bones, and their forces
 * pass back to the nodes through the mapping's transpose. With the mapped points {@code p = W x} (W the mapping's
 * weights) and the contacts' energy {@code E(p)} of {@link ContactForces} (each pair a one-sided penalty
 * {@code k max(0, g - d(p_i))^2 / 2} along its body's normal), the term is
 *
 * <pre>
 *   E(x) = E(W x),   f = -dE/dx = W^T f_p,   K = W^T K_p W   (K_p = k n n^T per touching point)
 * </pre>
 *
 * the forces on the nodes doing on any nodal motion the work the points' forces do on the mapped motion. Their sum
 * is the points' total force, and their moment about any origin at the nodes' positions is the points' moment at
 * theirs ({@link LinearMapping}). The per-pair kernel (signed distance, poses, penalty, tangent) is
 * {@link ContactForces}', run on the mapped points; only the points with a pair are mapped at each pass.
 *
 * <p>The tangent {@code K} joins {@code bdf2}'s Newton-Krylov products ({@link #multiplyAdd}) and its isotropic part
 * on each node, {@code sum_i w_ij^2 k_i / 3}, the prefactored preconditioner ({@link #addIsotropicStiffness}): a stiff
 * penalty (k / m far above 1 / h^2) is then as stable under {@code bdf2} as the nodes' own contact.
 *
 * <p><b>Projection.</b> As the nodes' own contact on a hard body ({@link ContactBody#hard()}, a bone), a point that
 * went deeper than its gap is put back after each step ({@link #project}, the simulation's projection stage): each
 * such point's correction {@code dp_i} ({@link ContactForces#project} on the points) is carried to its nodes as
 * their weighted mean, {@code dx_j = sum_i w_ij dp_i / sum_i |w_ij|} over the points corrected: a uniform
 * penetration moves the nodes, and so the points, by exactly the correction, and the points a node carries share
 * it rather than each moving it by the whole (which would throw a node that carries many out by a multiple). What
 * remains is read by {@link #maxPenetrationPastGap}. The force pass, the products and the projection do not
 * allocate; the read-outs do.
 */
public final class MappedContact implements ForceTerm {
    private final LinearMapping points; // the paired points only, on the model's nodes
    private final ContactForces contact; // pairs on the paired points' compact ids
    private final int[] start; // the compact mapping's rows, for the products' layouts
    private final int[] node;
    private final double[] weight;
    private final double[] px; // 3 per paired point: positions, m
    private final double[] pf; // 3 per paired point: forces, N (and the products' scratch)
    private final double[] pz; // 3 per paired point: the products' gathered z
    private final double[] ones; // per paired point: the points' inverse masses for the projection (all free)
    private final double[] nodeSum; // 3 per node: the projection's weighted corrections
    private final double[] nodeWeight; // per node: the projection's sum of |w|
    private final int[] hardNodes; // the nodes of points with a pair on a hard body, ascending

    /**
     * @param carried the fine surface on the model's nodes: point i is a node combination (nodes of the model whose
     *                force arrays this term adds into)
     * @param bodies  the rigid bodies touched
     * @param pairs   the contact pairs, each {@link ContactPair#node()} a point of {@code carried} (not a node)
     * @throws IllegalArgumentException naming the pair whose point or body is out of range
     */
    public MappedContact(LinearMapping carried, List<ContactBody> bodies, List<ContactPair> pairs) {
        int[] compact = new int[carried.pointCount()];
        java.util.Arrays.fill(compact, -1);
        LinearMapping.Builder b = new LinearMapping.Builder(carried.nodeCount());
        List<ContactPair> renumbered = new java.util.ArrayList<>(pairs.size());
        for (int e = 0; e < pairs.size(); e++) {
            ContactPair p = pairs.get(e);
            if (p.node() < 0 || p.node() >= carried.pointCount()) {
                throw new IllegalArgumentException("mapped contact pair " + e + " is on point " + p.node()
                        + ": expected a point of the carried surface, 0.." + (carried.pointCount() - 1));
            }
            if (p.body() < 0 || p.body() >= bodies.size()) {
                throw new IllegalArgumentException("mapped contact pair " + e + " is on body " + p.body()
                        + ": expected one of the " + bodies.size() + " bodies");
            }
            if (compact[p.node()] < 0) {
                int n = carried.entries(p.node());
                int[] ids = new int[n];
                double[] w = new double[n];
                for (int k = 0; k < n; k++) {
                    ids[k] = carried.node(p.node(), k);
                    w[k] = carried.weight(p.node(), k);
                }
                compact[p.node()] = b.add(ids, w);
            }
            renumbered.add(new ContactPair(compact[p.node()], p.body(), p.stiffnessNPerM(), p.gapM()));
        }
        points = pairs.isEmpty() ? null : b.build();
        contact = new ContactForces(bodies, renumbered);
        int n = points == null ? 0 : points.pointCount();
        start = new int[n + 1];
        int entries = 0;
        for (int i = 0; i < n; i++) {
            entries += points.entries(i);
            start[i + 1] = entries;
        }
        node = new int[entries];
        weight = new double[entries];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < points.entries(i); k++) {
                node[start[i] + k] = points.node(i, k);
                weight[start[i] + k] = points.weight(i, k);
            }
        }
        px = new double[3 * n];
        pf = new double[3 * n];
        pz = new double[3 * n];
        ones = new double[n];
        java.util.Arrays.fill(ones, 1);
        nodeSum = new double[3 * carried.nodeCount()];
        nodeWeight = new double[carried.nodeCount()];
        java.util.TreeSet<Integer> hard = new java.util.TreeSet<>();
        for (int e = 0; e < contact.count(); e++) {
            if (bodies.get(contact.body(e)).hard()) {
                int i = contact.node(e);
                for (int q = start[i]; q < start[i + 1]; q++) {
                    hard.add(node[q]);
                }
            }
        }
        hardNodes = hard.stream().mapToInt(Integer::intValue).toArray();
    }

    @Override
    public int[] projectedNodes() {
        return hardNodes.clone();
    }

    /**
     * Puts the points deeper than their gaps into a hard body back on the gap, through their nodes' weighted mean
     * correction (class comment); nodes of zero inverse mass stay. Returns the largest point correction, m.
     */
    @Override
    public double project(double t, double[] x, double[] invMass) {
        if (hardNodes.length == 0) {
            return 0;
        }
        points.apply(x, px);
        System.arraycopy(px, 0, pz, 0, px.length);
        double largest = contact.project(t, pz, ones);
        if (largest == 0) {
            return 0;
        }
        for (int j : hardNodes) {
            nodeSum[3 * j] = 0;
            nodeSum[3 * j + 1] = 0;
            nodeSum[3 * j + 2] = 0;
            nodeWeight[j] = 0;
        }
        final int n = px.length / 3;
        for (int i = 0; i < n; i++) {
            final double dx = pz[3 * i] - px[3 * i];
            final double dy = pz[3 * i + 1] - px[3 * i + 1];
            final double dz = pz[3 * i + 2] - px[3 * i + 2];
            if (dx == 0 && dy == 0 && dz == 0) {
                continue;
            }
            for (int e = start[i]; e < start[i + 1]; e++) {
                final int j = node[e];
                final double w = weight[e];
                nodeSum[3 * j] += w * dx;
                nodeSum[3 * j + 1] += w * dy;
                nodeSum[3 * j + 2] += w * dz;
                nodeWeight[j] += Math.abs(w);
            }
        }
        for (int j : hardNodes) {
            if (nodeWeight[j] > 0 && invMass[j] != 0) {
                x[3 * j] += nodeSum[3 * j] / nodeWeight[j];
                x[3 * j + 1] += nodeSum[3 * j + 1] / nodeWeight[j];
                x[3 * j + 2] += nodeSum[3 * j + 2] / nodeWeight[j];
            }
        }
        return largest;
    }

    /** Number of contact pairs. */
    public int pairCount() {
        return contact.count();
    }

    /** Number of carried points with at least one pair (the points mapped at each pass). */
    public int pointCount() {
        return px.length / 3;
    }

    @Override
    public void addForces(double t, double[] x, double[] v, double[] f) {
        if (points == null) {
            return;
        }
        points.apply(x, px);
        java.util.Arrays.fill(pf, 0);
        contact.forces(t, px, pf);
        points.addTranspose(pf, f);
    }

    @Override
    public double energy(double t, double[] x) {
        if (points == null) {
            return 0;
        }
        points.apply(x, px);
        return contact.energy(t, px);
    }

    @Override
    public void linearise(double t, double[] x) {
        if (points == null) {
            return;
        }
        points.apply(x, px);
        contact.linearise(t, px);
    }

    /** {@code y += weight W^T K_p W z}: z gathered to the points, the points' tangent, scattered back. */
    @Override
    public void multiplyAdd(double[] z, double[] y, int[] offset, double w) {
        final int n = px.length / 3;
        for (int i = 0; i < n; i++) {
            double ax = 0;
            double ay = 0;
            double az = 0;
            for (int e = start[i]; e < start[i + 1]; e++) {
                final int o = offset == null ? 3 * node[e] : offset[node[e]];
                if (o >= 0) {
                    ax += weight[e] * z[o];
                    ay += weight[e] * z[o + 1];
                    az += weight[e] * z[o + 2];
                }
            }
            pz[3 * i] = ax;
            pz[3 * i + 1] = ay;
            pz[3 * i + 2] = az;
        }
        java.util.Arrays.fill(pf, 0);
        contact.multiplyAdd(pz, pf, null, w);
        for (int i = 0; i < n; i++) {
            final double fx = pf[3 * i];
            final double fy = pf[3 * i + 1];
            final double fz = pf[3 * i + 2];
            if (fx == 0 && fy == 0 && fz == 0) {
                continue; // a point not touching at the linearisation
            }
            for (int e = start[i]; e < start[i + 1]; e++) {
                final int o = offset == null ? 3 * node[e] : offset[node[e]];
                if (o >= 0) {
                    y[o] += weight[e] * fx;
                    y[o + 1] += weight[e] * fy;
                    y[o + 2] += weight[e] * fz;
                }
            }
        }
    }

    /** Node j gets {@code sum_i w_ij^2 k_i / 3} over every pair, all taken as touching. */
    @Override
    public void addIsotropicStiffness(double[] perNode) {
        for (int e = 0; e < contact.count(); e++) {
            final int i = contact.node(e);
            for (int q = start[i]; q < start[i + 1]; q++) {
                perNode[node[q]] += weight[q] * weight[q] * contact.stiffness(e) / 3;
            }
        }
    }

    /** The mapped points' positions (m) for the nodes' x: the read-outs' input (allocates). */
    private double[] mapped(double[] x) {
        double[] p = new double[px.length];
        if (points != null) {
            points.apply(x, p);
        }
        return p;
    }

    /**
     * At time t (s) and nodal positions x (m), on the mapped points: {@code [0]} the deepest penetration past the
     * pairs' gaps (m), {@code [1]} its pair (-1 when none), {@code [2]} the deepest below the bodies' surfaces (m);
     * as {@link ContactForces#maxPenetrationPastGap}, over every pair (the caller tells hard bodies apart by
     * {@link #body}).
     */
    public double[] maxPenetrationPastGap(double t, double[] x) {
        return contact.maxPenetrationPastGap(t, mapped(x));
    }

    /** Every pair's signed distance (m) on the mapped points at t (s) and nodal x (m), one per pair. */
    public double[] distances(double t, double[] x) {
        double[] d = new double[contact.count()];
        contact.distances(t, mapped(x), d);
        return d;
    }

    /** Gap of pair e, m. */
    public double gap(int e) {
        return contact.gap(e);
    }

    /** Body index of pair e. */
    public int body(int e) {
        return contact.body(e);
    }

    /** The sum of the contact forces on the mapped points at t (s) and nodal x (m), N: what the nodes receive. */
    public double[] totalForceN(double t, double[] x) {
        return contact.totalForceN(t, mapped(x));
    }

    /** Number of pairs in contact at t (s) and nodal x (m). */
    public int activeCount(double t, double[] x) {
        return contact.activeCount(t, mapped(x));
    }
}
