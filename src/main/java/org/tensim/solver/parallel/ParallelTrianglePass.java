package org.tensim.solver.parallel;

import java.util.ArrayList;
import java.util.List;
import org.tensim.solver.ShearElements;
import org.tensim.solver.SystemState;
import org.tensim.solver.TriangleForcePass;
import org.tensim.solver.TriangleKernels;
import org.tensim.solver.TriangleSlabs;

/**
 * The membrane triangles' forces ({@link TriangleKernels}) and the transverse shear elements'
 * ({@link ShearElements}) on a {@link WorkerPool}, without locks: the nodes the triangles use are
 * cut into {@link #BLOCKS} slabs with disjoint node sets ({@link TriangleSlabs}); a triangle, or a
 * shear element, whose nodes all lie in one slab belongs to it, the slabs are shared among the
 * workers, and the elements that straddle two slabs (a thin seam, a few percent) are then added by
 * the calling thread. The partition does not depend on the
 * thread count, so every node sums its triangles in the same order with one thread or several:
 * the same bits (tested).
 *
 * <p>Each slab keeps its own compact copies of the compiled arrays (allocated once); the moduli and
 * damping are copied again when the state's parameters change ({@link SystemState#parameterVersion()}).
 */
public final class ParallelTrianglePass implements TriangleForcePass {
    /** Slabs of the partition (fixed: the summation order must not depend on the thread count). */
    public static final int BLOCKS = 8;
    /** Triangles from which the pass is worth a dispatch (below, the serial loop is used). */
    public static final int MIN_PARALLEL_TRIANGLES = 2048;

    private final SystemState s;
    private final WorkerPool pool;
    private final Block[] blocks;
    private final Block seam;
    private long version = -1;
    private double[] px;
    private double[] pv;
    private double[] f;
    private final WorkerPool.Task task;

    /** One slab's triangles and shear elements, as compact copies of the state's arrays. */
    private static final class Block {
        final int[] source;
        final int[] shearSource;
        final ShearElements shears;
        final int[] p3;
        final int[] q3;
        final double[] rest;
        final double[] mu;
        final double[] lambda;
        final double[] damping;

        Block(SystemState s, List<Integer> elements, List<Integer> shearElements) {
            shearSource = shearElements.stream().mapToInt(Integer::intValue).toArray();
            shears = s.shears.subset(shearSource);
            int n = elements.size();
            source = new int[n];
            p3 = new int[3 * n];
            q3 = new int[3 * n];
            rest = new double[4 * n];
            mu = new double[n];
            lambda = new double[n];
            damping = new double[n];
            for (int i = 0; i < n; i++) {
                int e = elements.get(i);
                source[i] = e;
                System.arraycopy(s.triP3, 3 * e, p3, 3 * i, 3);
                System.arraycopy(s.triQ3, 3 * e, q3, 3 * i, 3);
                System.arraycopy(s.triRest, 4 * e, rest, 4 * i, 4);
            }
        }

        void refresh(SystemState s) {
            for (int i = 0; i < source.length; i++) {
                mu[i] = s.triMu[source[i]];
                lambda[i] = s.triLambda[source[i]];
                damping[i] = s.triDamping[source[i]];
            }
            shears.copyStiffness(s.shears, shearSource);
        }

        void add(double[] x, double[] v, double[] f) {
            TriangleKernels.forces(p3, q3, rest, mu, lambda, damping, source.length, x, v, f);
            shears.forces(x, v, f);
        }
    }

    public ParallelTrianglePass(SystemState state, WorkerPool pool) {
        this.s = state;
        this.pool = pool;
        int[] slab = TriangleSlabs.nodeSlabs(state, BLOCKS);
        int[] blockOf = TriangleSlabs.blockOf(state, slab, BLOCKS);
        List<List<Integer>> lists = new ArrayList<>();
        for (int b = 0; b <= BLOCKS; b++) {
            lists.add(new ArrayList<>());
        }
        for (int e = 0; e < state.triangleCount(); e++) {
            lists.get(blockOf[e]).add(e);
        }
        List<List<Integer>> shearLists = new ArrayList<>();
        for (int b = 0; b <= BLOCKS; b++) {
            shearLists.add(new ArrayList<>());
        }
        for (int e = 0; e < state.shears.count(); e++) {
            int b = slab[state.shears.node(e, 0)];
            for (int a = 0; a < 6; a++) {
                if (b < 0 || slab[state.shears.node(e, a)] != b) {
                    b = BLOCKS; // the seam (or a node outside the triangles' slabs)
                }
            }
            shearLists.get(b).add(e);
        }
        blocks = new Block[BLOCKS];
        for (int b = 0; b < BLOCKS; b++) {
            blocks[b] = new Block(state, lists.get(b), shearLists.get(b));
        }
        seam = new Block(state, lists.get(BLOCKS), shearLists.get(BLOCKS));
        final int workers = pool.size();
        task = w -> {
            for (int b = w; b < BLOCKS; b += workers) {
                blocks[b].add(px, pv, f);
            }
        };
    }

    /** The slabs also add the transverse shear elements (those on the seam serially, as the triangles). */
    @Override
    public boolean addsShearForces() {
        return true;
    }

    @Override
    public void addTriangleForces(double[] x, double[] v, double[] force) {
        if (version != s.parameterVersion()) {
            for (Block b : blocks) {
                b.refresh(s);
            }
            seam.refresh(s);
            version = s.parameterVersion();
        }
        px = x;
        pv = v;
        f = force;
        pool.run(task);
        seam.add(x, v, force);
        px = null;
        pv = null;
        f = null;
    }
}
