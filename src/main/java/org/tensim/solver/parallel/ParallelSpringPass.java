package org.tensim.solver.parallel;

import java.util.Arrays;
import org.tensim.solver.SpringForcePass;
import org.tensim.solver.SpringKernels;
import org.tensim.solver.SystemState;

/**
 * The spring force pass on a {@link WorkerPool}: "owner computes" over a fixed
 * partition of the nodes, with per-thread force buffers and no atomics.
 *
 * <h2>Partition</h2>
 * Nodes are put in an internal order (authored, or reverse Cuthill-McKee when it
 * shortens the springs' spans a lot, see {@link Order}) and springs sorted by their
 * lower end in that order. Each thread owns a contiguous range of internal nodes
 * (balanced by spring count) and processes, in the global spring order, every spring
 * with at least one owned end. It adds into a private buffer that covers all the
 * nodes its springs touch, then copies only its owned nodes to {@code f}. A spring
 * cut by a range boundary is computed by both threads (each keeps its own end): a
 * few percent of extra work, in exchange for no reduction pass and no shared writes.
 *
 * <h2>Results independent of the thread count, to the last bit</h2>
 * Each node's force is its base force plus its springs' contributions added in the
 * global spring order, whichever thread owns it, and each contribution is computed
 * from the same inputs by the same operations. So 1, 2 or 8 threads give identical
 * bits (tested). Against {@code ForceModel}'s own loop the sums are the same up to
 * the order of the springs at a node: bit-identical when the sorted order equals the
 * authored one (the lattice), otherwise within rounding (tested to 1e-12 relative).
 *
 * <h2>Public layout kept</h2>
 * The arrays passed in are by authored node id; with a node permutation, each thread
 * gathers the positions (and velocities) of its nodes into private arrays in the
 * internal order and scatters its owned forces back. Spring parameters are private,
 * reordered copies, refreshed when {@link SystemState#parameterVersion()} moves.
 */
public final class ParallelSpringPass implements SpringForcePass {
    /** How nodes are ordered internally. */
    public enum Order {
        /** As authored (no permutation, no gather). */
        AUTHORED,
        /** Reverse Cuthill-McKee, always. */
        RCM,
        /** RCM when it divides the mean spring span by more than {@link #AUTO_GAIN}, else authored. */
        AUTO
    }

    /** Span ratio above which {@link Order#AUTO} permutes: below it the gather costs more than it saves. */
    public static final double AUTO_GAIN = 4;

    /**
     * Springs below which the pass runs on the calling thread alone (a pass of 4,096
     * springs takes about 25 microseconds: waking a worker and copying buffers would
     * eat the gain). The results are the same bits either way.
     */
    public static final int MIN_PARALLEL_SPRINGS = 4096;

    private final SystemState s;
    private final WorkerPool pool;
    private final int[] order; // internal position -> authored id; null when authored
    private final Block[] blocks;
    private final boolean direct;
    private final double authoredSpan;
    private final double internalSpan;
    private final int duplicated;
    private final WorkerPool.Task task = this::work;
    private long version;
    private boolean damped;
    // Arguments of the current pass, read by the workers (published by the pool's dispatch).
    private double[] px;
    private double[] pv;
    private double[] f;

    /** One thread's springs and buffers. */
    private static final class Block {
        int lo;
        int hi; // owned internal nodes [lo, hi)
        int first;
        int last; // touched internal nodes [first, last]
        int count;
        int[] sa; // 3 x (internal node - first)
        int[] sb;
        double[] k;
        double[] rl;
        double[] c;
        int[] src; // authored spring index of each entry
        double[] ft;
        double[] xt;
        double[] vt;
    }

    /**
     * Builds the partition for {@code pool.size()} threads.
     *
     * @param state compiled state (its spring parameters are copied; see class doc)
     * @param pool  the threads to run on (not closed by this pass)
     * @param o     internal node order
     */
    public ParallelSpringPass(SystemState state, WorkerPool pool, Order o) {
        this(state, pool, o, MIN_PARALLEL_SPRINGS);
    }

    /**
     * As {@link #ParallelSpringPass(SystemState, WorkerPool, Order)}, splitting the
     * springs among the threads only from {@code minParallelSprings} springs on.
     */
    public ParallelSpringPass(SystemState state, WorkerPool pool, Order o, int minParallelSprings) {
        this.s = state;
        this.pool = pool;
        final int n = state.nodeCount;
        final int[] sa = state.springA;
        final int[] sb = state.springB;
        authoredSpan = NodeOrdering.meanSpan(sa, sb, null);
        int[] ord = null;
        double span = authoredSpan;
        if (o != Order.AUTHORED && n > 0) {
            int[] rcm = NodeOrdering.reverseCuthillMcKee(n, sa, sb);
            double rcmSpan = NodeOrdering.meanSpan(sa, sb, NodeOrdering.invert(rcm));
            if (o == Order.RCM || authoredSpan > AUTO_GAIN * rcmSpan) {
                ord = rcm;
                span = rcmSpan;
            }
        }
        order = ord;
        internalSpan = span;
        final int[] rank = ord == null ? null : NodeOrdering.invert(ord);
        final int[] sorted = NodeOrdering.edgesByLowerEnd(n, sa, sb, rank);
        final int ns = sorted.length;
        final int[] ia = new int[ns];
        final int[] ib = new int[ns];
        for (int i = 0; i < ns; i++) {
            ia[i] = rank == null ? sa[sorted[i]] : rank[sa[sorted[i]]];
            ib[i] = rank == null ? sb[sorted[i]] : rank[sb[sorted[i]]];
        }

        final int threads = ns < minParallelSprings ? 1 : pool.size();
        blocks = new Block[threads];
        // Owned ranges: split the sorted springs into equal counts, at node boundaries.
        int[] bounds = new int[threads + 1];
        bounds[threads] = n;
        for (int t = 1; t < threads; t++) {
            int target = (int) ((long) ns * t / threads);
            int node = target < ns ? Math.min(ia[target], ib[target]) : n;
            bounds[t] = Math.max(bounds[t - 1], node);
        }
        int dup = 0;
        for (int t = 0; t < threads; t++) {
            Block b = new Block();
            b.lo = bounds[t];
            b.hi = bounds[t + 1];
            int cnt = 0;
            int first = b.lo;
            int last = b.hi - 1;
            for (int i = 0; i < ns; i++) {
                if (owns(b, ia[i]) || owns(b, ib[i])) {
                    cnt++;
                    first = Math.min(first, Math.min(ia[i], ib[i]));
                    last = Math.max(last, Math.max(ia[i], ib[i]));
                }
            }
            b.first = first;
            b.last = Math.max(last, first);
            b.count = cnt;
            b.sa = new int[cnt];
            b.sb = new int[cnt];
            b.k = new double[cnt];
            b.rl = new double[cnt];
            b.c = new double[cnt];
            b.src = new int[cnt];
            for (int i = 0, k = 0; i < ns; i++) {
                if (owns(b, ia[i]) || owns(b, ib[i])) {
                    b.sa[k] = 3 * (ia[i] - b.first);
                    b.sb[k] = 3 * (ib[i] - b.first);
                    b.src[k] = sorted[i];
                    k++;
                }
            }
            int width = 3 * (b.last - b.first + 1);
            b.ft = new double[width];
            if (ord != null) {
                b.xt = new double[width];
                b.vt = new double[width];
            }
            blocks[t] = b;
            dup += cnt;
        }
        duplicated = dup - ns;
        // One thread in the authored order needs no private buffer: it works on f in place.
        direct = threads == 1 && ord == null;
        refresh();
    }

    private static boolean owns(Block b, int node) {
        return node >= b.lo && node < b.hi;
    }

    /** Copies the spring parameters from the state (authored order) into the blocks. */
    private void refresh() {
        boolean d = false;
        for (Block b : blocks) {
            for (int k = 0; k < b.count; k++) {
                int i = b.src[k];
                b.k[k] = s.springK[i];
                b.rl[k] = s.springL[i];
                b.c[k] = s.springC[i];
                d |= s.springC[i] != 0;
            }
        }
        damped = d;
        version = s.parameterVersion();
    }

    /** Threads used (1 below {@link #MIN_PARALLEL_SPRINGS} springs). */
    public int threads() {
        return blocks.length;
    }

    /** Whether nodes are permuted internally (RCM), else the authored order is used. */
    public boolean permuted() {
        return order != null;
    }

    /** Mean |a - b| over springs in the authored node order, nodes. */
    public double authoredSpan() {
        return authoredSpan;
    }

    /** Mean |a - b| over springs in the internal node order, nodes. */
    public double internalSpan() {
        return internalSpan;
    }

    /** Springs computed twice because a range boundary cuts them. */
    public int duplicatedSprings() {
        return duplicated;
    }

    @Override
    public void addSpringForces(double[] x, double[] v, double[] forces) {
        if (version != s.parameterVersion()) {
            refresh();
        }
        px = x;
        pv = v;
        f = forces;
        if (blocks.length == 1) {
            work(0);
        } else {
            pool.run(task);
        }
        px = null;
        pv = null;
        f = null;
    }

    private void work(int w) {
        final Block b = blocks[w];
        final double[] x = px;
        final double[] v = pv;
        final double[] out = f;
        if (direct) {
            if (damped) {
                SpringKernels.springsDamped(b.sa, b.sb, b.k, b.rl, b.c, b.count, x, v, 0, out);
            } else {
                SpringKernels.springs(b.sa, b.sb, b.k, b.rl, b.count, x, 0, out);
            }
            return;
        }
        final double[] ft = b.ft;
        final int own = 3 * (b.lo - b.first);
        final int ownEnd = 3 * (b.hi - b.first);
        if (order == null) {
            // Owned forces start from f (gravity, external); the halo starts at 0 and is dropped.
            Arrays.fill(ft, 0, own, 0.0);
            System.arraycopy(out, 3 * b.lo, ft, own, ownEnd - own);
            Arrays.fill(ft, ownEnd, ft.length, 0.0);
            if (damped) {
                SpringKernels.springsDamped(b.sa, b.sb, b.k, b.rl, b.c, b.count, x, v, 3 * b.first, ft);
            } else {
                SpringKernels.springs(b.sa, b.sb, b.k, b.rl, b.count, x, 3 * b.first, ft);
            }
            System.arraycopy(ft, own, out, 3 * b.lo, ownEnd - own);
            return;
        }
        final int[] ord = order;
        final double[] xt = b.xt;
        final double[] vt = b.vt;
        for (int j = b.first, k = 0; j <= b.last; j++, k += 3) {
            final int o = 3 * ord[j];
            xt[k] = x[o];
            xt[k + 1] = x[o + 1];
            xt[k + 2] = x[o + 2];
            final boolean mine = j >= b.lo && j < b.hi;
            ft[k] = mine ? out[o] : 0;
            ft[k + 1] = mine ? out[o + 1] : 0;
            ft[k + 2] = mine ? out[o + 2] : 0;
        }
        if (damped) {
            for (int j = b.first, k = 0; j <= b.last; j++, k += 3) {
                final int o = 3 * ord[j];
                vt[k] = v[o];
                vt[k + 1] = v[o + 1];
                vt[k + 2] = v[o + 2];
            }
            SpringKernels.springsDamped(b.sa, b.sb, b.k, b.rl, b.c, b.count, xt, vt, 0, ft);
        } else {
            SpringKernels.springs(b.sa, b.sb, b.k, b.rl, b.count, xt, 0, ft);
        }
        for (int j = b.lo, k = own; j < b.hi; j++, k += 3) {
            final int o = 3 * ord[j];
            out[o] = ft[k];
            out[o + 1] = ft[k + 1];
            out[o + 2] = ft[k + 2];
        }
    }
}
