package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.solver.SlidingCases.Case;
import org.tensim.solver.SurfaceSliding.Mode;
import org.tensim.testsupport.AllocationCounter;

/**
 * The sliding term's forces on seeded random configurations (a bumpy mapped surface turned anyhow, followers above
 * and below it): Newton's third law (total force and moment), forces = -grad E by central differences, along the
 * normal (the closest point's direction past a triangle's rim: {@link SlidingCases#frame}) only with the magnitude
 * k (g - d), the nearest triangle, the walk, no allocation, and the refusals.
 */
class SurfaceSlidingTest {
    private static final int SEEDS = 20;

    private static double[] forces(SurfaceSliding s, double[] x) {
        double[] f = new double[x.length];
        s.addForces(0, x, new double[x.length], f);
        return f;
    }

    @Test
    void totalForceAndMomentVanishForAnyConfiguration() {
        for (Mode mode : Mode.values()) {
            for (long seed = 1; seed <= SEEDS; seed++) {
                Case c = SlidingCases.random(seed, 6, 12);
                SurfaceSliding s = c.term(mode);
                double[] f = forces(s, c.x());
                double[] sum = new double[3];
                double[] moment = new double[3];
                double scale = 0;
                double lever = 0;
                for (int j = 0; 3 * j < f.length; j++) {
                    double[] xj = {c.x()[3 * j], c.x()[3 * j + 1], c.x()[3 * j + 2]};
                    double[] fj = {f[3 * j], f[3 * j + 1], f[3 * j + 2]};
                    for (int a = 0; a < 3; a++) {
                        sum[a] += fj[a];
                        moment[a] += xj[(a + 1) % 3] * fj[(a + 2) % 3] - xj[(a + 2) % 3] * fj[(a + 1) % 3];
                    }
                    double fn = Math.sqrt(fj[0] * fj[0] + fj[1] * fj[1] + fj[2] * fj[2]);
                    scale += fn;
                    lever += fn * Math.sqrt(xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2]);
                }
                assertTrue(scale > 1e-3, mode + " seed " + seed + ": the case has forces (" + scale + " N)");
                for (int a = 0; a < 3; a++) {
                    assertEquals(0, sum[a], 1e-13 * scale, mode + " seed " + seed + ": total force");
                    assertEquals(0, moment[a], 1e-13 * lever, mode + " seed " + seed + ": total moment");
                }
            }
        }
    }

    @Test
    void forcesAreMinusTheEnergyGradientByCentralDifferences() {
        for (Mode mode : Mode.values()) {
            for (long seed = 1; seed <= 6; seed++) {
                Case c = SlidingCases.random(100 + seed, 5, 8);
                SurfaceSliding s = c.term(mode);
                double[] x = c.x().clone();
                SlidingCases.overPairedTriangles(c, s, x, new java.util.Random(seed));
                double[] f = forces(s, x);
                double h = 1e-7; // m, against positions of 0.1 m: round-off ~1e-16 E / h, truncation ~h^2
                double fmax = 0;
                double worst = 0;
                for (int k = 0; k < x.length; k++) {
                    double x0 = x[k];
                    x[k] = x0 + h;
                    double ep = s.energy(0, x);
                    x[k] = x0 - h;
                    double em = s.energy(0, x);
                    x[k] = x0;
                    worst = Math.max(worst, Math.abs(-(ep - em) / (2 * h) - f[k]));
                    fmax = Math.max(fmax, Math.abs(f[k]));
                }
                assertTrue(fmax > 1e-3, mode + " seed " + seed + ": forces " + fmax + " N");
                assertTrue(worst < 1e-8 * fmax, mode + " seed " + seed + ": |f + dE/dx| = " + worst + " N against "
                        + fmax + " N");
            }
        }
    }

    @Test
    void theFollowersForceIsAlongTheNormalWithMagnitudeKTimesGapMinusDistance() {
        for (long seed = 1; seed <= SEEDS; seed++) {
            Case c = SlidingCases.random(200 + seed, 6, 12);
            SurfaceSliding s = c.term(Mode.SLIDING);
            double[] f = forces(s, c.x());
            for (int e = 0; e < s.pairCount(); e++) {
                int i = 3 * c.followers()[e];
                double[] na = SlidingCases.frame(c, c.x(), s.pairedTriangle(e), i);
                double d = na[3];
                double expected = c.stiffness()[e] * (c.gaps()[e] - d);
                double along = f[i] * na[0] + f[i + 1] * na[1] + f[i + 2] * na[2];
                assertEquals(expected, along, 1e-12 * c.stiffness()[e] * 0.01, "seed " + seed + " follower " + e);
                for (int a = 0; a < 3; a++) {
                    assertEquals(0, f[i + a] - along * na[a], 1e-14, "seed " + seed + " follower " + e
                            + ": no tangential force (frictionless)");
                }
            }
        }
    }

    @Test
    void contactPushesOutOnlyThePenetratingFollowersAndLeavesTheOthersFree() {
        int pushed = 0;
        int free = 0;
        for (long seed = 1; seed <= SEEDS; seed++) {
            Case c = SlidingCases.random(300 + seed, 6, 12);
            SurfaceSliding s = c.term(Mode.CONTACT);
            double[] f = forces(s, c.x());
            for (int e = 0; e < s.pairCount(); e++) {
                int i = 3 * c.followers()[e];
                double[] na = SlidingCases.frame(c, c.x(), s.pairedTriangle(e), i);
                double d = na[3];
                double along = f[i] * na[0] + f[i + 1] * na[1] + f[i + 2] * na[2];
                double pen = c.gaps()[e] - d;
                if (pen > 0) {
                    assertEquals(c.stiffness()[e] * pen, along, 1e-12, "seed " + seed + " follower " + e);
                    pushed++;
                } else {
                    assertEquals(0, Math.abs(f[i]) + Math.abs(f[i + 1]) + Math.abs(f[i + 2]), 0);
                    free++;
                }
            }
        }
        assertTrue(pushed > 20 && free > 20, pushed + " pushed, " + free + " free: the cases have both");
    }

    @Test
    void eachFollowerIsPairedWithItsNearestTriangle() {
        for (long seed = 1; seed <= SEEDS; seed++) {
            Case c = SlidingCases.random(400 + seed, 6, 12);
            SurfaceSliding s = c.term(Mode.SLIDING);
            SurfacePairing pairing = new SurfacePairing(c.triangles(), c.mapping().pointCount());
            double[] p = new double[3 * c.mapping().pointCount()];
            c.mapping().apply(c.x(), p);
            for (int e = 0; e < s.pairCount(); e++) {
                int i = 3 * c.followers()[e];
                double mine = pairing.closestDistance2(p, s.pairedTriangle(e), c.x(), i);
                for (int t = 0; t < pairing.triangleCount(); t++) {
                    assertTrue(mine <= pairing.closestDistance2(p, t, c.x(), i), "seed " + seed + " follower " + e);
                }
            }
        }
    }

    @Test
    void theWalkFollowsASurfaceSlidingUnderTheFollowersAcrossManyTriangles() {
        Case c = SlidingCases.random(7, 8, 10);
        SurfaceSliding s = c.term(Mode.SLIDING);
        double[] x = c.x().clone();
        double[] f = new double[x.length];
        double[] v = new double[x.length];
        // Carry the surface's nodes 3 spacings along the grid's first axis (0 -> point g), 1/20 spacing a call.
        int g = 8;
        double[] p = new double[3 * c.mapping().pointCount()];
        c.mapping().apply(x, p);
        double[] axis = {p[3 * g] - p[0], p[3 * g + 1] - p[1], p[3 * g + 2] - p[2]};
        for (int call = 0; call < 60; call++) {
            for (int j = 0; j < 2 * g * g; j++) {
                for (int a = 0; a < 3; a++) {
                    x[3 * j + a] += axis[a] / 20;
                }
            }
            s.addForces(0, x, v, f);
        }
        SurfacePairing pairing = new SurfacePairing(c.triangles(), c.mapping().pointCount());
        c.mapping().apply(x, p);
        pairing.bound(p);
        SurfaceSliding fresh = c.term(Mode.SLIDING);
        int moved = 0;
        for (int e = 0; e < s.pairCount(); e++) {
            int i = 3 * c.followers()[e];
            int nearest = pairing.nearest(p, x, i);
            assertEquals(pairing.closestDistance2(p, nearest, x, i), pairing.closestDistance2(p, s.pairedTriangle(e),
                    x, i), 1e-18, "follower " + e + " walked to its nearest triangle");
            moved += fresh.pairedTriangle(e) != s.pairedTriangle(e) ? 1 : 0;
        }
        assertTrue(moved >= s.pairCount() / 2, moved + " of " + s.pairCount() + " followers changed triangle");
    }

    @Test
    void heldAtRestTheFollowersStartWithoutForceAtTheirRestDistances() {
        Case c = SlidingCases.random(13, 6, 12);
        SurfaceSliding sliding = SurfaceSliding.heldAtRest(c.followers(), c.mapping(), c.triangles(), c.stiffness(),
                Mode.SLIDING, 0, c.x());
        assertEquals(0, sliding.energy(0, c.x()), 1e-30);
        assertTrue(java.util.Arrays.stream(forces(sliding, c.x())).allMatch(v -> Math.abs(v) < 1e-15));
        SurfaceSliding contact = SurfaceSliding.heldAtRest(c.followers(), c.mapping(), c.triangles(), c.stiffness(),
                Mode.CONTACT, 0.001, c.x());
        int capped = 0;
        for (int e = 0; e < sliding.pairCount(); e++) {
            double d0 = sliding.gapM(e);
            assertEquals(Math.min(0.001, d0), contact.gapM(e), 0, "follower " + e);
            capped += d0 > 0.001 ? 1 : 0;
        }
        assertTrue(capped > 0 && capped < sliding.pairCount(), capped + " followers start beyond the 1 mm gap");
        assertEquals(0, contact.maxPenetrationM(c.x()), 1e-18);
    }

    @Test
    void readOutsGiveTheLargestPenetrationAndSeparation() {
        Case c = SlidingCases.random(11, 6, 12);
        SurfaceSliding s = c.term(Mode.SLIDING);
        double pen = 0;
        double sep = 0;
        int deepest = -1;
        int farthest = -1;
        for (int e = 0; e < s.pairCount(); e++) {
            int i = 3 * c.followers()[e];
            double[] na = SlidingCases.normalAndCorner(c, c.x(), s.pairedTriangle(e));
            double d = na[0] * (c.x()[i] - na[3]) + na[1] * (c.x()[i + 1] - na[4]) + na[2] * (c.x()[i + 2] - na[5]);
            deepest = c.gaps()[e] - d > pen ? e : deepest;
            pen = Math.max(pen, c.gaps()[e] - d);
            farthest = d - c.gaps()[e] > sep ? e : farthest;
            sep = Math.max(sep, d - c.gaps()[e]);
        }
        assertTrue(pen > 0 && sep > 0);
        assertEquals(pen, s.maxPenetrationM(c.x()), 1e-15);
        assertEquals(sep, s.maxSeparationM(c.x()), 1e-15);
        assertEquals(12, s.pairCount());
        double[] at = s.extremeAt(c.x(), 1);
        double[] away = s.extremeAt(c.x(), -1);
        assertEquals(pen, at[0], 1e-15);
        assertEquals(sep, away[0], 1e-15);
        for (int a = 0; a < 3; a++) {
            assertEquals(c.x()[3 * c.followers()[deepest] + a], at[1 + a], 0, "the deepest follower's place");
            assertEquals(c.x()[3 * c.followers()[farthest] + a], away[1 + a], 0, "the farthest follower's place");
        }
    }

    @Test
    void theForcePassDoesNotAllocate() {
        Case c = SlidingCases.random(5, 8, 30);
        SurfaceSliding s = c.term(Mode.CONTACT);
        double[] x = c.x().clone();
        double[] v = new double[x.length];
        double[] f = new double[x.length];
        Runnable pass = () -> {
            for (int k = 0; k < 50; k++) {
                x[k % x.length] += 1e-5; // moves points and followers: walks happen
                s.addForces(0, x, v, f);
            }
        };
        for (int warm = 0; warm < 200; warm++) {
            pass.run();
        }
        assertEquals(0, AllocationCounter.currentThread().bytesAllocatedBy(pass, 5));
    }

    @Test
    void badInputIsRefusedNamingTheValue() {
        Case c = SlidingCases.random(3, 4, 3);
        double[] x = c.x();
        LinearMapping m = c.mapping();
        int[] tri = c.triangles();
        double[] k = c.stiffness();
        String out = assertThrows(IllegalArgumentException.class, () -> new SurfaceSliding(new int[] {0, 1, 2}, m,
                tri, k, Mode.SLIDING, 0, x)).getMessage();
        assertTrue(out.contains("follower 0 (node 0) carries a point"), out);
        int[] twice = {c.followers()[0], c.followers()[0], c.followers()[1]};
        out = assertThrows(IllegalArgumentException.class, () -> new SurfaceSliding(twice, m, tri, k, Mode.SLIDING,
                0, x)).getMessage();
        assertTrue(out.contains("listed twice"), out);
        double[] bad = {k[0], -1, k[2]};
        out = assertThrows(IllegalArgumentException.class, () -> new SurfaceSliding(c.followers(), m, tri, bad,
                Mode.CONTACT, 0, x)).getMessage();
        assertTrue(out.contains("follower 1") && out.contains("-1.0 N/m"), out);
        int[] outOfRange = tri.clone();
        outOfRange[4] = 99;
        out = assertThrows(IllegalArgumentException.class, () -> new SurfaceSliding(c.followers(), m, outOfRange, k,
                Mode.CONTACT, 0, x)).getMessage();
        assertTrue(out.contains("triangle 1 has point 99"), out);
        out = assertThrows(IllegalArgumentException.class, () -> new SurfaceSliding(c.followers(), m, tri, k,
                Mode.CONTACT, Double.NaN, x)).getMessage();
        assertTrue(out.contains("gap NaN m"), out);
    }
}
