package org.tensim.solver.prefactored;

import org.tensim.solver.ConjugateGradient;
import org.tensim.solver.ForceModel;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.SystemState;
import org.tensim.solver.links.LinkTangent;

/**
 * Newton's method on the implicit step's residual
 * {@code g(v) = M (v - v^) - beta f(t, x^ + beta v, v)} (free nodes only), each Newton system
 * {@code J dv = -g} solved by conjugate gradient preconditioned with a sparse Cholesky factor.
 * J is applied matrix-free by {@link SpringJacobian}, linearised once per Newton iteration.
 * The rigid links are kept within the step ({@link LinkTangent}): each Newton iterate's velocities
 * are shifted onto the links' lengths linearised at that iterate, and CG runs in their tangent
 * space (on {@code P^T J P}, with the preconditioner {@code P C^-1 P^T}; Baraff and Witkin 1998's
 * filtered CG, here for pair constraints).
 * Scratch arrays are allocated once, here.
 */
final class NewtonKrylov {
    private final SystemState s;
    private final int[] nodes;
    /** Inputs, compact over free nodes (3 per node): x^, v^ and the first guess of v. */
    final double[] xHat;
    final double[] vHat;
    final double[] guess;
    /** Full-size iterate (positions, velocities) at the end of {@link #solve}; fixed and driven nodes set. */
    final double[] xIt;
    final double[] vIt;
    private final double[] f;
    private final SpringJacobian jacobian;
    private final LinkTangent links;
    private final double[] g;
    private final double[] r;
    private final double[] dv;
    private final ConjugateGradient cg;
    private SparseCholesky preconditioner;
    private NodeLoops loops = NodeLoops.SERIAL; // the force model's, during a solve
    private final double[] work;
    private final double[] scratch = new double[6];
    double lastRelativeResidual;
    /** When the solves and the products' fibres and shear elements are shared among the force model's threads. */
    private KernelSharing sharing = KernelSharing.MEASURED;
    private SharingChoice solveSharing = new SharingChoice(sharing);
    private SharingChoice productSharing = new SharingChoice(sharing);
    long products;
    /** Wall time per part of the solve since construction, ns, indexed by {@link Bdf2Part#ordinal()}. */
    final long[] partNanos = new long[Bdf2Part.values().length];

    NewtonKrylov(SystemState s, int[] freeIndex, int[] freeNodes) {
        this.s = s;
        this.nodes = freeNodes;
        int n3 = 3 * s.nodeCount;
        int nf3 = 3 * freeNodes.length;
        xHat = new double[nf3];
        vHat = new double[nf3];
        guess = new double[nf3];
        xIt = new double[n3];
        vIt = new double[n3];
        f = new double[n3];
        jacobian = new SpringJacobian(s, freeIndex, freeNodes);
        links = new LinkTangent(s, freeIndex, freeNodes.length);
        g = new double[nf3];
        r = new double[nf3];
        dv = new double[nf3];
        cg = new ConjugateGradient(nf3);
        work = new double[nf3];
    }

    /**
     * Solves g(v) = 0 from the guess, leaving the new positions and velocities in
     * {@link #xIt} and {@link #vIt}.
     *
     * @param t1    time of the new state, s
     * @param beta  weight of the new step, s
     */
    void solve(ForceModel model, SparseCholesky precond, double t1, double beta, int newtonIterations,
            int krylovIterations, double krylovTolerance) {
        final int n3 = xIt.length;
        System.arraycopy(s.x, 0, xIt, 0, n3);
        System.arraycopy(s.v, 0, vIt, 0, n3);
        s.applyMotions(t1, xIt, vIt, scratch);
        scatter(guess, vIt);
        for (int it = 0; it < newtonIterations; it++) {
            positions(beta);
            long t0 = System.nanoTime();
            if (!links.isEmpty()) {
                // Newton on the links' lengths too: each iteration starts on their linearisation.
                links.linearise(xIt, beta);
                links.constrain(vIt);
                positions(beta);
            }
            long t1Links = System.nanoTime();
            partNanos[Bdf2Part.LINKS.ordinal()] += t1Links - t0;
            model.computeForces(t1, xIt, vIt, f);
            double norm = residual(beta);
            long t2 = System.nanoTime();
            partNanos[Bdf2Part.RESIDUAL.ordinal()] += t2 - t1Links;
            if (norm == 0) {
                break;
            }
            jacobian.linearise(t1, xIt, beta, model.nodeLoops(), model);
            partNanos[Bdf2Part.LINEARISE.ordinal()] += System.nanoTime() - t2;
            conjugateGradient(model, precond, krylovIterations, krylovTolerance);
            for (int j = 0; j < nodes.length; j++) {
                for (int c = 0; c < 3; c++) {
                    vIt[3 * nodes[j] + c] += dv[3 * j + c];
                }
            }
        }
        positions(beta);
    }

    /** x = x^ + beta v on the free nodes. */
    private void positions(double beta) {
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                final int k = 3 * nodes[j] + c;
                xIt[k] = xHat[3 * j + c] + beta * vIt[k];
            }
        }
    }

    /** g = M (v - v^) - beta f; returns |g|. */
    private double residual(double beta) {
        final double[] m = s.mass;
        double sum = 0;
        for (int j = 0; j < nodes.length; j++) {
            final int i = nodes[j];
            for (int c = 0; c < 3; c++) {
                final int k = 3 * i + c;
                final double gk = m[i] * (vIt[k] - vHat[3 * j + c]) - beta * f[k];
                g[3 * j + c] = gk;
                sum += gk * gk;
            }
        }
        return Math.sqrt(sum);
    }

    /**
     * Preconditioned CG on J dv = -g from dv = 0 ({@link ConjugateGradient}), stopped when the residual's norm
     * in the preconditioner's inverse, sqrt(r^T P^-1 r), has fallen by {@code tolerance} (a norm that weighs light
     * and heavy nodes alike, unlike |r|), or after {@code maxIterations}.
     */
    private void conjugateGradient(ForceModel model, SparseCholesky precond, int maxIterations, double tolerance) {
        final int nf3 = g.length;
        for (int k = 0; k < nf3; k++) {
            dv[k] = 0;
            r[k] = -g[k];
        }
        links.projectDual(r);
        preconditioner = precond;
        loops = model.nodeLoops();
        cg.solve(system, dv, r, 0, tolerance, maxIterations, ConjugateGradient.Stop.PRECONDITIONED);
        lastRelativeResidual = cg.relativeResidual();
    }

    /**
     * J in the links' tangent space ({@code P^T J P}), products and solves timed, with the preconditioner
     * {@code P C^-1 P^T}.
     */
    private final ConjugateGradient.Problem system = new ConjugateGradient.Problem() {
        @Override
        public void multiply(double[] pv, double[] out) {
            products++;
            final boolean shared = loops.threads() >= 2 && productSharing.share();
            jacobian.sharedKernels = shared;
            // The triangles' slabs were shared before the rest: the one-thread form of the products (NEVER) keeps
            // them so; the measured choice takes the whole product to the calling thread when that is faster.
            jacobian.sharedTriangles = shared || sharing != KernelSharing.MEASURED;
            long t0 = System.nanoTime();
            jacobian.multiply(pv, out);
            long t1 = System.nanoTime();
            links.projectDual(out);
            long t2 = System.nanoTime();
            productSharing.record(shared, t1 - t0);
            partNanos[Bdf2Part.PRODUCTS.ordinal()] += t2 - t0;
        }

        @Override
        public void precondition(double[] rv, double[] zv) {
            System.arraycopy(rv, 0, zv, 0, rv.length);
            final boolean shared = loops.threads() >= 2 && solveSharing.share();
            long t0 = System.nanoTime();
            preconditioner.solve3(zv, work, shared ? loops : NodeLoops.SERIAL);
            long t1 = System.nanoTime();
            links.project(zv);
            long t2 = System.nanoTime();
            solveSharing.record(shared, t1 - t0);
            partNanos[Bdf2Part.SOLVES.ordinal()] += t2 - t0;
        }
    };

    /** Sets when the solves and the products' fibres and shear elements are shared (their measures start anew). */
    void setSharing(KernelSharing policy) {
        sharing = policy;
        solveSharing = new SharingChoice(policy);
        productSharing = new SharingChoice(policy);
    }

    private void scatter(double[] compact, double[] full) {
        for (int j = 0; j < nodes.length; j++) {
            for (int c = 0; c < 3; c++) {
                full[3 * nodes[j] + c] = compact[3 * j + c];
            }
        }
    }
}
