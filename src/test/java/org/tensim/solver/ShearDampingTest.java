package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.testsupport.RandomMeshes;

/**
 * The transverse shear elements' Kelvin-Voigt damping ({@link org.tensim.model.TransverseShear#dampingS}):
 * the damping force is {@code -beta_e K_1 v} with K_1 the tangent's first term (the Jacobian the implicit
 * solvers use, and its diagonal their preconditioners'); a negative damping time is refused. (That it
 * dissipates and leaves rigid motions alone: {@link ShearElementsTest}.)
 */
class ShearDampingTest {
    private static final double KAPPA_G = RandomMeshes.SHEAR_KAPPA_G;
    private static final double T = RandomMeshes.SHEAR_T;
    private static final double BETA = 1.2e-4;

    private static SystemState randomElements(Random rnd) {
        return SystemState.compile(RandomMeshes.shears(rnd, BETA));
    }

    private static double[] gaussian(Random rnd, int n, double scale) {
        double[] v = new double[n];
        for (int k = 0; k < n; k++) {
            v[k] = scale * rnd.nextGaussian();
        }
        return v;
    }

    /** f(x, v) - f(x): the damping force alone. */
    private static double[] dampingForce(SystemState s, double[] x, double[] v) {
        double[] withRate = new double[x.length];
        double[] elastic = new double[x.length];
        s.shears.forces(x, v, withRate);
        s.shears.forces(x, elastic);
        for (int k = 0; k < x.length; k++) {
            withRate[k] -= elastic[k];
        }
        return withRate;
    }

    @Test
    void dampingForceIsMinusTheDampingJacobianTimesTheVelocity() {
        Random rnd = new Random(5);
        SystemState s = randomElements(rnd);
        assertTrue(s.shears.damped());
        double[] x = s.x.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += 1e-3 * rnd.nextGaussian();
        }
        double[] v = gaussian(rnd, x.length, 0.1);
        double[] fd = dampingForce(s, x, v);
        s.shears.linearise(x, false);
        double[] cv = new double[x.length];
        s.shears.multiplyAdd(v, cv, null, 0, 1);
        double scale = 0;
        for (double c : cv) {
            scale = Math.max(scale, Math.abs(c));
        }
        assertTrue(scale > 0, "a deformed, moving element is damped");
        for (int k = 0; k < x.length; k++) {
            assertEquals(-cv[k], fd[k], 1e-12 * scale, "component " + k);
        }
        // The diagonal of the same Jacobian, as the implicit solvers' preconditioners take it.
        double[] diag = new double[x.length];
        s.shears.addDiagonal(diag, 0, 1);
        for (int k = 0; k < x.length; k++) {
            double[] unit = new double[x.length];
            unit[k] = 1;
            double[] col = new double[x.length];
            s.shears.multiplyAdd(unit, col, null, 0, 1);
            assertEquals(col[k], diag[k], 1e-12 * Math.abs(col[k]) + 1e-300, "diagonal " + k);
        }
    }

    @Test
    void negativeDampingIsRefusedWithItsNameAndUnit() {
        Topology t = new Topology();
        for (int i = 0; i < 3; i++) {
            t.addNode(0.01 * i, 0.01 * (i % 2), 0, 1);
        }
        for (int i = 0; i < 3; i++) {
            var p = t.node(i).position();
            t.addNode(p.x(), p.y(), -T, 1);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> t.addShear(new int[] {0, 1, 2}, new int[] {3, 4, 5}, KAPPA_G, T, -1e-4));
        assertTrue(e.getMessage().contains("damping time beta") && e.getMessage().contains("s"), e.getMessage());
    }
}
