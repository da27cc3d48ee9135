package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tensim.testsupport.FiniteDifferences.maxAbs;
import static org.tensim.testsupport.FiniteDifferences.perturbed;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.testsupport.FiniteDifferences;
import org.tensim.testsupport.RandomMeshes;

/**
 * The active fibre tension ({@link org.tensim.model.ActiveFibre}, {@link FibreTension}) as physics:
 * forces are minus the gradient of {@code W = sigma t A0 Phi(|F f0|)} (Phi the integral of the
 * force-length relation), they are internal (no net force, no net moment), W ignores rigid motions,
 * the tension shortens the fibre, a strip pulled by its fibres carries {@code f_L sigma t} per unit
 * width, and the tangent is the forces' derivative.
 */
class FibreTensionTest {
    private static final double SIGMA = 20e3;
    private static final double T = 2.5e-3;

    /** Fibres in random directions on the random triangles of {@link RandomMeshes#triangles} (half with midpoint corners). */
    private static Topology randomFibres(Random rnd, double sigma) {
        Topology t = RandomMeshes.triangles(rnd, 0.3);
        for (org.tensim.model.TriangleElement te : t.triangles()) {
            int[] p = {te.p(0), te.p(1), te.p(2)};
            int[] q = {te.q(0), te.q(1), te.q(2)};
            Vec3 dir = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            t.addFibre(p, q, dir, T * (0.5 + rnd.nextDouble()), time -> sigma * (1 + time));
        }
        return t;
    }

    @Test
    void forcesAreMinusTheEnergyGradient() {
        Random rnd = new Random(3);
        SystemState s = SystemState.compile(randomFibres(rnd, SIGMA));
        double[] x = perturbed(s.x, rnd, 0.2);
        double time = 0.5;
        double[] f = new double[x.length];
        s.fibres.forces(time, x, f);
        double scale = maxAbs(f);
        assertTrue(scale > 0, "the tensed fibres exert forces");
        double[] g = FiniteDifferences.gradient(y -> s.fibres.energy(time, y), x, 1e-6);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-g[k], f[k], 1e-6 * scale, "component " + k);
        }
    }

    @Test
    void forcesAreInternalAndTheEnergyIgnoresRigidMotions() {
        Random rnd = new Random(5);
        SystemState s = SystemState.compile(randomFibres(rnd, SIGMA));
        double[] x = perturbed(s.x, rnd, 0.3);
        double[] f = new double[x.length];
        s.fibres.forces(0, x, f);
        double scale = maxAbs(f);
        double[] sum = new double[3];
        double[] moment = new double[3];
        for (int i = 0; i < s.nodeCount; i++) {
            double px = x[3 * i];
            double py = x[3 * i + 1];
            double pz = x[3 * i + 2];
            double fx = f[3 * i];
            double fy = f[3 * i + 1];
            double fz = f[3 * i + 2];
            sum[0] += fx;
            sum[1] += fy;
            sum[2] += fz;
            moment[0] += py * fz - pz * fy;
            moment[1] += pz * fx - px * fz;
            moment[2] += px * fy - py * fx;
        }
        for (int d = 0; d < 3; d++) {
            assertEquals(0, sum[d], 1e-12 * scale, "net force, axis " + d);
            assertEquals(0, moment[d], 1e-12 * scale, "net moment about the origin, axis " + d);
        }
        // A rotation by 0.7 rad about a tilted axis and a translation leave W unchanged.
        double w0 = s.fibres.energy(0, x);
        Vec3 axis = new Vec3(1, -2, 0.5).normalized();
        double c = Math.cos(0.7);
        double sn = Math.sin(0.7);
        double[] y = new double[x.length];
        for (int i = 0; i < s.nodeCount; i++) {
            Vec3 v = new Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
            Vec3 r = v.times(c).plus(cross(axis, v).times(sn)).plus(axis.times(axis.dot(v) * (1 - c)));
            y[3 * i] = r.x() + 0.3;
            y[3 * i + 1] = r.y() - 1.1;
            y[3 * i + 2] = r.z() + 2;
        }
        assertTrue(w0 > 0);
        assertEquals(w0, s.fibres.energy(0, y), 1e-12 * w0);
    }

    @Test
    void theTensionShortensEachFibre() {
        Random rnd = new Random(9);
        for (int trial = 0; trial < 20; trial++) {
            Topology t = new Topology();
            for (int i = 0; i < 3; i++) {
                t.addNode(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), 1);
            }
            t.addFibre(new int[] {0, 1, 2}, new int[] {0, 1, 2}, new Vec3(rnd.nextGaussian(), rnd.nextGaussian(),
                    rnd.nextGaussian()), T, time -> SIGMA);
            SystemState s = SystemState.compile(t);
            double[] x = perturbed(s.x, rnd, 0.1);
            double[] f = new double[x.length];
            s.fibres.forces(0, x, f);
            double[] y = x.clone();
            double step = 1e-4 / maxAbs(f);
            for (int k = 0; k < x.length; k++) {
                y[k] += step * f[k];
            }
            // W = sigma t A0 lambda with fixed sigma t A0: W falls exactly when the stretch lambda does.
            assertTrue(s.fibres.energy(0, y) < s.fibres.energy(0, x), "trial " + trial + ": moving along the"
                    + " forces shortens the fibre");
        }
    }

    @Test
    void aStripPulledByItsFibresCarriesSigmaTimesThicknessPerUnitWidth() {
        // A strip L x B in the plane z = 0 of two triangles, fibres along x: the nodes at x = L are pulled
        // back towards x = 0 by f_L(stretch) sigma t B in total, the nodes at x = 0 forward by the same: the
        // full sigma t B on the plateau (stretch >= 1), less on the ascending limb, none below 0.4.
        double len = 0.03;
        double width = 0.02;
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(len, 0, 0, 1);
        t.addNode(len, width, 0, 1);
        t.addNode(0, width, 0, 1);
        t.addFibre(new int[] {0, 1, 2}, new int[] {0, 1, 2}, new Vec3(1, 0, 0), T, time -> SIGMA);
        t.addFibre(new int[] {0, 2, 3}, new int[] {0, 2, 3}, new Vec3(1, 0, 0), T, time -> SIGMA);
        SystemState s = SystemState.compile(t);
        double[] stretches = {1, 1.3, 0.8, 0.5, 0.3};
        double[] share = {1, 1, 1 - 4 * 0.2 * 0.2, 9 * 0.1 * 0.1, 0}; // Blemker et al. 2005's curve, by hand
        for (int i = 0; i < stretches.length; i++) {
            double stretch = stretches[i];
            double[] x = s.x.clone();
            x[3] = x[6] = stretch * len;
            double[] f = new double[x.length];
            s.fibres.forces(0, x, f);
            double pull = share[i] * SIGMA * T * width;
            assertEquals(-pull, f[3] + f[6], 1e-9 * SIGMA * T * width, "stretch " + stretch);
            assertEquals(pull, f[0] + f[9], 1e-9 * SIGMA * T * width, "stretch " + stretch);
            assertEquals(0, f[1] + f[4] + f[7] + f[10], 1e-9 * SIGMA * T * width);
        }
    }

    @Test
    void tangentIsTheDerivativeOfTheForces() {
        Random rnd = new Random(13);
        SystemState s = SystemState.compile(randomFibres(rnd, SIGMA));
        double[] x = perturbed(s.x, rnd, 0.1);
        double time = 0.25;
        int[] offset = new int[s.nodeCount];
        for (int i = 0; i < offset.length; i++) {
            offset[i] = 3 * i;
        }
        s.fibres.linearise(time, x);
        double h = 1e-6;
        double[] fp = new double[x.length];
        double[] fm = new double[x.length];
        for (int k = 0; k < x.length; k++) {
            double[] z = new double[x.length];
            z[k] = 1;
            double[] kz = new double[x.length];
            s.fibres.multiplyAdd(z, kz, offset, 1);
            java.util.Arrays.fill(fp, 0);
            java.util.Arrays.fill(fm, 0);
            double keep = x[k];
            x[k] = keep + h;
            s.fibres.forces(time, x, fp);
            x[k] = keep - h;
            s.fibres.forces(time, x, fm);
            x[k] = keep;
            double scale = Math.max(maxAbs(kz), 1);
            for (int j = 0; j < x.length; j++) {
                assertEquals(-(fp[j] - fm[j]) / (2 * h), kz[j], 1e-5 * scale, "K[" + j + "][" + k + "]");
            }
            assertTrue(kz[k] >= -1e-9 * scale, "a tensed fibre's tangent has a non-negative diagonal");
        }
    }

    @Test
    void noActiveStressNoForceAndANormalDirectionIsRefused() {
        Random rnd = new Random(17);
        SystemState s = SystemState.compile(randomFibres(rnd, 0));
        double[] f = new double[s.x.length];
        s.fibres.forces(1, perturbed(s.x, rnd, 0.2), f);
        assertEquals(0, maxAbs(f));
        Topology t = new Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(1, 0, 0, 1);
        t.addNode(0, 1, 0, 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> t.addFibre(new int[] {0, 1, 2}, new int[] {0, 1, 2}, new Vec3(0, 0, 1), T, time -> SIGMA));
        assertTrue(e.getMessage().contains("normal to the triangle"), e.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> t.addFibre(new int[] {0, 1, 2}, new int[] {0, 1, 2}, new Vec3(1, 0, 0), 0, time -> SIGMA));
    }

    private static Vec3 cross(Vec3 a, Vec3 b) {
        return new Vec3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
    }
}
