package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.SlidingCases.Case;
import org.tensim.solver.SurfaceSliding.Mode;
import org.tensim.solver.integrators.Integrators;

/**
 * The sliding term's tangent: at the gaps (no penetration) it is the exact Jacobian -df/dx by central differences;
 * anywhere it is symmetric and positive semi-definite; the products honour the implicit integrators' layouts; the
 * isotropic part is the trace of the diagonal blocks over 3; and with it {@code bdf2} holds a stiff coupling at
 * steps far above the explicit limit where the same term without a tangent runs away.
 */
class SurfaceSlidingTangentTest {
    private static double[] forces(SurfaceSliding s, double[] x) {
        double[] f = new double[x.length];
        s.addForces(0, x, new double[x.length], f);
        return f;
    }

    private static double[] randomVector(Random r, int n) {
        double[] z = new double[n];
        for (int i = 0; i < n; i++) {
            z[i] = r.nextGaussian();
        }
        return z;
    }

    private static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) {
            s += a[i] * b[i];
        }
        return s;
    }

    /**
     * The followers put over the inside of their triangles (where a small move keeps the pairing:
     * {@link SlidingCases#overPairedTriangles}) into x, and their gaps set to their distances there: no force at x,
     * so K is the whole Jacobian.
     */
    private static SurfaceSliding atGaps(Case c, Mode mode, double[] x, long seed) {
        SurfaceSliding probe = c.term(mode);
        SlidingCases.overPairedTriangles(c, probe, x, new Random(seed));
        double[] d = new double[c.followers().length];
        probe.distancesM(x, d);
        for (int e = 0; e < d.length; e++) {
            d[e] = Double.isNaN(d[e]) ? 0 : d[e] + (mode == Mode.CONTACT ? 1e-7 : 0); // CONTACT: touching by 1e-7 m, beyond the 1e-8 m probe
        }
        return new SurfaceSliding(c.followers(), c.mapping(), c.triangles(), c.stiffness(), mode, d, x);
    }

    @Test
    void atTheGapsTheTangentIsTheForcesJacobianByCentralDifferences() {
        for (Mode mode : Mode.values()) {
            for (long seed = 1; seed <= 6; seed++) {
                Case c = SlidingCases.random(300 + seed, 5, 10);
                double[] x = c.x().clone();
                SurfaceSliding s = atGaps(c, mode, x, seed);
                s.linearise(0, x);
                Random r = new Random(seed);
                double[] z = randomVector(r, x.length);
                double[] kz = new double[x.length];
                s.multiplyAdd(z, kz, null, 1);
                double h = 1e-8; // m along z: pen stays ~1e-8 m, so the neglected k pen terms are ~1e-6 of k
                double[] xp = x.clone();
                double[] xm = x.clone();
                for (int i = 0; i < x.length; i++) {
                    xp[i] += h * z[i];
                    xm[i] -= h * z[i];
                }
                double[] fp = forces(s, xp);
                double[] fm = forces(s, xm);
                double worst = 0;
                double scale = 0;
                for (int i = 0; i < x.length; i++) {
                    double fd = -(fp[i] - fm[i]) / (2 * h);
                    worst = Math.max(worst, Math.abs(fd - kz[i]));
                    scale = Math.max(scale, Math.abs(kz[i]));
                }
                assertTrue(scale > 1, mode + " seed " + seed + ": K z has " + scale + " N/m");
                // CONTACT touches by 1e-7 m: the terms of order k pen / size left out are ~2e-5 of K there.
                assertTrue(worst < 1e-4 * scale, mode + " seed " + seed + ": |K z + df/dx z| = " + worst
                        + " against " + scale);
            }
        }
    }

    @Test
    void anywhereTheTangentIsSymmetricAndPositiveSemiDefinite() {
        for (Mode mode : Mode.values()) {
            for (long seed = 1; seed <= 10; seed++) {
                Case c = SlidingCases.random(400 + seed, 6, 12);
                SurfaceSliding s = c.term(mode);
                s.linearise(0, c.x());
                Random r = new Random(seed);
                double[] a = randomVector(r, c.x().length);
                double[] b = randomVector(r, c.x().length);
                double[] ka = new double[a.length];
                double[] kb = new double[b.length];
                s.multiplyAdd(a, ka, null, 1);
                s.multiplyAdd(b, kb, null, 1);
                double scale = Math.sqrt(dot(ka, ka) * dot(b, b));
                assertTrue(scale > 0, mode + " seed " + seed + ": the tangent acts");
                assertEquals(dot(b, ka), dot(a, kb), 1e-12 * scale, mode + " seed " + seed + ": b.Ka = a.Kb");
                assertTrue(dot(a, ka) >= -1e-12 * scale, mode + " seed " + seed + ": a.Ka = " + dot(a, ka));
            }
        }
    }

    @Test
    void aContactFollowerThatDoesNotTouchTakesNoTangent() {
        Case c = SlidingCases.random(7, 5, 10);
        double[] far = new double[c.followers().length];
        java.util.Arrays.fill(far, -1); // held beyond 1 m below: no follower touches
        SurfaceSliding s = new SurfaceSliding(c.followers(), c.mapping(), c.triangles(), c.stiffness(), Mode.CONTACT,
                far, c.x());
        s.linearise(0, c.x());
        double[] z = randomVector(new Random(7), c.x().length);
        double[] kz = new double[z.length];
        s.multiplyAdd(z, kz, null, 1);
        assertEquals(0, Math.sqrt(dot(kz, kz)), 0, "no contact, no stiffness");
    }

    @Test
    void productsOnALayoutWithNodesLeftOutEqualTheFullProductRestricted() {
        Case c = SlidingCases.random(11, 5, 10);
        SurfaceSliding s = c.term(Mode.SLIDING);
        s.linearise(0, c.x());
        int nodes = c.x().length / 3;
        Random r = new Random(11);
        int[] offset = new int[nodes];
        int next = 0;
        for (int j = 0; j < nodes; j++) {
            offset[j] = r.nextInt(4) == 0 ? -1 : 3 * next++; // a quarter left out, the rest packed in order
        }
        double[] zPacked = randomVector(r, 3 * next);
        double[] zFull = new double[3 * nodes];
        for (int j = 0; j < nodes; j++) {
            if (offset[j] >= 0) {
                System.arraycopy(zPacked, offset[j], zFull, 3 * j, 3);
            }
        }
        double[] yFull = new double[3 * nodes];
        s.multiplyAdd(zFull, yFull, null, 2.5);
        double[] yPacked = new double[3 * next];
        s.multiplyAdd(zPacked, yPacked, offset, 2.5);
        for (int j = 0; j < nodes; j++) {
            for (int a = 0; offset[j] >= 0 && a < 3; a++) {
                assertEquals(yFull[3 * j + a], yPacked[offset[j] + a], 1e-12 * (1 + Math.abs(yFull[3 * j + a])),
                        "node " + j + " axis " + a);
            }
        }
    }

    @Test
    void theIsotropicPartIsTheTraceOfEachDiagonalBlockOverThree() {
        Case c = SlidingCases.random(13, 5, 10); // each surface node carries one point: no two corners share one
        SurfaceSliding s = c.term(Mode.SLIDING);
        s.linearise(0, c.x());
        int nodes = c.x().length / 3;
        double[] iso = new double[nodes];
        s.addIsotropicStiffness(iso);
        double total = 0;
        for (int j = 0; j < nodes; j++) {
            double trace = 0;
            for (int a = 0; a < 3; a++) {
                double[] e = new double[3 * nodes];
                e[3 * j + a] = 1;
                double[] ke = new double[3 * nodes];
                s.multiplyAdd(e, ke, null, 1);
                trace += ke[3 * j + a];
            }
            assertEquals(trace / 3, iso[j], 1e-12 * (1 + trace), "node " + j);
            total += iso[j];
        }
        assertTrue(total > 0, "the followers and their corners get stiffness");
    }

    /**
     * A 10 g node held on a surface moving up and down and sliding sideways, with k = 1e5 N/m: the explicit limit
     * 2 sqrt(m / k) is 0.63 ms. bdf2 at 5 ms (8 times that) with the tangent keeps it within F / k of the surface
     * and frictionless; the same term stripped of its tangent runs away.
     */
    @Test
    void bdf2HoldsAStiffCouplingAtStepsFarAboveTheExplicitLimit() {
        double m = 0.01;
        double k = 1e5;
        double dt = 5e-3;
        assertTrue(dt > 5 * 2 * Math.sqrt(m / k), "the step is far above the explicit limit");
        double[] with = run(m, k, dt, true);
        assertTrue(Double.isFinite(with[0]) && with[0] < 5e-5, "with the tangent |d| up to " + with[0] + " m");
        assertEquals(0.003, with[1], 1e-6, "frictionless: the surface slid 0.1 m under the node, which stays");
        double[] without = run(m, k, dt, false);
        assertTrue(!(without[0] < 1e-3), "without a tangent the node leaves the surface: |d| up to " + without[0]);
    }

    /** [max |d| (m) over 20 s, or NaN/inf on divergence; the node's final x (m)]. */
    private static double[] run(double m, double k, double dt, boolean tangent) {
        double amp = 0.02;
        double w = 2 * Math.PI;
        double slide = 0.005; // m/s
        Topology t = new Topology();
        double[][] corners = {{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}};
        for (double[] c : corners) {
            t.addNode(c[0], c[1], 0, 0.001).drive((time, rest, out, o) -> {
                out[o] = rest.x() + slide * time;
                out[o + 1] = rest.y();
                out[o + 2] = rest.z() + amp * Math.sin(w * time);
            });
        }
        t.addNode(0.003, 0.001, -m * 9.81 / k, m);
        t.setGravity(new Vec3(0, 0, -9.81));
        t.setViscousDamping(0.01);
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create("bdf2"));
        sim = sim.apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
        LinearMapping.Builder map = new LinearMapping.Builder(5);
        for (int i = 0; i < 4; i++) {
            map.add(new int[] {i}, new double[] {1});
        }
        SurfaceSliding term = new SurfaceSliding(new int[] {4}, map.build(), new int[] {0, 1, 2, 0, 2, 3},
                new double[] {k}, Mode.SLIDING, 0, sim.state().x);
        sim.forces().addTerm(tangent ? term : (ForceTerm) term::addForces);
        double worst = 0;
        try {
            for (int step = 1; step * dt <= 20 + 1e-9; step++) {
                sim.step(dt);
                double d = sim.state().x[14] - amp * Math.sin(w * sim.time());
                worst = Math.max(worst, Double.isNaN(d) ? Double.POSITIVE_INFINITY : Math.abs(d));
            }
        } catch (SimulationDivergedException | ArithmeticException e) {
            return new double[] {Double.POSITIVE_INFINITY, Double.NaN};
        }
        return new double[] {worst, sim.state().x[12]};
    }
}
