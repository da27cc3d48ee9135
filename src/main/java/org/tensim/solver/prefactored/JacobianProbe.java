package org.tensim.solver.prefactored;

import java.util.Arrays;

/**
 * Reads the entries of a sparse symmetric operator on the free nodes (3 per node) from products with a few
 * probe vectors (Curtis, Powell and Reid 1974; Coleman and More 1983): nodes are coloured so that no two of a
 * colour are within two edges of the node graph, and one product per colour and coordinate,
 * {@code y = A sum_{j of colour c} e_(j,d)}, gives {@code A[(i, .), (j, d)] = y_i} for the one neighbour j of
 * each node i that has colour c. Nodes of very many neighbours (hubs: an anchor tied to a whole rim) would make
 * the colouring need as many colours as they have neighbours; each is probed alone, its row read from its
 * column (A is symmetric), and the other probes do not read its row.
 *
 * <p>From the products it keeps what {@link PrefactoredMatrix} factors: per entry (i, j) of the graph the
 * scalar {@code (A_ij,xx + A_ij,yy + A_ij,zz) / 3} (the block's mean diagonal: the scalar node matrix closest
 * to A for a factor shared by the three coordinates), and per node its 3 x 3 diagonal block.
 * The products may be spread over steps ({@link #run}); the entries then come from the
 * linearisations of the steps they were read at, which suits a preconditioner.
 */
final class JacobianProbe {
    /** A node with more neighbours than this is a hub (probed alone). */
    static final int HUB_DEGREE = 64;

    /** The operator probed: {@code y = A v} on compact free-node vectors (v may be overwritten). */
    interface Operator {
        void apply(double[] v, double[] y);
    }

    private final int n;
    /** The graph in compressed rows, each row's columns ascending, the diagonal included. */
    final int[] rowStart;
    final int[] column;
    /** Colour of each node; hubs have colours from {@link #ordinaryColours} on, one each. */
    private final int[] colour;
    private final int ordinaryColours;
    private final int[] hubs;
    private final boolean[] isHub;
    /** Per graph entry: the mean diagonal of A's block. */
    private final double[] trace;
    /** Per node: its diagonal block, row-major (9 doubles). */
    private final double[] diagonal;
    private final double[] v;
    private final double[] y;
    private int next;

    /**
     * @param n        free nodes
     * @param rowStart compressed rows of the graph (n + 1 entries), columns ascending, diagonal included
     * @param column   the columns
     */
    JacobianProbe(int n, int[] rowStart, int[] column) {
        this.n = n;
        this.rowStart = rowStart;
        this.column = column;
        isHub = new boolean[n];
        int hubCount = 0;
        for (int i = 0; i < n; i++) {
            if (rowStart[i + 1] - rowStart[i] > HUB_DEGREE) {
                isHub[i] = true;
                hubCount++;
            }
        }
        hubs = new int[hubCount];
        for (int i = 0, h = 0; i < n; i++) {
            if (isHub[i]) {
                hubs[h++] = i;
            }
        }
        colour = new int[n];
        ordinaryColours = colourDistanceTwo();
        for (int h = 0; h < hubs.length; h++) {
            colour[hubs[h]] = ordinaryColours + h;
        }
        trace = new double[column.length];
        diagonal = new double[9 * n];
        v = new double[3 * n];
        y = new double[3 * n];
    }

    /** Greedy colouring: no two ordinary nodes of a colour share a neighbour or are neighbours (hubs aside). */
    private int colourDistanceTwo() {
        int[] seen = new int[n + 1];
        Arrays.fill(seen, -1);
        int colours = 0;
        for (int i = 0; i < n; i++) {
            if (isHub[i]) {
                continue;
            }
            for (int p = rowStart[i]; p < rowStart[i + 1]; p++) {
                int j = column[p];
                if (isHub[j]) {
                    continue;
                }
                if (j < i) {
                    seen[colour[j]] = i;
                }
                for (int q = rowStart[j]; q < rowStart[j + 1]; q++) {
                    int k = column[q];
                    if (k < i && !isHub[k]) {
                        seen[colour[k]] = i;
                    }
                }
            }
            int c = 0;
            while (seen[c] == i) {
                c++;
            }
            colour[i] = c;
            colours = Math.max(colours, c + 1);
        }
        return colours;
    }

    /** Products a full reading takes: one per colour (hubs included) and coordinate. */
    int products() {
        return 3 * (ordinaryColours + hubs.length);
    }

    /** Colours of the ordinary nodes (hubs not counted). */
    int ordinaryColours() {
        return ordinaryColours;
    }

    /** Hubs, each probed alone. */
    int hubCount() {
        return hubs.length;
    }

    /** Starts a new reading. */
    void restart() {
        next = 0;
        Arrays.fill(trace, 0);
        Arrays.fill(diagonal, 0);
    }

    /** Whether every product of the reading is done. */
    boolean complete() {
        return next >= products();
    }

    /**
     * Makes up to {@code budget} more products of the reading (all that remain when budget is larger).
     *
     * @return the products made
     */
    int run(Operator a, int budget) {
        int done = 0;
        while (done < budget && !complete()) {
            int c = next / 3;
            int d = next % 3;
            Arrays.fill(v, 0);
            for (int j = 0; j < n; j++) {
                if (colour[j] == c) {
                    v[3 * j + d] = 1;
                }
            }
            a.apply(v, y);
            if (c < ordinaryColours) {
                readOrdinary(c, d);
            } else {
                readHub(hubs[c - ordinaryColours], d);
            }
            next++;
            done++;
        }
        return done;
    }

    private void readOrdinary(int c, int d) {
        for (int i = 0; i < n; i++) {
            if (isHub[i]) {
                continue;
            }
            for (int p = rowStart[i]; p < rowStart[i + 1]; p++) {
                int j = column[p];
                if (colour[j] == c) {
                    trace[p] += y[3 * i + d] / 3;
                    if (j == i) {
                        for (int r = 0; r < 3; r++) {
                            diagonal[9 * i + 3 * r + d] = y[3 * i + r];
                        }
                    }
                }
            }
        }
    }

    /** Column h (coordinate d) of A, and by symmetry row h where the other end is not a hub. */
    private void readHub(int h, int d) {
        for (int p = rowStart[h]; p < rowStart[h + 1]; p++) {
            int i = column[p];
            int q = entry(i, h);
            trace[q] += y[3 * i + d] / 3;
            if (i == h) {
                for (int r = 0; r < 3; r++) {
                    diagonal[9 * h + 3 * r + d] = y[3 * h + r];
                }
            } else if (!isHub[i]) {
                trace[p] += y[3 * i + d] / 3;
            }
        }
    }

    /** Position of (i, j) in the graph. */
    int entry(int i, int j) {
        int p = Arrays.binarySearch(column, rowStart[i], rowStart[i + 1], j);
        if (p < 0) {
            throw new IllegalStateException("(" + i + ", " + j + ") is not in the probed graph");
        }
        return p;
    }

    /** Per graph entry, the mean diagonal of A's block (valid when {@link #complete()}); live array. */
    double[] traces() {
        return trace;
    }

    /** Per node, its 3 x 3 diagonal block, row-major (valid when {@link #complete()}); live array. */
    double[] diagonalBlocks() {
        return diagonal;
    }
}
