package org.tensim.solver.parallel;

import org.tensim.solver.LinkSweeps;
import org.tensim.solver.RigidLinkProjection;
import org.tensim.solver.SystemState;

/**
 * The rigid-link projection's sweeps over {@link LinkColoring colours}, each colour
 * split among the threads of a {@link WorkerPool}. Within a colour no two links
 * share a node, so the split cannot change any result: 1 or N threads give the same
 * bits (tested). The Gauss-Seidel order is colour by colour (links of a colour by
 * their lower node), not the authored order: the converged positions satisfy the
 * same tolerance but differ from the authored-order sweep's within it.
 *
 * <p>Colours are swept from the smallest to the largest. After a sweep, the links of
 * the last colour are exact to rounding (each was just corrected, and no later
 * correction moved its nodes), so the measure that follows a sweep skips them: with
 * the two or three colours of chains and lattices that saves a third to a half of
 * the measure. A link of that colour left uncorrected (both ends immovable, or zero
 * length) makes the measure cover every link again.
 *
 * <p>The correction per link is the one of {@code RigidLinkProjection}: the ends move
 * along the link, in inverse proportion to their masses; fixed and driven nodes
 * (inverse mass 0) never move. A colour with fewer than {@link #MIN_PARALLEL_LINKS}
 * links runs on the calling thread alone: a dispatch costs more than it saves.
 */
public final class ParallelLinkSweeps implements LinkSweeps {
    /** Links of one colour below which a colour is swept on the calling thread only. */
    public static final int MIN_PARALLEL_LINKS = 2048;

    private final WorkerPool pool;
    private final int minParallel;
    private final int[] colourStart; // links of colour c: [colourStart[c], colourStart[c+1])
    private final int[] la; // node ids
    private final int[] lb;
    private final int[] la3; // 3 x node id: the offsets into positions
    private final int[] lb3;
    private final double[] len;
    private final int[] src; // authored index
    private final double[] worstError;
    private final int[] worstIndex;
    private final WorkerPool.Task sweepTask = this::sweepSlice;
    private final WorkerPool.Task measureTask = this::measureSlice;
    private final int[] skipped; // per worker, one cache line apart: last colour's links left uncorrected
    private final boolean lastColourHasImmovable;
    private double[] swept; // the array of the last sweep, until the next measure
    private int measureEnd;
    private int worstLink = -1;
    private int colour;
    private double[] px;
    private double[] w;

    /** Colours the links of {@code s} and lays them out by colour. */
    public ParallelLinkSweeps(SystemState s, WorkerPool pool) {
        this(s, pool, MIN_PARALLEL_LINKS);
    }

    /**
     * As {@link #ParallelLinkSweeps(SystemState, WorkerPool)}, with the number of
     * links (>= 1) from which a colour, or the measure, is split among the threads.
     */
    public ParallelLinkSweeps(SystemState s, WorkerPool pool, int minParallelLinks) {
        if (minParallelLinks < 1) {
            throw new IllegalArgumentException("minParallelLinks must be >= 1, got " + minParallelLinks);
        }
        this.pool = pool;
        this.minParallel = minParallelLinks;
        final int m = s.linkCount();
        LinkColoring col = LinkColoring.greedy(s.nodeCount, s.linkA, s.linkB);
        int k = col.colours();
        // Colours swept from the smallest to the largest: after a sweep the last colour's
        // links are exact (they share no node and nothing moves them afterwards), so the
        // measure skips the largest colour.
        int[] size = new int[k];
        for (int i = 0; i < m; i++) {
            size[col.colour(i)]++;
        }
        Integer[] bySize = new Integer[k];
        for (int c = 0; c < k; c++) {
            bySize[c] = c;
        }
        java.util.Arrays.sort(bySize, (p, q) -> size[p] != size[q] ? Integer.compare(size[p], size[q])
                : Integer.compare(p, q));
        final int[] slot = new int[k];
        for (int c = 0; c < k; c++) {
            slot[bySize[c]] = c;
        }
        colourStart = new int[k + 1];
        for (int i = 0; i < m; i++) {
            colourStart[slot[col.colour(i)] + 1]++;
        }
        for (int c = 0; c < k; c++) {
            colourStart[c + 1] += colourStart[c];
        }
        // Within a colour, by lower node then authored index: neighbouring links, neighbouring memory.
        int[] byLower = NodeOrdering.edgesByLowerEnd(s.nodeCount, s.linkA, s.linkB, null);
        int[] fill = java.util.Arrays.copyOf(colourStart, k);
        la = new int[m];
        lb = new int[m];
        la3 = new int[m];
        lb3 = new int[m];
        len = new double[m];
        src = new int[m];
        for (int i : byLower) {
            int p = fill[slot[col.colour(i)]]++;
            la[p] = s.linkA[i];
            lb[p] = s.linkB[i];
            la3[p] = 3 * s.linkA[i];
            lb3[p] = 3 * s.linkB[i];
            len[p] = s.linkL[i];
            src[p] = i;
        }
        worstError = new double[16 * pool.size()]; // one cache line apart per worker
        worstIndex = new int[16 * pool.size()];
        skipped = new int[16 * pool.size()];
        boolean immovable = false;
        for (int i = k == 0 ? 0 : colourStart[k - 1]; i < m; i++) {
            immovable |= s.invMass[la[i]] + s.invMass[lb[i]] == 0;
        }
        lastColourHasImmovable = immovable;
    }

    /** Number of link colours. */
    public int colours() {
        return colourStart.length - 1;
    }

    @Override
    public void sweep(SystemState s, double[] x) {
        px = x;
        w = s.invMass;
        java.util.Arrays.fill(skipped, 0);
        for (int c = 0; c < colourStart.length - 1; c++) {
            colour = c;
            if (colourStart[c + 1] - colourStart[c] < minParallel) {
                sweepRange(0, colourStart[c], colourStart[c + 1]);
            } else {
                pool.run(sweepTask);
            }
        }
        px = null;
        w = null;
        swept = x;
    }

    private void sweepSlice(int worker) {
        int from = colourStart[colour];
        int count = colourStart[colour + 1] - from;
        int t = pool.size();
        sweepRange(worker, from + (int) ((long) count * worker / t),
                from + (int) ((long) count * (worker + 1) / t));
    }

    private void sweepRange(int worker, int from, int to) {
        final double[] x = px;
        final double[] wm = w;
        for (int i = from; i < to; i++) {
            if (!RigidLinkProjection.correct(x, la3[i], lb3[i], wm[la[i]], wm[lb[i]], len[i])) {
                skipped[16 * worker] = 1; // immovable or coincident ends: the error is reported by measure()
            }
        }
    }

    @Override
    public double measure(SystemState s, double[] x) {
        px = x;
        // Right after a sweep of x in which every link of the last colour was corrected,
        // those links are exact to rounding (1e-16 relative): only the others are measured.
        boolean skipLast = swept == x && !lastColourHasImmovable && colourStart.length > 1 && !anySkipped();
        measureEnd = skipLast ? colourStart[colourStart.length - 2] : la3.length;
        swept = null;
        boolean parallel = measureEnd >= minParallel;
        if (parallel) {
            pool.run(measureTask);
        } else {
            measureRange(0, 0, measureEnd);
        }
        px = null;
        int parts = parallel ? pool.size() : 1;
        double worst = 0;
        int index = -1;
        for (int p = 0; p < parts; p++) {
            double e = worstError[16 * p];
            int i = worstIndex[16 * p];
            if (i < 0) {
                continue;
            }
            // NaN beats everything; ties go to the smaller authored index: independent of the split.
            boolean nan = Double.isNaN(e);
            boolean worstNan = Double.isNaN(worst);
            if (index < 0 || (nan && !worstNan) || (nan == worstNan && (e > worst || (e == worst && i < index)))) {
                worst = e;
                index = i;
            }
        }
        worstLink = index;
        return worst;
    }

    private boolean anySkipped() {
        for (int p = 0; p < skipped.length; p += 16) {
            if (skipped[p] != 0) {
                return true;
            }
        }
        return false;
    }

    private void measureSlice(int worker) {
        int t = pool.size();
        int m = measureEnd;
        measureRange(worker, (int) ((long) m * worker / t), (int) ((long) m * (worker + 1) / t));
    }

    private void measureRange(int part, int from, int to) {
        final double[] x = px;
        double worst = 0;
        int index = -1;
        for (int i = from; i < to; i++) {
            final int a3 = la3[i];
            final int b3 = lb3[i];
            final double dx = x[b3] - x[a3];
            final double dy = x[b3 + 1] - x[a3 + 1];
            final double dz = x[b3 + 2] - x[a3 + 2];
            final double l = Math.sqrt(dx * dx + dy * dy + dz * dz);
            final double e = Math.abs(l - len[i]) / len[i];
            if (index < 0 || e > worst || (e == worst && src[i] < src[index]) || (e != e && worst == worst)) {
                worst = e;
                index = i;
            }
        }
        worstError[16 * part] = worst;
        worstIndex[16 * part] = index < 0 ? -1 : src[index];
    }

    @Override
    public int worstLink() {
        return worstLink;
    }
}
