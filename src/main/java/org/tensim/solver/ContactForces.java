package org.tensim.solver;

import java.util.List;
import org.tensim.model.ContactBody;
import org.tensim.model.ContactPair;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * Frictionless one-sided contact of nodes with moving rigid bodies ({@link ContactBody},
 * {@link ContactPair}) on flat arrays allocated once: forces, energy, tangent stiffness and
 * read-outs for reports. For pair (node i, body b, stiffness k in N/m, gap g in m) at time t
 * (s), with the body's pose {@code x = R(t) x0 + c(t)} and its rest-frame signed distance phi_b:
 *
 * <pre>
 *   y = R^T (x_i - c),   d = phi_b(y),   m = grad phi_b(y),   n = R m   (world normal, outward)
 *   p = g - d   (penetration, m);   if p &gt; 0:
 *   W = k p^2 / 2,   f_i = -dW/dx_i = k p n,   K_ii = k n n^T
 * </pre>
 *
 * and nothing when p &lt;= 0. The force is exactly minus the gradient of W with n as the SDF
 * returns it (not renormalised, so that this holds for an approximate grid gradient too). The
 * tangent drops the curvature term {@code -k p (dn/dx)}: exact for a plane, and otherwise a
 * positive semi-definite Gauss-Newton approximation that keeps the implicit solvers' matrices
 * positive definite (the dropped term is small while p is, i.e. for stiff contact). No damping
 * along n: the scene's global damping acts, as on free nodes. Fixed and driven nodes get forces
 * like any node, which their zero inverse mass ignores.
 *
 * <p>Each body's pose is evaluated once per force pass per distinct t (cached by t, like
 * {@code HelicalAxisMotion}), and every pair's signed distance is evaluated at every pass (no
 * broad phase: the bodies' distances are cheap grid lookups, and skipping them by the bounds would
 * have to be proved safe). The force pass, energy, linearisation and products do not allocate and
 * are for the simulation thread; the read-outs ({@link #activeCount} etc.) use their own scratch
 * and may be called from another thread on a copy of the positions.
 */
public final class ContactForces {
    private final int[] node3; // per pair: 3 x node id
    private final int[] body; // per pair: body index
    private final double[] stiffness; // per pair: k, N/m
    private final double[] gap; // per pair: g, m
    private final SignedDistance[] surface; // per body
    private final RigidMotion[] motion; // per body
    private final double[] rotation; // per body: R(t) row-major, 9
    private final double[] translation; // per body: c(t), 3
    private final double[] poseTime; // per body: the t of the cached pose (NaN: none yet)
    private final double[] normal; // tangent: n per pair (world)
    private final double[] active; // tangent: k per pair when in contact at the linearisation, else 0
    private final double[] scratch = new double[4]; // hot loop: n, then d
    private final ContactProjection projection;
    private final boolean[] hard; // per body: projected after each step

    ContactForces(List<ContactBody> bodies, List<ContactPair> pairs) {
        int nb = bodies.size();
        surface = new SignedDistance[nb];
        motion = new RigidMotion[nb];
        hard = new boolean[nb];
        rotation = new double[9 * nb];
        translation = new double[3 * nb];
        poseTime = new double[nb];
        for (int b = 0; b < nb; b++) {
            surface[b] = bodies.get(b).surface();
            motion[b] = bodies.get(b).motion();
            hard[b] = bodies.get(b).hard();
            poseTime[b] = Double.NaN;
        }
        int n = pairs.size();
        node3 = new int[n];
        body = new int[n];
        stiffness = new double[n];
        gap = new double[n];
        normal = new double[3 * n];
        active = new double[n];
        for (int e = 0; e < n; e++) {
            ContactPair p = pairs.get(e);
            node3[e] = 3 * p.node();
            body[e] = p.body();
            stiffness[e] = p.stiffnessNPerM();
            gap[e] = p.gapM();
        }
        projection = new ContactProjection(this, node3, body, gap, hard);
    }

    /** Node ids with a pair on a hard body ({@link ContactBody#hard()}), each once, ascending. */
    public int[] hardNodes() {
        return projection.hardNodes();
    }

    /**
     * Puts every node that went deeper than its gap into a hard body back on the gap, along the body's normal, at
     * time t (s) and positions x (m), by {@link ContactProjection}'s line search (frictionless, one-sided; nodes of
     * zero inverse mass are left where they are). Allocation-free, simulation thread.
     *
     * @return the largest penetration found, g - d, m
     */
    public double project(double t, double[] x, double[] invMass) {
        return projection.project(t, x, invMass);
    }

    /** Number of node-body pairs. */
    public int count() {
        return node3.length;
    }

    /** Penalty stiffness of pair e, N/m. */
    public double stiffness(int e) {
        return stiffness[e];
    }

    /** Node id of pair e. */
    public int node(int e) {
        return node3[e] / 3;
    }

    /** The cached pose of body b at t, evaluated when t differs from the cached one. */
    private void pose(int b, double t) {
        // Compared bit for bit: NaN (no pose yet) never equals, and -0.0 vs 0.0 costs one evaluation.
        if (Double.doubleToRawLongBits(poseTime[b]) != Double.doubleToRawLongBits(t)) {
            motion[b].pose(t, rotation, 9 * b, translation, 3 * b);
            poseTime[b] = t;
        }
    }

    /**
     * Signed distance d (m) of pair e's node at positions x to its body posed by (rot, ro, tr, to),
     * returned, with the world normal n = R m into out[0..2].
     */
    private double distance(int e, double[] x, double[] rot, int ro, double[] tr, int to, double[] out) {
        final int i = node3[e];
        final double rx = x[i] - tr[to];
        final double ry = x[i + 1] - tr[to + 1];
        final double rz = x[i + 2] - tr[to + 2];
        // y = R^T r: column j of R dotted with r.
        final double yx = rot[ro] * rx + rot[ro + 3] * ry + rot[ro + 6] * rz;
        final double yy = rot[ro + 1] * rx + rot[ro + 4] * ry + rot[ro + 7] * rz;
        final double yz = rot[ro + 2] * rx + rot[ro + 5] * ry + rot[ro + 8] * rz;
        final double d = surface[body[e]].distance(yx, yy, yz, out, 0);
        final double mx = out[0];
        final double my = out[1];
        final double mz = out[2];
        out[0] = rot[ro] * mx + rot[ro + 1] * my + rot[ro + 2] * mz;
        out[1] = rot[ro + 3] * mx + rot[ro + 4] * my + rot[ro + 5] * mz;
        out[2] = rot[ro + 6] * mx + rot[ro + 7] * my + rot[ro + 8] * mz;
        return d;
    }

    /** Signed distance (m) of pair e at time t with the cached poses, its world normal into n (simulation thread). */
    double distance(int e, double t, double[] x, double[] n) {
        final int b = body[e];
        pose(b, t);
        return distance(e, x, rotation, 9 * b, translation, 3 * b, n);
    }

    /** Adds the contact forces {@code k max(0, g - d) n} (N) at time t (s) and positions x (m) to f. Allocation-free. */
    public void forces(double t, double[] x, double[] f) {
        final double[] n = scratch;
        for (int e = 0; e < node3.length; e++) {
            final double p = gap[e] - distance(e, t, x, n);
            if (p > 0) {
                final double kp = stiffness[e] * p;
                final int i = node3[e];
                f[i] += kp * n[0];
                f[i + 1] += kp * n[1];
                f[i + 2] += kp * n[2];
            }
        }
    }

    /** The contacts' energy {@code sum k max(0, g - d)^2 / 2} at time t (s) and positions x (m), J. */
    public double energy(double t, double[] x) {
        final double[] n = scratch;
        double sum = 0;
        for (int e = 0; e < node3.length; e++) {
            final double p = Math.max(0, gap[e] - distance(e, t, x, n));
            sum += 0.5 * stiffness[e] * p * p;
        }
        return sum;
    }

    /** Linearises the tangent {@code K_ii = k n n^T} of the pairs in contact at time t (s) and positions px (m). */
    public void linearise(double t, double[] px) {
        final double[] n = scratch;
        for (int e = 0; e < node3.length; e++) {
            final double p = gap[e] - distance(e, t, px, n);
            active[e] = p > 0 ? stiffness[e] : 0;
            normal[3 * e] = n[0];
            normal[3 * e + 1] = n[1];
            normal[3 * e + 2] = n[2];
        }
    }

    /**
     * {@code y += weight K z} with K linearised by {@link #linearise}; {@code offset[i]} is the index of
     * node i's x in z and y, or -1 for a node left out (its z taken as 0, its y not written); a null
     * offset means the full layout (3 i).
     */
    public void multiplyAdd(double[] z, double[] y, int[] offset, double weight) {
        for (int e = 0; e < node3.length; e++) {
            final int i = offset == null ? node3[e] : offset[node3[e] / 3];
            if (i >= 0) {
                multiplyAdd(e, i, z, y, weight);
            }
        }
    }

    /** Pair e's term {@code weight k n n^T z} added to y at index i (its node's x), when in contact. */
    private void multiplyAdd(int e, int i, double[] z, double[] y, double weight) {
        final double k = active[e];
        if (k == 0) {
            return;
        }
        final double nx = normal[3 * e];
        final double ny = normal[3 * e + 1];
        final double nz = normal[3 * e + 2];
        final double w = weight * k * (nx * z[i] + ny * z[i + 1] + nz * z[i + 2]);
        y[i] += w * nx;
        y[i + 1] += w * ny;
        y[i + 2] += w * nz;
    }

    /**
     * The pairs whose node part {@code part} of a partition of the nodes owns, in increasing order: that part's
     * share of {@link #multiplyAdd(double[], double[], int[], double)}.
     *
     * @param offset as in {@link #multiplyAdd(double[], double[], int[], double)} (not null)
     * @param owner  per node of the compact vectors (offset / 3): its part
     */
    public int[] ownedPairs(int[] offset, int[] owner, int part) {
        int[] pairs = new int[node3.length];
        int n = 0;
        for (int e = 0; e < node3.length; e++) {
            final int i = offset[node3[e] / 3];
            if (i >= 0 && owner[i / 3] == part) {
                pairs[n++] = e;
            }
        }
        return java.util.Arrays.copyOf(pairs, n);
    }

    /**
     * The share of {@link #multiplyAdd(double[], double[], int[], double)} of the given pairs ({@link #ownedPairs}):
     * each pair's node receives the same term as there. Disjoint shares may run at the same time.
     */
    public void multiplyAdd(int[] pairs, double[] z, double[] y, int[] offset, double weight) {
        for (final int e : pairs) {
            multiplyAdd(e, offset[node3[e] / 3], z, y, weight);
        }
    }

    /** {@code diag += weight} times the diagonal of K (k n_d^2 per active pair), full layout. */
    public void addDiagonal(double[] diag, double weight) {
        for (int e = 0; e < node3.length; e++) {
            final double k = active[e] * weight;
            for (int d = 0; d < 3 && k != 0; d++) {
                diag[node3[e] + d] += k * normal[3 * e + d] * normal[3 * e + d];
            }
        }
    }

    /**
     * The contacts' stiffness for a critical-step estimate ({@link SystemState#criticalTimeStep()}): every
     * pair taken as in contact, with any normal, i.e. {@code k I} on its node, which bounds {@code k n n^T}
     * (|n| = 1) from above; counted in the Gershgorin sums as a spring of stiffness k to a fixed point.
     * Why all pairs: an explicit step must stay stable when the nodes reach the bodies, not only at rest.
     */
    public ExtraStiffness worstCaseStiffness() {
        return node3.length == 0 ? ExtraStiffness.NONE : new ContactStiffnessBound(node3, stiffness);
    }

    // ---- Read-outs for reports: computed on demand, with their own scratch (not for the hot loop).

    /** Visits every pair: its signed distance d (m) and world normal n at time t and positions x. */
    private void visit(double t, double[] x, PairVisitor v) {
        final double[] rot = new double[9 * surface.length];
        final double[] tr = new double[3 * surface.length];
        for (int b = 0; b < surface.length; b++) {
            motion[b].pose(t, rot, 9 * b, tr, 3 * b);
        }
        final double[] n = new double[3];
        for (int e = 0; e < node3.length; e++) {
            final int b = body[e];
            final double d = distance(e, x, rot, 9 * b, tr, 3 * b, n);
            v.pair(e, d, n);
        }
    }

    private interface PairVisitor {
        void pair(int e, double d, double[] n);
    }

    /** Number of pairs in contact ({@code d < g}) at time t (s) and positions x (m). */
    public int activeCount(double t, double[] x) {
        int[] count = new int[1];
        visit(t, x, (e, d, n) -> count[0] += gap[e] - d > 0 ? 1 : 0);
        return count[0];
    }

    /**
     * The deepest penetration below the bodies' surfaces themselves, {@code max(0, max_e -d_e)} (m),
     * at time t (s) and positions x (m): not below the gap, so 0 while every node keeps out of the
     * bodies even when it is within its gap.
     */
    public double maxPenetrationM(double t, double[] x) {
        double[] max = new double[1];
        visit(t, x, (e, d, n) -> max[0] = Math.max(max[0], -d));
        return max[0];
    }

    /**
     * In one pass over the pairs at time t (s) and positions x (m): {@code [0]} the deepest penetration past
     * the pairs' gaps, {@code max(0, max_e (g_e - d_e))} (m; for a node that started inside a body, a
     * negative gap, how much deeper it went), {@code [1]} the pair it is at (-1 when none), and {@code [2]}
     * the deepest penetration below the surfaces themselves ({@link #maxPenetrationM}).
     */
    public double[] maxPenetrationPastGap(double t, double[] x) {
        double[] max = {0, -1, 0};
        visit(t, x, (e, d, n) -> {
            if (gap[e] - d > max[0]) {
                max[0] = gap[e] - d;
                max[1] = e;
            }
            max[2] = Math.max(max[2], -d);
        });
        return max;
    }

    /** Gap g of pair e, m: the signed distance below which the pair is in contact (negative for a node that started inside). */
    public double gap(int e) {
        return gap[e];
    }

    /**
     * Every pair's signed distance d (m) at time t (s) and positions x (m), into {@code d} (one per pair): pair e
     * is in contact when {@code d[e] < gap(e)}. For a listener reading the state after a step (which nodes touch,
     * how deep): it uses the force pass's cached poses and scratch, so it allocates nothing and must be called on
     * the simulation thread, between steps.
     */
    public void distances(double t, double[] x, double[] d) {
        if (d.length < node3.length) {
            throw new IllegalArgumentException("distances: room for " + d.length + " of " + node3.length + " pairs");
        }
        final double[] n = scratch;
        for (int e = 0; e < node3.length; e++) {
            d[e] = distance(e, t, x, n);
        }
    }

    /** Body index of pair e (in the topology's contact bodies). */
    public int body(int e) {
        return body[e];
    }

    /** The sum of the contact forces on the nodes at time t (s) and positions x (m), N, as {x, y, z}. */
    public double[] totalForceN(double t, double[] x) {
        double[] sum = new double[3];
        visit(t, x, (e, d, n) -> {
            final double kp = stiffness[e] * Math.max(0, gap[e] - d);
            for (int c = 0; c < 3; c++) {
                sum[c] += kp * n[c];
            }
        });
        return sum;
    }

    /** The sum of the magnitudes of the contact forces {@code sum k max(0, g - d) |n|} at t (s) and x (m), N. */
    public double totalNormalForceN(double t, double[] x) {
        double[] sum = new double[1];
        visit(t, x, (e, d, n) -> sum[0] += stiffness[e] * Math.max(0, gap[e] - d)
                * Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
        return sum[0];
    }

    /**
     * Each node's smallest signed distance d (m) to the hard bodies it has a pair with ({@link ContactBody#hard()}:
     * bones, not a compliant support), at time t (s) and positions x (m), for the first {@code nodes} node ids; NaN
     * for a node without such a pair.
     */
    public double[] nearestHardDistances(double t, double[] x, int nodes) {
        double[] near = new double[nodes];
        java.util.Arrays.fill(near, Double.NaN);
        visit(t, x, (e, d, n) -> {
            int i = node3[e] / 3;
            if (i < nodes && hard[body[e]] && !(d >= near[i])) {
                near[i] = d; // NaN compares false: the node's first pair sets it
            }
        });
        return near;
    }

    /** Whether each node is in contact ({@code d < g} for at least one of its pairs) at t (s) and x (m), per node id. */
    public boolean[] nodesInContact(double t, double[] x) {
        boolean[] in = new boolean[x.length / 3];
        visit(t, x, (e, d, n) -> in[node3[e] / 3] |= gap[e] - d > 0);
        return in;
    }
}
