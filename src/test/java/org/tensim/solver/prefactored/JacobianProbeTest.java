package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Probing reads a sparse symmetric block matrix exactly: on seeded random graphs (a ring with random chords, and
 * hubs joined to a third of the nodes), the entries' mean diagonals and the diagonal blocks read from the products
 * equal the matrix's own, with fewer products than columns.
 */
class JacobianProbeTest {
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void readsEveryEntryOfARandomSymmetricBlockMatrixIncludingHubs(long seed) {
        Random rnd = new Random(seed);
        int n = 300 + rnd.nextInt(200);
        List<TreeSet<Integer>> rows = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            TreeSet<Integer> r = new TreeSet<>();
            r.add(i);
            rows.add(r);
        }
        for (int i = 0; i < n; i++) {
            join(rows, i, (i + 1) % n);
            join(rows, i, rnd.nextInt(n));
        }
        int hubs = 1 + rnd.nextInt(3);
        for (int h = 0; h < hubs; h++) {
            int hub = rnd.nextInt(n);
            for (int k = 0; k < n / 3; k++) {
                join(rows, hub, rnd.nextInt(n));
            }
        }
        int[] start = new int[n + 1];
        for (int i = 0; i < n; i++) {
            start[i + 1] = start[i] + rows.get(i).size();
        }
        int[] col = new int[start[n]];
        for (int i = 0, p = 0; i < n; i++) {
            for (int j : rows.get(i)) {
                col[p++] = j;
            }
        }
        // A symmetric 3n x 3n matrix on the graph: a random 3 x 3 block per entry (i <= j), its transpose at (j, i).
        double[][] block = new double[col.length][9];
        JacobianProbe probe = new JacobianProbe(n, start, col);
        for (int i = 0; i < n; i++) {
            for (int p = start[i]; p < start[i + 1]; p++) {
                int j = col[p];
                if (j < i) {
                    continue;
                }
                int q = probe.entry(j, i);
                for (int r = 0; r < 3; r++) {
                    for (int c = 0; c < 3; c++) {
                        double v = rnd.nextGaussian();
                        block[p][3 * r + c] = v;
                        block[q][3 * c + r] = v;
                    }
                }
            }
        }
        JacobianProbe.Operator a = (v, y) -> {
            java.util.Arrays.fill(y, 0);
            for (int i = 0; i < n; i++) {
                for (int p = start[i]; p < start[i + 1]; p++) {
                    int j = col[p];
                    for (int r = 0; r < 3; r++) {
                        for (int c = 0; c < 3; c++) {
                            y[3 * i + r] += block[p][3 * r + c] * v[3 * j + c];
                        }
                    }
                }
            }
        };
        probe.restart();
        int made = 0;
        while (!probe.complete()) {
            made += probe.run(a, 2); // spread over several calls, as over steps
        }
        assertEquals(probe.products(), made);
        assertTrue(probe.hubCount() >= 1, "hubs found: " + probe.hubCount());
        assertTrue(probe.products() < 3 * n / 4, probe.products() + " products for " + 3 * n + " columns");
        double[] trace = probe.traces();
        double[] diag = probe.diagonalBlocks();
        for (int i = 0; i < n; i++) {
            for (int p = start[i]; p < start[i + 1]; p++) {
                double expected = (block[p][0] + block[p][4] + block[p][8]) / 3;
                assertEquals(expected, trace[p], 1e-12, "mean diagonal of (" + i + ", " + col[p] + ")");
                if (col[p] == i) {
                    for (int k = 0; k < 9; k++) {
                        assertEquals(block[p][k], diag[9 * i + k], 1e-12, "diagonal block of " + i);
                    }
                }
            }
        }
    }

    private static void join(List<TreeSet<Integer>> rows, int i, int j) {
        rows.get(i).add(j);
        rows.get(j).add(i);
    }
}
