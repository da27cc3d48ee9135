package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The one CG routine: both stopping norms, the cap, and a first guess that already solves. */
class ConjugateGradientTest {
    /** A symmetric positive definite 4 x 4 system with a Jacobi preconditioner. */
    private static final double[][] A = {{4, 1, 0, 0}, {1, 3, 1, 0}, {0, 1, 5, 2}, {0, 0, 2, 6}};
    private static final double[] X = {1, -2, 0.5, 3};

    private static final ConjugateGradient.Problem PROBLEM = new ConjugateGradient.Problem() {
        @Override
        public void multiply(double[] p, double[] out) {
            for (int i = 0; i < 4; i++) {
                out[i] = 0;
                for (int j = 0; j < 4; j++) {
                    out[i] += A[i][j] * p[j];
                }
            }
        }

        @Override
        public void precondition(double[] r, double[] z) {
            for (int i = 0; i < 4; i++) {
                z[i] = r[i] / A[i][i];
            }
        }
    };

    private static double[] b() {
        double[] b = new double[4];
        PROBLEM.multiply(X, b);
        return b;
    }

    @Test
    void bothNormsSolveASmallSystemInAtMostItsSizeOfIterations() {
        for (ConjugateGradient.Stop stop : ConjugateGradient.Stop.values()) {
            ConjugateGradient cg = new ConjugateGradient(4);
            double[] x = new double[4];
            double[] r = b();
            double b2 = 0;
            for (double v : r) {
                b2 += v * v;
            }
            assertTrue(cg.solve(PROBLEM, x, r, b2, 1e-12, 50, stop), stop.toString());
            assertTrue(cg.iterations() <= 4 + 1, stop + ": " + cg.iterations());
            assertTrue(cg.relativeResidual() <= 1e-12, stop + ": " + cg.relativeResidual());
            assertArrayEquals(X, x, 1e-9, stop.toString());
        }
    }

    @Test
    void theCapStopsItUnconvergedAndAnExactGuessNeedsNoIteration() {
        ConjugateGradient cg = new ConjugateGradient(4);
        double[] x = new double[4];
        assertFalse(cg.solve(PROBLEM, x, b(), 1, 1e-12, 1, ConjugateGradient.Stop.RESIDUAL));
        assertEquals(1, cg.iterations());
        double[] exact = X.clone();
        assertTrue(cg.solve(PROBLEM, exact, new double[4], 1, 1e-12, 50, ConjugateGradient.Stop.RESIDUAL));
        assertEquals(0, cg.iterations());
        assertArrayEquals(X, exact, 0);
    }
}
