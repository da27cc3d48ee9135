package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import edu.emory.mathcs.csparsej.tdouble.Dcs_cholsol;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The CSparseJ factor with its AMD ordering solves what it factored, three columns at once, as a
 * symmetric positive definite operator (what conjugate gradient needs of a preconditioner).
 */
class SparseCholeskyTest {
    /** A random graph Laplacian plus a positive diagonal: symmetric positive definite. */
    private static double[][] laplacian(int n, int edges, long seed, double diagonal) {
        Random r = new Random(seed);
        double[][] a = new double[n][n];
        for (int i = 0; i < n; i++) {
            a[i][i] = diagonal;
        }
        for (int e = 0; e < edges; e++) {
            int i = r.nextInt(n);
            int j = r.nextInt(n);
            if (i == j) {
                continue;
            }
            double w = 1 + 10 * r.nextDouble();
            a[i][i] += w;
            a[j][j] += w;
            a[i][j] -= w;
            a[j][i] -= w;
        }
        return a;
    }

    private static SparseCholesky factor(double[][] a) {
        int n = a.length;
        int[] rows = new int[n * n];
        int[] cols = new int[n * n];
        double[] vals = new double[n * n];
        int count = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (a[i][j] != 0) {
                    rows[count] = i;
                    cols[count] = j;
                    vals[count++] = a[i][j];
                }
            }
        }
        SparseCholesky.Pattern p = SparseCholesky.analyse(n, rows, cols, vals, count);
        return SparseCholesky.factor(p, rows, cols, vals, count, "the test matrix");
    }

    @Test
    void solvesThreeColumnsOfALaplacianSystem() {
        int n = 60;
        double[][] a = laplacian(n, 200, 3, 0.5);
        SparseCholesky ch = factor(a);
        Random r = new Random(7);
        double[] x = new double[3 * n];
        for (int k = 0; k < x.length; k++) {
            x[k] = r.nextGaussian();
        }
        double[] b = new double[3 * n];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                for (int c = 0; c < 3; c++) {
                    b[3 * i + c] += a[i][j] * x[3 * j + c];
                }
            }
        }
        ch.solve3(b, new double[3 * n]);
        for (int k = 0; k < x.length; k++) {
            assertEquals(x[k], b[k], 1e-9, "unknown " + k / 3 + ", coordinate " + k % 3);
        }
        assertTrue(ch.factorNonZeros() >= n, "the factor holds at least the diagonal");
    }

    /**
     * A shell-like matrix: a grid of node pairs (as a shell's two layers), each node coupled to its twin
     * and to its grid neighbours and their twins. Its factor comes in supernodes, which solve3 takes
     * two columns at a time; the answer is CSparseJ's own column-by-column solve (cs_cholsol) to
     * round-off, and the solve is a symmetric positive definite operator.
     */
    @Test
    void pairedColumnsSolveAsCsparseDoesAndStaySymmetric() {
        int side = 24;
        int n = 2 * side * side;
        java.util.List<double[]> entries = new java.util.ArrayList<>();
        Random r = new Random(11);
        double[] diagonal = new double[n];
        java.util.function.BiConsumer<Integer, Integer> couple = (i, j) -> {
            double w = 1 + r.nextDouble();
            entries.add(new double[] {i, j, -w});
            entries.add(new double[] {j, i, -w});
            diagonal[i] += w;
            diagonal[j] += w;
        };
        for (int i = 0; i < side; i++) {
            for (int j = 0; j < side; j++) {
                int a = 2 * (i * side + j);
                couple.accept(a, a + 1);
                if (i + 1 < side) {
                    int b = a + 2 * side;
                    couple.accept(a, b);
                    couple.accept(a + 1, b + 1);
                    couple.accept(a, b + 1);
                }
                if (j + 1 < side) {
                    couple.accept(a, a + 2);
                    couple.accept(a + 1, a + 3);
                    couple.accept(a + 1, a + 2);
                }
            }
        }
        int count = entries.size() + n;
        int[] rows = new int[count];
        int[] cols = new int[count];
        double[] vals = new double[count];
        for (int k = 0; k < entries.size(); k++) {
            rows[k] = (int) entries.get(k)[0];
            cols[k] = (int) entries.get(k)[1];
            vals[k] = entries.get(k)[2];
        }
        for (int i = 0; i < n; i++) {
            rows[entries.size() + i] = i;
            cols[entries.size() + i] = i;
            vals[entries.size() + i] = diagonal[i] + 0.01 * (1 + r.nextDouble()); // a mass term
        }
        SparseCholesky ch = SparseCholesky.factor(SparseCholesky.analyse(n, rows, cols, vals, count), rows, cols,
                vals, count, "the shell-like test matrix");
        assertTrue(ch.pairedColumns() > n / 4, "many columns solved in pairs: " + ch.pairedColumns() + " of " + n);
        double[] b = new double[3 * n];
        for (int k = 0; k < b.length; k++) {
            b[k] = r.nextGaussian();
        }
        double[][] expected = new double[3][n];
        for (int c = 0; c < 3; c++) {
            for (int i = 0; i < n; i++) {
                expected[c][i] = b[3 * i + c];
            }
            assertTrue(Dcs_cholsol.cs_cholsol(1, SparseCholesky.compress(n, rows, cols, vals, count), expected[c]),
                    "CSparseJ's own solve");
        }
        double[] u = b.clone();
        ch.solve3(u, new double[3 * n]);
        double scale = 0;
        for (double[] e : expected) {
            for (double v : e) {
                scale = Math.max(scale, Math.abs(v));
            }
        }
        for (int i = 0; i < n; i++) {
            for (int c = 0; c < 3; c++) {
                assertEquals(expected[c][i], u[3 * i + c], 1e-13 * scale, "unknown " + i + ", coordinate " + c);
            }
        }
        // Symmetric and positive definite: a . S w = w . S a to round-off, and b . S b > 0.
        double[] w = new double[3 * n];
        for (int k = 0; k < w.length; k++) {
            w[k] = r.nextGaussian();
        }
        double[] sw = w.clone();
        ch.solve3(sw, new double[3 * n]);
        double bSw = 0;
        double wSb = 0;
        double bSb = 0;
        for (int k = 0; k < b.length; k++) {
            bSw += b[k] * sw[k];
            wSb += w[k] * u[k];
            bSb += b[k] * u[k];
        }
        assertEquals(bSw, wSb, 1e-12 * Math.abs(bSb), "symmetric");
        assertTrue(bSb > 0, "positive definite");
    }

    @Test
    void aMatrixThatIsNotPositiveDefiniteIsNamedInAClearError() {
        double[][] a = laplacian(10, 30, 5, 0);
        a[4][4] = -1; // a negative pivot
        NotPositiveDefiniteException e = assertThrows(NotPositiveDefiniteException.class, () -> factor(a));
        assertTrue(e.getMessage().contains("the test matrix") && e.getMessage().contains("not positive definite"),
                e.getMessage());
    }
}
