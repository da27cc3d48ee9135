package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;

/** The volume elements' energy {@code K V (J - 1)^2 / 2}: forces as minus its gradient, its stiffness, its damping. */
class VolumeElementsTest {
    private static final double K = 1500; // Pa
    private static final double H = 0.01; // m

    /** A distorted brick (8 nodes, corner c at bits x, y, z) and a tet, each its own element, on one topology. */
    private static Topology cells(double beta) {
        Topology t = new Topology();
        Random r = new Random(1);
        int[] hex = new int[8];
        for (int c = 0; c < 8; c++) {
            hex[c] = t.addNode(H * ((c & 1) * 1.2 + 0.1 * r.nextDouble()), H * ((c >> 1 & 1) * 0.9
                    + 0.1 * r.nextDouble()), H * ((c >> 2 & 1) + 0.1 * r.nextDouble()), 1e-3).id();
        }
        int[] tet = new int[4];
        double[][] p = {{0, 0, 0}, {1.1, 0.1, 0}, {0.2, 0.9, 0.1}, {0.1, 0.2, 1.3}};
        for (int c = 0; c < 4; c++) {
            tet[c] = t.addNode(0.05 + H * p[c][0], H * p[c][1], H * p[c][2], 1e-3).id();
        }
        t.addVolumeElement(hex, K, beta);
        t.addVolumeElement(tet, 2 * K, beta);
        return t;
    }

    private static double[] moved(SystemState s, double scale, long seed) {
        Random r = new Random(seed);
        double[] x = s.x0.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] += scale * H * r.nextGaussian();
        }
        return x;
    }

    @Test
    void forcesAreMinusTheGradientOfTheEnergy() {
        SystemState s = SystemState.compile(cells(0));
        VolumeElements v = s.volumes;
        assertEquals(2, v.count());
        for (long seed = 0; seed < 5; seed++) {
            double[] x = moved(s, 0.15, seed);
            double[] f = new double[x.length];
            v.forces(x, null, f);
            double worst = 0;
            double norm = 0;
            double d = 1e-7 * H;
            for (int k = 0; k < x.length; k++) {
                double[] xp = x.clone();
                double[] xm = x.clone();
                xp[k] += d;
                xm[k] -= d;
                double grad = (v.energy(xp) - v.energy(xm)) / (2 * d);
                worst = Math.max(worst, Math.abs(f[k] + grad));
                norm = Math.max(norm, Math.abs(f[k]));
            }
            assertTrue(norm > 0, "a deformed cell has forces");
            assertTrue(worst < 1e-6 * norm, "f = -grad E to " + worst / norm + " (seed " + seed + ")");
        }
    }

    @Test
    void theRestVolumeIsExactAndAnAffineMotionGivesItsDeterminant() {
        Topology t = cells(0);
        // The tet's volume: det of its edges / 6.
        double[][] e = {{1.1, 0.1, 0}, {0.2, 0.9, 0.1}, {0.1, 0.2, 1.3}};
        double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2]
                - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        assertEquals(det / 6 * H * H * H, t.volumeElements().get(1).restVolumeM3(), 1e-20);
        SystemState s = SystemState.compile(t);
        // x -> A x + c, a rotation about z by 0.7 rad times a stretch: J = det A on both elements, exactly.
        double c = Math.cos(0.7);
        double sn = Math.sin(0.7);
        double[][] stretch = {{1.1, 0.05, 0}, {0, 0.95, 0.02}, {0.03, 0, 1.2}};
        double[][] a = new double[3][3];
        double[][] rot = {{c, -sn, 0}, {sn, c, 0}, {0, 0, 1}};
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                for (int k = 0; k < 3; k++) {
                    a[i][j] += rot[i][k] * stretch[k][j];
                }
            }
        }
        double detA = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2]
                - a[1][2] * a[2][0]) + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        double[] x = new double[s.x0.length];
        for (int n = 0; n < s.nodeCount; n++) {
            for (int i = 0; i < 3; i++) {
                x[3 * n + i] = 0.3 + a[i][0] * s.x0[3 * n] + a[i][1] * s.x0[3 * n + 1] + a[i][2] * s.x0[3 * n + 2];
            }
        }
        assertEquals(detA, s.volumes.volumeRatio(0, x), 1e-12);
        assertEquals(detA, s.volumes.volumeRatio(1, x), 1e-12);
        // A rigid motion (the rotation alone): J = 1, no energy, no force.
        for (int n = 0; n < s.nodeCount; n++) {
            for (int i = 0; i < 3; i++) {
                x[3 * n + i] = -0.1 + rot[i][0] * s.x0[3 * n] + rot[i][1] * s.x0[3 * n + 1]
                        + rot[i][2] * s.x0[3 * n + 2];
            }
        }
        assertEquals(0, s.volumes.energy(x), 1e-30);
        double[] f = new double[x.length];
        s.volumes.forces(x, null, f);
        for (double fk : f) {
            assertEquals(0, fk, 1e-15);
        }
    }

    @Test
    void theRestStiffnessIsTheHessianAtRestAndTheLinearisedOneTheGaussNewtonPart() {
        SystemState s = SystemState.compile(cells(0));
        VolumeElements v = s.volumes;
        int n = s.x0.length;
        double d = 1e-6 * H;
        double worst = 0;
        double scale = 0;
        for (int k = 0; k < n; k++) {
            double[] xp = s.x0.clone();
            double[] xm = s.x0.clone();
            xp[k] += d;
            xm[k] -= d;
            double[] fp = new double[n];
            double[] fm = new double[n];
            v.forces(xp, null, fp);
            v.forces(xm, null, fm);
            double[] z = new double[n];
            z[k] = 1;
            double[] kz = new double[n];
            v.restStiffness().multiplyAdd(z, kz);
            for (int j = 0; j < n; j++) {
                double fd = -(fp[j] - fm[j]) / (2 * d);
                worst = Math.max(worst, Math.abs(fd - kz[j]));
                scale = Math.max(scale, Math.abs(kz[j]));
            }
        }
        assertTrue(worst < 1e-6 * scale, "K at rest = -df/dx to " + worst / scale);
        // Deformed: the linearised product is K V b (b . z) with b = dJ/dx, checked against J's differences.
        double[] x = moved(s, 0.1, 9);
        v.linearise(x);
        Random r = new Random(4);
        double[] z = new double[n];
        for (int k = 0; k < n; k++) {
            z[k] = r.nextGaussian();
        }
        double[] y = new double[n];
        v.multiplyAdd(z, y, 1, 0);
        double[] expected = new double[n];
        for (int e = 0; e < 2; e++) {
            double[] b = new double[n];
            double dot = 0;
            for (int k = 0; k < n; k++) {
                double[] xp = x.clone();
                double[] xm = x.clone();
                xp[k] += d;
                xm[k] -= d;
                b[k] = (v.volumeRatio(e, xp) - v.volumeRatio(e, xm)) / (2 * d);
                dot += b[k] * z[k];
            }
            double kv = e == 0 ? K * cells(0).volumeElements().get(0).restVolumeM3()
                    : 2 * K * cells(0).volumeElements().get(1).restVolumeM3();
            for (int k = 0; k < n; k++) {
                expected[k] += kv * b[k] * dot;
            }
        }
        double err = 0;
        double size = 0;
        for (int k = 0; k < n; k++) {
            err = Math.max(err, Math.abs(y[k] - expected[k]));
            size = Math.max(size, Math.abs(expected[k]));
        }
        assertTrue(err < 1e-6 * size, "Gauss-Newton product to " + err / size);
    }

    @Test
    void dampingResistsTheRateOfVolumeChangeAndDissipates() {
        double beta = 0.02;
        SystemState s = SystemState.compile(cells(beta));
        double[] x = moved(s, 0.1, 3);
        Random r = new Random(8);
        double[] vel = new double[x.length];
        for (int k = 0; k < vel.length; k++) {
            vel[k] = 0.01 * r.nextGaussian();
        }
        double[] f0 = new double[x.length];
        double[] f1 = new double[x.length];
        s.volumes.forces(x, null, f0);
        s.volumes.forces(x, vel, f1);
        // The damping's power, -sum_e beta K V (dJ/dt)^2, with dJ/dt by differences of J along v.
        double power = 0;
        for (int k = 0; k < x.length; k++) {
            power += (f1[k] - f0[k]) * vel[k];
        }
        double dt = 1e-7;
        double expected = 0;
        for (int e = 0; e < 2; e++) {
            double[] xp = x.clone();
            double[] xm = x.clone();
            for (int k = 0; k < x.length; k++) {
                xp[k] += dt * vel[k];
                xm[k] -= dt * vel[k];
            }
            double rate = (s.volumes.volumeRatio(e, xp) - s.volumes.volumeRatio(e, xm)) / (2 * dt);
            double kv = (e == 0 ? K : 2 * K) * cells(0).volumeElements().get(e).restVolumeM3();
            expected -= beta * kv * rate * rate;
        }
        assertTrue(expected < 0);
        assertEquals(expected, power, 1e-6 * Math.abs(expected));
        assertTrue(s.volumes.damped());
    }

    @Test
    void aFlatCellAndAWrongCornerCountAreRefused() {
        Topology t = new Topology();
        for (int i = 0; i < 4; i++) {
            t.addNode(i, i == 1 ? 1 : 0, 0, 1);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> t.addVolumeElement(new int[] {0, 1, 2, 3}, K, 0));
        assertTrue(e.getMessage().startsWith("volume element on nodes [0, 1, 2, 3] is inverted or flat"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> t.addVolumeElement(new int[] {0, 1, 2}, K, 0));
        assertEquals("a volume element needs 4 nodes (a tet) or 8 (a hexahedron), got 3", e.getMessage());
    }
}
