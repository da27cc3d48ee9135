package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The CSparseJ factor with its AMD ordering solves what it factored, three columns at once. */
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

    @Test
    void aMatrixThatIsNotPositiveDefiniteIsNamedInAClearError() {
        double[][] a = laplacian(10, 30, 5, 0);
        a[4][4] = -1; // a negative pivot
        NotPositiveDefiniteException e = assertThrows(NotPositiveDefiniteException.class, () -> factor(a));
        assertTrue(e.getMessage().contains("the test matrix") && e.getMessage().contains("not positive definite"),
                e.getMessage());
    }
}
