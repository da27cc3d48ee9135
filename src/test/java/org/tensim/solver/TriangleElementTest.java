package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.tensim.model.Topology;
import org.tensim.testsupport.FiniteDifferences;
import org.tensim.testsupport.RandomMeshes;

/**
 * The St Venant-Kirchhoff membrane triangle ({@link org.tensim.model.TriangleElement},
 * {@link TriangleKernels}, {@link TriangleTangent}) as physics: forces are minus the energy's
 * gradient, the energy ignores rigid motions, the rest state is force-free, a uniform strain is
 * in equilibrium on any mesh (the patch test) with the exact plane-stress tractions, and the
 * small-strain stiffness is the linear constant-strain triangle's.
 */
class TriangleElementTest {
    private static final double E = RandomMeshes.TRIANGLE_E;
    private static final double T = RandomMeshes.TRIANGLE_T;

    @ParameterizedTest
    @ValueSource(doubles = {-0.3, 0, 1.0 / 3, 0.45, 0.49})
    void forcesAreMinusTheEnergyGradient(double nu) {
        Random rnd = new Random(7);
        SystemState s = SystemState.compile(RandomMeshes.triangles(rnd, nu));
        ForceModel fm = new ForceModel(s);
        double[] x = FiniteDifferences.perturbed(s.x, rnd, 0.2);
        double[] f = new double[x.length];
        fm.triangles(x, f);
        double scale = FiniteDifferences.maxAbs(f);
        assertTrue(scale > 0, "the deformed elements exert forces");
        double[] g = FiniteDifferences.gradient(fm::triangleEnergy, x, 1e-6);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-g[k], f[k], 1e-6 * scale, "component " + k);
        }
    }

    @Test
    void tangentIsTheDerivativeOfTheForces() {
        Random rnd = new Random(11);
        SystemState s = SystemState.compile(RandomMeshes.triangles(rnd, 0.3));
        ForceModel fm = new ForceModel(s);
        double[] x = s.x.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.1 * rnd.nextGaussian();
        }
        TriangleTangent tangent = new TriangleTangent(s);
        tangent.linearise(x, false);
        double[] dir = new double[x.length];
        for (int k = 0; k < x.length; k++) {
            dir[k] = rnd.nextGaussian();
        }
        double[] kd = new double[x.length];
        tangent.multiplyAdd(dir, kd, null);
        double[] df = FiniteDifferences.directional(fm::triangles, x, dir, 1e-6);
        double scale = FiniteDifferences.maxAbs(kd);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-df[k], kd[k], 1e-6 * scale, "component " + k);
        }
        // The clamped tangent is positive semi-definite even where elements are compressed.
        for (int k = 0; k < x.length; k++) {
            x[k] = s.x0[k] + 0.3 * rnd.nextGaussian();
        }
        tangent.linearise(x, true);
        for (int trial = 0; trial < 50; trial++) {
            for (int k = 0; k < x.length; k++) {
                dir[k] = rnd.nextGaussian();
            }
            java.util.Arrays.fill(kd, 0);
            tangent.multiplyAdd(dir, kd, null);
            double q = 0;
            for (int k = 0; k < x.length; k++) {
                q += dir[k] * kd[k];
            }
            assertTrue(q >= -1e-9 * scale, "d.K d = " + q);
        }
    }

    /** Kelvin-Voigt damping dissipates (f . v &lt; 0) and ignores rigid velocities (spin and drift). */
    @Test
    void dampingDissipatesAndIgnoresRigidMotions() {
        Random rnd = new Random(21);
        Topology t = RandomMeshes.triangles(rnd, 0.4);
        Topology damped = new Topology();
        for (var n : t.nodes()) {
            damped.addNode(n.position(), n.mass());
        }
        for (var e : t.triangles()) {
            damped.addTriangle(new int[] {e.p(0), e.p(1), e.p(2)}, new int[] {e.q(0), e.q(1), e.q(2)},
                    e.thicknessM(), e.youngPa(), e.poisson(), 0.01);
        }
        SystemState s = SystemState.compile(damped);
        ForceModel fm = new ForceModel(s);
        double[] x = s.x0.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.05 * rnd.nextGaussian();
        }
        double[] elastic = new double[x.length];
        fm.triangles(x, elastic);
        double[] v = new double[x.length];
        for (int trial = 0; trial < 20; trial++) {
            for (int k = 0; k < v.length; k++) {
                v[k] = rnd.nextGaussian();
            }
            double[] f = new double[x.length];
            fm.computeForces(0, x, v, f);
            double power = 0;
            for (int k = 0; k < v.length; k++) {
                power += (f[k] - elastic[k]) * v[k];
            }
            assertTrue(power < 0, "damping power " + power + " W");
        }
        // A rigid velocity: spin about z plus a drift.
        for (int i = 0; i < s.nodeCount; i++) {
            v[3 * i] = -x[3 * i + 1] + 0.3;
            v[3 * i + 1] = x[3 * i] - 0.2;
            v[3 * i + 2] = 0.5;
        }
        double[] f = new double[x.length];
        fm.computeForces(0, x, v, f);
        for (int k = 0; k < v.length; k++) {
            assertEquals(elastic[k], f[k], 1e-9 * E * T, "component " + k);
        }
    }

    @Test
    void energyIgnoresRigidMotionsAndTheRestStateIsForceFree() {
        Random rnd = new Random(3);
        SystemState s = SystemState.compile(RandomMeshes.triangles(rnd, 0.45));
        ForceModel fm = new ForceModel(s);
        double[] f = new double[s.x.length];
        fm.triangles(s.x0, f);
        for (double v : f) {
            assertEquals(0, v, 1e-12 * E * T);
        }
        assertEquals(0, fm.triangleEnergy(s.x0), 1e-18);
        double[] x = s.x0.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.1 * rnd.nextGaussian();
        }
        double w = fm.triangleEnergy(x);
        assertTrue(w > 0);
        // Rotation about a random axis and a translation.
        double[][] rot = rotation(rnd);
        double[] moved = new double[x.length];
        for (int i = 0; i < x.length / 3; i++) {
            double[] v = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
            for (int d = 0; d < 3; d++) {
                moved[3 * i + d] = dot(rot[d], v) + 0.7 * (d + 1);
            }
        }
        assertEquals(w, fm.triangleEnergy(moved), 1e-12 * w);
    }

    /**
     * The patch test: a distorted mesh of a rectangle, stretched by a uniform affine map (a finite
     * uniaxial stress state); every interior node is in equilibrium to round-off, and the forces on
     * the end sum to the exact section force.
     */
    @ParameterizedTest
    @ValueSource(doubles = {0, 0.25, 1.0 / 3, 0.45, 0.49})
    void uniformStrainIsExactOnADistortedMesh(double nu) {
        Random rnd = new Random(5);
        int cells = 6;
        double len = 0.06;
        Topology t = new Topology();
        for (int j = 0; j <= cells; j++) {
            for (int i = 0; i <= cells; i++) {
                boolean interior = i > 0 && i < cells && j > 0 && j < cells;
                double dx = interior ? 0.35 * (rnd.nextDouble() - 0.5) : 0;
                double dy = interior ? 0.35 * (rnd.nextDouble() - 0.5) : 0;
                t.addNode((i + dx) * len / cells, (j + dy) * len / cells, 0, 1);
            }
        }
        for (int j = 0; j < cells; j++) {
            for (int i = 0; i < cells; i++) {
                int a = j * (cells + 1) + i;
                boolean flip = rnd.nextBoolean();
                t.addTriangle(a, a + 1, flip ? a + cells + 2 : a + cells + 1, T, E, nu);
                t.addTriangle(flip ? a : a + 1, a + cells + 2, a + cells + 1, T, E, nu);
            }
        }
        SystemState s = SystemState.compile(t);
        ForceModel fm = new ForceModel(s);
        // Uniaxial Green strain E_xx = g, E_yy = -nu g (plane stress S_yy = 0): stretches sqrt(1 + 2 E).
        double g = 0.02;
        double sx = Math.sqrt(1 + 2 * g);
        double sy = Math.sqrt(1 - 2 * nu * g);
        double[] x = s.x0.clone();
        for (int i = 0; i < s.nodeCount; i++) {
            x[3 * i] *= sx;
            x[3 * i + 1] *= sy;
        }
        double[] f = new double[x.length];
        fm.triangles(x, f);
        // First Piola-Kirchhoff stress P_xx = sx S_xx, S_xx = E g: the end's force per unit rest width.
        double endForce = sx * E * g * T * len;
        double sum = 0;
        for (int j = 0; j <= cells; j++) {
            for (int i = 0; i <= cells; i++) {
                int v = j * (cells + 1) + i;
                boolean interior = i > 0 && i < cells && j > 0 && j < cells;
                if (interior) {
                    for (int d = 0; d < 3; d++) {
                        assertEquals(0, f[3 * v + d], 1e-12 * endForce, "interior node " + v);
                    }
                }
                if (i == cells) {
                    sum += f[3 * v];
                }
            }
        }
        assertEquals(-endForce, sum, 1e-12 * endForce, "the elements pull the end back with sigma t w");
    }

    /** At rest the tangent is the constant-strain triangle's {@code A t B^T D B} (plane stress), in any plane. */
    @Test
    void smallStrainStiffnessIsTheLinearCst() {
        Random rnd = new Random(9);
        double nu = 0.42;
        double[][] xy = {{0, 0}, {0.013, 0.002}, {0.004, 0.011}};
        // The same triangle placed in 3-D by a rotation (about a random axis) and a shift.
        double[][] rot = rotation(rnd);
        Topology t = new Topology();
        for (double[] p : xy) {
            double[] v = {p[0], p[1], 0};
            t.addNode(dot(rot[0], v) + 1, dot(rot[1], v) - 2, dot(rot[2], v) + 0.5, 1);
        }
        t.addTriangle(0, 1, 2, T, E, nu);
        SystemState s = SystemState.compile(t);
        TriangleTangent k = new TriangleTangent(s);
        // Linear CST: B (3 x 6) from the shape functions' gradients, D plane stress.
        double area = 0.5 * ((xy[1][0] - xy[0][0]) * (xy[2][1] - xy[0][1]) - (xy[2][0] - xy[0][0]) * (xy[1][1] - xy[0][1]));
        double[] b = new double[3];
        double[] c = new double[3];
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            int m = (i + 2) % 3;
            b[i] = (xy[j][1] - xy[m][1]) / (2 * area);
            c[i] = (xy[m][0] - xy[j][0]) / (2 * area);
        }
        double d0 = E / (1 - nu * nu);
        double[][] dm = {{d0, d0 * nu, 0}, {d0 * nu, d0, 0}, {0, 0, d0 * (1 - nu) / 2}};
        for (int col = 0; col < 6; col++) {
            double[][] bm = new double[3][6];
            for (int i = 0; i < 3; i++) {
                bm[0][2 * i] = b[i];
                bm[1][2 * i + 1] = c[i];
                bm[2][2 * i] = c[i];
                bm[2][2 * i + 1] = b[i];
            }
            double[] strain = new double[3];
            for (int r = 0; r < 3; r++) {
                strain[r] = bm[r][col];
            }
            double[] stress = new double[3];
            for (int r = 0; r < 3; r++) {
                for (int q = 0; q < 3; q++) {
                    stress[r] += dm[r][q] * strain[q];
                }
            }
            double[] expected = new double[6];
            for (int r = 0; r < 6; r++) {
                for (int q = 0; q < 3; q++) {
                    expected[r] += area * T * bm[q][r] * stress[q];
                }
            }
            // Apply the 3-D tangent to the rotated in-plane unit displacement.
            double[] in = new double[9];
            double[] local = {col % 2 == 0 ? 1 : 0, col % 2 == 1 ? 1 : 0, 0};
            for (int d = 0; d < 3; d++) {
                in[3 * (col / 2) + d] = dot(rot[d], local);
            }
            double[] out = new double[9];
            k.multiplyAdd(in, out, null);
            for (int node = 0; node < 3; node++) {
                double ox = rot[0][0] * out[3 * node] + rot[1][0] * out[3 * node + 1] + rot[2][0] * out[3 * node + 2];
                double oy = rot[0][1] * out[3 * node] + rot[1][1] * out[3 * node + 1] + rot[2][1] * out[3 * node + 2];
                double oz = rot[0][2] * out[3 * node] + rot[1][2] * out[3 * node + 1] + rot[2][2] * out[3 * node + 2];
                double tol = 1e-9 * d0 * T;
                assertEquals(expected[2 * node], ox, tol, "K[" + (2 * node) + "][" + col + "]");
                assertEquals(expected[2 * node + 1], oy, tol, "K[" + (2 * node + 1) + "][" + col + "]");
                assertEquals(0, oz, tol, "no out-of-plane stiffness at rest");
            }
        }
    }

    @Test
    void badInputIsRefusedWithItsNameAndUnit() {
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(1, 0, 0, 1);
        t.addNode(2, 0, 0, 1);
        t.addNode(0, 1, 0, 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> t.addTriangle(0, 1, 2, T, E, 0.3));
        assertTrue(e.getMessage().contains("degenerate"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> t.addTriangle(0, 1, 3, T, -1, 0.3));
        assertTrue(e.getMessage().contains("Young's modulus") && e.getMessage().contains("Pa"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> t.addTriangle(0, 1, 3, 0, E, 0.3));
        assertTrue(e.getMessage().contains("thickness") && e.getMessage().contains("m"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> t.addTriangle(0, 1, 3, T, E, 0.6));
        assertTrue(e.getMessage().contains("Poisson"), e.getMessage());
        assertThrows(IndexOutOfBoundsException.class, () -> t.addTriangle(0, 1, 7, T, E, 0.3));
    }

    private static double[][] rotation(Random rnd) {
        double[] k = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        double n = Math.sqrt(dot(k, k));
        for (int d = 0; d < 3; d++) {
            k[d] /= n;
        }
        double a = 0.9;
        double c = Math.cos(a);
        double sn = Math.sin(a);
        return new double[][] {
            {c + k[0] * k[0] * (1 - c), k[0] * k[1] * (1 - c) - k[2] * sn, k[0] * k[2] * (1 - c) + k[1] * sn},
            {k[1] * k[0] * (1 - c) + k[2] * sn, c + k[1] * k[1] * (1 - c), k[1] * k[2] * (1 - c) - k[0] * sn},
            {k[2] * k[0] * (1 - c) - k[1] * sn, k[2] * k[1] * (1 - c) + k[0] * sn, c + k[2] * k[2] * (1 - c)}};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
