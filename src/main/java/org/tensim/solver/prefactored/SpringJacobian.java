package org.tensim.solver.prefactored;

import org.tensim.solver.ForceModel;
import org.tensim.solver.ForceTerm;

import org.tensim.solver.NodeLoops;
import org.tensim.solver.PartitionedTriangleTangent;
import org.tensim.solver.SpringKernels;
import org.tensim.solver.SystemState;

/**
 * The Jacobian of an implicit step, {@code J = M + beta C + beta^2 K}, on the free nodes
 * (compact numbering, 3 per node), applied matrix-free. Per spring of stiffness k (N/m), axial
 * damping c (N s/m), rest length L, length l and direction u, its block is
 *
 * <pre>
 *   beta^2 k ((1 - g) u u^T + g I) + beta c u u^T,   g = max(0, 1 - L / l)
 * </pre>
 *
 * (Baraff and Witkin 1998): the transverse term of a compressed spring (l &lt; L) is negative and
 * is clamped to zero, which keeps J symmetric positive definite so that conjugate gradient
 * applies, and keeps Newton's iteration from following a buckling branch; the global viscous
 * damping c_v adds {@code beta c_v I}. Springs to fixed and driven nodes act on the free end
 * only (those nodes are eliminated). Membrane triangles add {@code beta^2 K_T}, their tangent
 * stiffness with the compressive part of the stress dropped ({@link org.tensim.solver.TriangleTangent},
 * applied as {@link PartitionedTriangleTangent}: its slabs on the force model's threads), which keeps
 * J positive definite in the same way, and {@code beta beta_e K_T} for their Kelvin-Voigt damping.
 * Active fibre tensions add {@code beta^2 K_F} ({@link org.tensim.solver.FibreTension}, positive
 * semi-definite), at the new step's time. Transverse shear elements add {@code (beta^2 + beta beta_e) K_S},
 * {@code K_S = sum K_kl grad g_k grad g_l^T} ({@link org.tensim.solver.ShearElements}, their indefinite
 * geometric term dropped). Contacts with rigid bodies add {@code beta^2 k n n^T} on each node in contact at the
 * linearisation ({@link org.tensim.solver.ContactForces}, curvature term dropped), at the new step's time; they
 * are not in the prefactored preconditioner ({@link PrefactoredMatrix}: the set in contact changes from step to
 * step), so stiff contact costs CG iterations but not accuracy of the product.
 */
final class SpringJacobian {
    /**
     * Fibres and shear elements from which their part of a product is shared among the threads: below, a
     * dispatch costs more than half the loops (the triangles' threshold,
     * {@link PartitionedTriangleTangent#MIN_PARALLEL_ELEMENTS}). The springs' loop stays on the calling thread:
     * it is about 0.2 ms of a 3.7 ms product on the default diaphragm, less than a dispatch costs when the
     * other core is busy (docs/performance.md).
     */
    static final int MIN_SHARED_ELEMENTS = 2048;
    private final SystemState s;
    private final int[] nodes;
    private final int[] endA; // per spring: 3 x compact index of end a, -1 when not free
    private final int[] endB;
    private final double[] dir; // per spring: u_x, u_y, u_z
    private final double[] coef; // per spring: alpha, beta of alpha u u^T + beta I
    private double diagonalTerm; // beta c_v
    private final PartitionedTriangleTangent triangles; // null without triangles
    private final int[] triangleOffset; // per node: 3 x compact index, -1 when not free
    private NodeLoops loops = NodeLoops.SERIAL;
    /** Whose added terms' tangents join the products (null: none), set at linearisation. */
    private ForceModel model;
    private final NodeLoops.Body springRange = this::lineariseSprings;
    private double[] positions; // during linearise only
    private double weight; // beta, during linearise only
    private double triangleWeight; // beta^2
    private double triangleDampingWeight; // beta

    SpringJacobian(SystemState s, int[] freeIndex, int[] freeNodes) {
        this.s = s;
        this.nodes = freeNodes;
        int ns = s.springCount();
        endA = new int[ns];
        endB = new int[ns];
        for (int i = 0; i < ns; i++) {
            int a = freeIndex[s.springA[i]];
            int b = freeIndex[s.springB[i]];
            endA[i] = a < 0 ? -1 : 3 * a;
            endB[i] = b < 0 ? -1 : 3 * b;
        }
        dir = new double[3 * ns];
        coef = new double[2 * ns];
        triangleOffset = new int[s.nodeCount];
        for (int i = 0; i < s.nodeCount; i++) {
            triangleOffset[i] = freeIndex[i] < 0 ? -1 : 3 * freeIndex[i];
        }
        triangles = s.triangleCount() == 0 ? null : new PartitionedTriangleTangent(s, triangleOffset);
    }

    /**
     * Linearises at time t (s) and positions px (full layout) for the step weight beta (s); the
     * products until the next linearisation share their triangle slabs among the threads of loops.
     */
    void linearise(double t, double[] px, double beta, NodeLoops loops) {
        linearise(t, px, beta, loops, null);
    }

    /**
     * As {@link #linearise(double, double[], double, NodeLoops)}, with the tangents of {@code model}'s added terms
     * ({@link ForceTerm#linearise}; null: none) in the products, after the built-in ones, on the calling thread.
     */
    void linearise(double t, double[] px, double beta, NodeLoops loops, ForceModel model) {
        this.loops = loops;
        this.model = model;
        if (model != null) {
            for (int i = 0; i < model.termCount(); i++) {
                model.term(i).linearise(t, px);
            }
        }
        final double b2 = beta * beta;
        diagonalTerm = beta * s.viscousDamping();
        triangleWeight = b2;
        triangleDampingWeight = beta;
        if (triangles != null) {
            triangles.linearise(px, loops);
        }
        s.fibres.linearise(t, px);
        s.contacts.linearise(t, px);
        s.shears.linearise(px, false);
        s.volumes.linearise(px);
        positions = px;
        weight = beta;
        try {
            loops.run(s.springCount(), springRange);
        } finally {
            positions = null;
        }
    }

    /** Directions and block coefficients of the springs [from, to) at {@link #positions}. */
    private void lineariseSprings(int from, int to) {
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] kk = s.springK;
        final double[] cc = s.springC;
        final double[] rl = s.springL;
        final double[] px = positions;
        final double beta = weight;
        final double b2 = beta * beta;
        for (int i = from; i < to; i++) {
            final int a = 3 * sa[i];
            final int b = 3 * sb[i];
            final double len = SpringKernels.direction(px, a, b, dir, 3 * i);
            final double g = len > 0 ? Math.max(0, 1 - rl[i] / len) : 0;
            coef[2 * i] = b2 * kk[i] * (1 - g) + beta * cc[i];
            coef[2 * i + 1] = b2 * kk[i] * g;
        }
    }

    /**
     * Whether the fibres', contact pairs' and shear elements' part of the product is shared among the threads of the
     * linearisation's loops (when it has two or more; the same bits either way).
     */
    boolean sharedKernels = true;
    /**
     * Whether the triangles' slabs go to the threads of the linearisation's loops (the same bits either way):
     * false keeps them on the calling thread, where a product measured faster so (see {@link SharingChoice}).
     */
    boolean sharedTriangles = true;
    /** Parts of the shared product per thread. */
    static final int PARTS_PER_THREAD = 4;
    private NodeParts parts; // made at the first shared product
    private FibreShare[] shares;
    private final NodeLoops.Body sharedRange = this::sharedParts;
    private double[] pIn; // during a shared product only
    private double[] pOut;

    /** One part's fibres, contact pairs and shear elements. */
    private static final class FibreShare {
        final int[] fibres;
        final int[] contacts;
        final org.tensim.solver.ShearElements.Part shears;

        FibreShare(int[] fibres, int[] contacts, org.tensim.solver.ShearElements.Part shears) {
            this.fibres = fibres;
            this.contacts = contacts;
            this.shears = shears;
        }
    }

    /** out = J p (compact vectors). */
    void multiply(double[] p, double[] out) {
        final double[] m = s.mass;
        final double dt = diagonalTerm;
        for (int j = 0; j < nodes.length; j++) {
            final double mj = m[nodes[j]] + dt;
            out[3 * j] = mj * p[3 * j];
            out[3 * j + 1] = mj * p[3 * j + 1];
            out[3 * j + 2] = mj * p[3 * j + 2];
        }
        final int[] ea = endA;
        final int[] eb = endB;
        final double[] u = dir;
        for (int i = 0; i < ea.length; i++) {
            final int a = ea[i];
            final int b = eb[i];
            if (a < 0 && b < 0) {
                continue;
            }
            final double rx = (b >= 0 ? p[b] : 0) - (a >= 0 ? p[a] : 0);
            final double ry = (b >= 0 ? p[b + 1] : 0) - (a >= 0 ? p[a + 1] : 0);
            final double rz = (b >= 0 ? p[b + 2] : 0) - (a >= 0 ? p[a + 2] : 0);
            final double ux = u[3 * i];
            final double uy = u[3 * i + 1];
            final double uz = u[3 * i + 2];
            final double beta = coef[2 * i + 1];
            final double ur = coef[2 * i] * (ux * rx + uy * ry + uz * rz);
            final double ax = ur * ux + beta * rx;
            final double ay = ur * uy + beta * ry;
            final double az = ur * uz + beta * rz;
            if (a >= 0) {
                out[a] -= ax;
                out[a + 1] -= ay;
                out[a + 2] -= az;
            }
            if (b >= 0) {
                out[b] += ax;
                out[b + 1] += ay;
                out[b + 2] += az;
            }
        }
        if (triangles != null) {
            triangles.multiplyAdd(p, out, triangleWeight, triangleDampingWeight,
                    sharedTriangles ? loops : NodeLoops.SERIAL);
        }
        final int threads = loops.threads();
        if (sharedKernels && threads >= 2
                && s.fibres.count() + s.contacts.count() + s.shears.count() >= MIN_SHARED_ELEMENTS) {
            if (parts == null || parts.parts() != PARTS_PER_THREAD * threads) {
                share(PARTS_PER_THREAD * threads); // once per thread count
            }
            pIn = p;
            pOut = out;
            try {
                loops.runTasks(parts.parts(), sharedRange);
            } finally {
                pIn = null;
                pOut = null;
            }
        } else {
            s.fibres.multiplyAdd(p, out, triangleOffset, triangleWeight);
            s.contacts.multiplyAdd(p, out, triangleOffset, triangleWeight);
            s.shears.multiplyAdd(p, out, triangleOffset, triangleWeight, triangleDampingWeight);
        }
        // The volume elements, serial (their pass is one loop over the cells).
        s.volumes.multiplyAdd(p, out, triangleOffset, triangleWeight, triangleDampingWeight);
        // The scene's own terms (a mapped contact), serial: their nodes are not partitioned.
        if (model != null) {
            for (int i = 0; i < model.termCount(); i++) {
                model.term(i).multiplyAdd(p, out, triangleOffset, triangleWeight);
            }
        }
    }

    /**
     * Cuts the free nodes into {@code count} parts of equal node counts, parts claimed by the threads
     * as they come: several per thread, so that a thread whose core another process takes leaves its parts to
     * the others.
     */
    private void share(int count) {
        long[] work = new long[nodes.length];
        java.util.Arrays.fill(work, 1); // equal node counts: the parts are claimed as they come, which evens them
        parts = new NodeParts(restX(), work, count);
        shares = new FibreShare[count];
        for (int k = 0; k < count; k++) {
            shares[k] = new FibreShare(s.fibres.ownedFibres(triangleOffset, parts.owner, k),
                    s.contacts.ownedPairs(triangleOffset, parts.owner, k),
                    s.shears.part(triangleOffset, parts.owner, k));
        }
    }

    /**
     * The fibres', contact pairs' and shear elements' terms of the parts [from, to): the one-thread loops'
     * operations on each owned node, in their order (see {@link NodeParts}).
     */
    private void sharedParts(int from, int to) {
        for (int k = from; k < to; k++) {
            s.fibres.multiplyAdd(shares[k].fibres, pIn, pOut, triangleOffset, triangleWeight);
            s.contacts.multiplyAdd(shares[k].contacts, pIn, pOut, triangleOffset, triangleWeight);
            s.shears.multiplyAdd(shares[k].shears, pIn, pOut, triangleOffset, triangleWeight, triangleDampingWeight);
        }
    }

    /** The free nodes' rest x (compact index), m: where {@link NodeParts} cuts. */
    private double[] restX() {
        double[] x = new double[nodes.length];
        for (int j = 0; j < nodes.length; j++) {
            x[j] = s.x0[3 * nodes[j]];
        }
        return x;
    }

    /** The parts of the last shared product, or null (for tests). */
    NodeParts parts() {
        return parts;
    }
}
