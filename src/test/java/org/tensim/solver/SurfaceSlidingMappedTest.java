package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.solver.SlidingCases.Case;
import org.tensim.solver.SurfaceSliding.Mode;

/**
 * Followers that are points mapped from the state's nodes ({@link SurfaceSliding#mapped}): a lung's surface vertices
 * carried by its lattice. Each case's follower e becomes the point {@code y_e = 0.8 A_e + 0.2 H}, its own node A_e
 * and one hub node H shared by all (so the rows share a node and the tangent's merged rows add on it), with A_e
 * placed so that y_e is where the node follower was. The forces are minus the energy's gradient by central
 * differences; total force and moment vanish at the nodes; the tangent is the forces' Jacobian at the gaps; the
 * forces on the points are the node followers' forces at the same places, carried by the weights.
 */
class SurfaceSlidingMappedTest {
    private static final double OWN = 0.8;

    /** The case's positions with a hub node appended, its followers' nodes placed to put the points at x's. */
    private record Mapped(double[] x, LinearMapping followers, int hub) {
    }

    private static Mapped mapped(Case c, double[] x) {
        int nodes = x.length / 3;
        double[] y = java.util.Arrays.copyOf(x, 3 * nodes + 3);
        int hub = nodes;
        double[] h = {0, 0, 0};
        for (int f : c.followers()) {
            for (int a = 0; a < 3; a++) {
                h[a] += x[3 * f + a] / c.followers().length;
            }
        }
        for (int a = 0; a < 3; a++) {
            y[3 * hub + a] = h[a] + 0.01;
        }
        LinearMapping.Builder b = new LinearMapping.Builder(nodes + 1);
        for (int f : c.followers()) {
            for (int a = 0; a < 3; a++) {
                y[3 * f + a] = (x[3 * f + a] - (1 - OWN) * y[3 * hub + a]) / OWN;
            }
            b.add(new int[] {f, hub}, new double[] {OWN, 1 - OWN});
        }
        return new Mapped(y, b.build(), hub);
    }

    private static double[] forces(SurfaceSliding s, double[] x) {
        double[] f = new double[x.length];
        s.addForces(0, x, new double[x.length], f);
        return f;
    }

    @Test
    void theForcesAreMinusTheEnergysGradientAndCarryNoNetForceOrMoment() {
        for (Mode mode : Mode.values()) {
            for (long seed = 1; seed <= 5; seed++) {
                Case c = SlidingCases.random(900 + seed, 5, 8);
                double[] x0 = c.x().clone();
                SlidingCases.overPairedTriangles(c, c.term(mode), x0, new Random(seed));
                Mapped m = mapped(c, x0);
                SurfaceSliding s = SurfaceSliding.mapped(m.followers(), c.mapping(), c.triangles(), c.stiffness(),
                        mode, c.gaps(), m.x());
                double[] x = m.x();
                double[] f = forces(s, x);
                double h = 1e-7;
                double fmax = 0;
                double worst = 0;
                for (int k = 0; k < x.length; k++) {
                    double keep = x[k];
                    x[k] = keep + h;
                    double ep = s.energy(0, x);
                    x[k] = keep - h;
                    double em = s.energy(0, x);
                    x[k] = keep;
                    worst = Math.max(worst, Math.abs(-(ep - em) / (2 * h) - f[k]));
                    fmax = Math.max(fmax, Math.abs(f[k]));
                }
                assertTrue(fmax > 1e-3, mode + " seed " + seed + ": forces " + fmax + " N");
                assertTrue(Math.abs(f[3 * m.hub()]) + Math.abs(f[3 * m.hub() + 1]) > 0, "the hub is pushed");
                assertTrue(worst < 1e-8 * fmax, mode + " seed " + seed + ": |f + dE/dx| = " + worst + " N");
                double[] net = new double[6];
                for (int j = 0; 3 * j < x.length; j++) {
                    double fx = f[3 * j], fy = f[3 * j + 1], fz = f[3 * j + 2];
                    double px = x[3 * j], py = x[3 * j + 1], pz = x[3 * j + 2];
                    net[0] += fx;
                    net[1] += fy;
                    net[2] += fz;
                    net[3] += py * fz - pz * fy;
                    net[4] += pz * fx - px * fz;
                    net[5] += px * fy - py * fx;
                }
                for (int a = 0; a < 6; a++) {
                    assertEquals(0, net[a], 1e-12 * fmax, mode + " seed " + seed + ": net " + (a < 3 ? "force"
                            : "moment") + " component " + a % 3);
                }
            }
        }
    }

    @Test
    void eachPointsForceIsTheNodeFollowersForceThereSharedByTheWeights() {
        Case c = SlidingCases.random(950, 6, 12);
        SurfaceSliding nodes = c.term(Mode.SLIDING);
        double[] fn = forces(nodes, c.x());
        Mapped m = mapped(c, c.x());
        SurfaceSliding points = SurfaceSliding.mapped(m.followers(), c.mapping(), c.triangles(), c.stiffness(),
                Mode.SLIDING, c.gaps(), m.x());
        double[] fp = forces(points, m.x());
        double[] hub = new double[3];
        for (int e = 0; e < c.followers().length; e++) {
            int i = 3 * c.followers()[e];
            assertEquals(nodes.pairedTriangle(e), points.pairedTriangle(e), "follower " + e + "'s triangle");
            for (int a = 0; a < 3; a++) {
                assertEquals(OWN * fn[i + a], fp[i + a], 1e-12 * (1 + Math.abs(fn[i + a])), "follower " + e);
                hub[a] += (1 - OWN) * fn[i + a];
            }
        }
        for (int a = 0; a < 3; a++) {
            assertEquals(hub[a], fp[3 * m.hub() + a], 1e-12 * (1 + Math.abs(hub[a])), "the hub's share");
        }
        assertThrows(IllegalStateException.class, () -> points.follower(0));
        assertEquals(c.followers()[3], nodes.follower(3));
    }

    @Test
    void atTheGapsTheTangentIsTheForcesJacobianAndSymmetric() {
        for (Mode mode : Mode.values()) {
            for (long seed = 1; seed <= 4; seed++) {
                Case c = SlidingCases.random(980 + seed, 5, 10);
                double[] x0 = c.x().clone();
                SlidingCases.overPairedTriangles(c, c.term(mode), x0, new Random(seed));
                Mapped m = mapped(c, x0);
                double[] x = m.x();
                SurfaceSliding probe = SurfaceSliding.mapped(m.followers(), c.mapping(), c.triangles(),
                        c.stiffness(), mode, c.gaps(), x);
                double[] d = new double[probe.pairCount()];
                probe.distancesM(x, d);
                for (int e = 0; e < d.length; e++) {
                    d[e] = Double.isNaN(d[e]) ? 0 : d[e] + (mode == Mode.CONTACT ? 1e-7 : 0);
                }
                SurfaceSliding s = SurfaceSliding.mapped(m.followers(), c.mapping(), c.triangles(), c.stiffness(),
                        mode, d, x);
                s.linearise(0, x);
                Random r = new Random(seed);
                double[] z = new double[x.length];
                double[] w = new double[x.length];
                for (int i = 0; i < z.length; i++) {
                    z[i] = r.nextGaussian();
                    w[i] = r.nextGaussian();
                }
                double[] kz = new double[x.length];
                double[] kw = new double[x.length];
                s.multiplyAdd(z, kz, null, 1);
                s.multiplyAdd(w, kw, null, 1);
                double h = 1e-8;
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
                double wkz = 0;
                double zkw = 0;
                for (int i = 0; i < x.length; i++) {
                    worst = Math.max(worst, Math.abs(-(fp[i] - fm[i]) / (2 * h) - kz[i]));
                    scale = Math.max(scale, Math.abs(kz[i]));
                    wkz += w[i] * kz[i];
                    zkw += z[i] * kw[i];
                }
                assertTrue(scale > 1, mode + " seed " + seed + ": K z has " + scale + " N/m");
                assertTrue(worst < 1e-4 * scale, mode + " seed " + seed + ": |K z + df/dx z| = " + worst);
                assertEquals(wkz, zkw, 1e-10 * (Math.abs(wkz) + scale), mode + " seed " + seed + ": symmetric");
            }
        }
    }

    @Test
    void aMappedFollowerOnANodeOfTheSurfaceIsRefused() {
        Case c = SlidingCases.random(990, 4, 3);
        LinearMapping.Builder b = new LinearMapping.Builder(c.x().length / 3);
        for (int f : c.followers()) {
            b.add(new int[] {f, 1}, new double[] {0.5, 0.5}); // node 1 carries surface point 0
        }
        LinearMapping bad = b.build();
        String out = assertThrows(IllegalArgumentException.class, () -> SurfaceSliding.mapped(bad, c.mapping(),
                c.triangles(), c.stiffness(), Mode.SLIDING, c.gaps(), c.x())).getMessage();
        assertTrue(out.contains("follower 0 (node 1) carries a point of the surface"), out);
    }
}
