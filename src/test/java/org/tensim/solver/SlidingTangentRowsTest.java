package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.solver.SlidingCases.Case;
import org.tensim.solver.SurfaceSliding.Mode;
import org.tensim.testsupport.AllocationCounter;

/**
 * The sliding tangent's merged rows on a surface whose points are blended over their neighbours' carriers (as the
 * pleura's are), so that a triangle's three corner rows share most of their nodes: the products equal the unmerged
 * formula walked corner by corner, also after the followers move to other triangles between linearisations; the
 * isotropic part is the trace of K's diagonal blocks over 3 probed with unit vectors; no allocation.
 */
class SlidingTangentRowsTest {
    private static final int G = 5;

    /**
     * A case of {@link SlidingCases#random} whose point p is re-carried by 0.4 of its own row plus 0.6 spread evenly
     * over the rows of its grid neighbours (up to 8): overlapping rows of 6-18 entries, weights summing to 1.
     */
    private static Case blended(long seed, int followers) {
        Case c = SlidingCases.random(seed, G, followers);
        LinearMapping m = c.mapping();
        LinearMapping.Builder b = new LinearMapping.Builder(m.nodeCount());
        for (int i = 0; i < G; i++) {
            for (int j = 0; j < G; j++) {
                int[] around = new int[9];
                int count = 0;
                for (int di = -1; di <= 1; di++) {
                    for (int dj = -1; dj <= 1; dj++) {
                        boolean inside = i + di >= 0 && i + di < G && j + dj >= 0 && j + dj < G;
                        if ((di != 0 || dj != 0) && inside) {
                            around[count++] = (i + di) * G + j + dj;
                        }
                    }
                }
                int own = i * G + j;
                int entries = m.entries(own) * (count + 1);
                int[] nodes = new int[entries];
                double[] weights = new double[entries];
                int k = 0;
                for (int q = -1; q < count; q++) {
                    int p = q < 0 ? own : around[q];
                    double share = q < 0 ? 0.4 : 0.6 / count;
                    for (int r = 0; r < m.entries(p); r++) {
                        nodes[k] = m.node(p, r);
                        weights[k++] = share * m.weight(p, r);
                    }
                }
                b.add(nodes, weights);
            }
        }
        return new Case(c.x(), c.followers(), b.build(), c.triangles(), c.stiffness(), c.gaps());
    }

    private static SurfacePairing pairing(Case c) {
        return new SurfacePairing(c.triangles(), c.mapping().pointCount());
    }

    /** A random plane record (unit normal, distance, barycentric coordinates summing to 1, one may be negative). */
    private static double[] randomPlane(Random r) {
        double[] p = new double[7];
        double len = 0;
        for (int a = 0; a < 3; a++) {
            p[a] = r.nextGaussian();
            len += p[a] * p[a];
        }
        for (int a = 0; a < 3; a++) {
            p[a] /= Math.sqrt(len);
        }
        p[3] = 0.001 * r.nextGaussian();
        p[4] = 1.4 * r.nextDouble() - 0.2;
        p[5] = (1 - p[4]) * r.nextDouble();
        p[6] = 1 - p[4] - p[5];
        return p;
    }

    /**
     * {@code y += w K z} by the formula corner by corner, each corner's row walked on its own (what the merged row
     * must equal): u = z_i - sum_c beta_c sum_k W_ck z_k, y_i += w k n (n . u), y_k -= w k beta_c W_ck n (n . u).
     */
    private static void unmerged(Case c, int[] tri, double[][] planes, double[] z, double[] y, double w) {
        LinearMapping m = c.mapping();
        for (int e = 0; e < tri.length; e++) {
            if (tri[e] < 0) {
                continue;
            }
            double[] pl = planes[e];
            int i = 3 * c.followers()[e];
            double nu = pl[0] * z[i] + pl[1] * z[i + 1] + pl[2] * z[i + 2];
            for (int corner = 0; corner < 3; corner++) {
                int p = c.triangles()[3 * tri[e] + corner];
                for (int k = 0; k < m.entries(p); k++) {
                    int o = 3 * m.node(p, k);
                    nu -= pl[4 + corner] * m.weight(p, k) * (pl[0] * z[o] + pl[1] * z[o + 1] + pl[2] * z[o + 2]);
                }
            }
            double s = w * c.stiffness()[e] * nu;
            for (int a = 0; a < 3; a++) {
                y[i + a] += s * pl[a];
            }
            for (int corner = 0; corner < 3; corner++) {
                int p = c.triangles()[3 * tri[e] + corner];
                for (int k = 0; k < m.entries(p); k++) {
                    int o = 3 * m.node(p, k);
                    for (int a = 0; a < 3; a++) {
                        y[o + a] -= s * pl[4 + corner] * m.weight(p, k) * pl[a];
                    }
                }
            }
        }
    }

    private static double[] gaussian(Random r, int n) {
        double[] z = new double[n];
        for (int i = 0; i < n; i++) {
            z[i] = r.nextGaussian();
        }
        return z;
    }

    /** max |a - b| over max |b|. */
    private static double relative(double[] a, double[] b) {
        double worst = 0;
        double scale = 0;
        for (int i = 0; i < a.length; i++) {
            worst = Math.max(worst, Math.abs(a[i] - b[i]));
            scale = Math.max(scale, Math.abs(b[i]));
        }
        assertTrue(scale > 0, "the product acts");
        return worst / scale;
    }

    @Test
    void mergedProductsEqualTheCornerByCornerFormulaAcrossTriangleChanges() {
        for (long seed = 1; seed <= 5; seed++) {
            Case c = blended(500 + seed, 12);
            SurfacePairing surface = pairing(c);
            SlidingTangent tangent = new SlidingTangent(SlidingChecks.nodeFollowers(c.followers(),
                c.x().length / 3), c.stiffness(), c.mapping(), surface);
            Random r = new Random(seed);
            int followers = c.followers().length;
            int[] tri = new int[followers];
            double[][] planes = new double[followers][];
            for (int round = 0; round < 4; round++) { // each round: every follower on another triangle, or none
                for (int e = 0; e < followers; e++) {
                    int before = tri[e];
                    tri[e] = r.nextInt(8) == 0 ? -1 : r.nextInt(surface.triangleCount());
                    if (round > 0 && tri[e] == before) {
                        tri[e] = (before + 1) % surface.triangleCount();
                    }
                    planes[e] = randomPlane(r);
                    tangent.set(e, tri[e], planes[e]);
                }
                double[] z = gaussian(r, c.x().length);
                double[] merged = new double[z.length];
                double[] direct = new double[z.length];
                tangent.multiplyAdd(z, merged, null, 1.7);
                unmerged(c, tri, planes, z, direct, 1.7);
                double rel = relative(merged, direct);
                assertTrue(rel < 1e-12, "seed " + seed + " round " + round + ": relative difference " + rel);
            }
        }
    }

    @Test
    void theBlendedRowsOverlap() {
        Case c = blended(501, 12);
        int[] t = c.triangles();
        LinearMapping m = c.mapping();
        java.util.Set<Integer> union = new java.util.HashSet<>();
        int sum = 0;
        for (int corner = 0; corner < 3; corner++) {
            for (int k = 0; k < m.entries(t[corner]); k++) {
                union.add(m.node(t[corner], k));
                sum++;
            }
        }
        assertTrue(union.size() < sum * 2 / 3, "triangle 0's rows: " + sum + " entries over " + union.size()
                + " nodes");
    }

    @Test
    void theIsotropicPartIsTheTraceOfKsDiagonalBlocksOverThreeWhereCornersShareNodes() {
        Case c = blended(601, 10);
        SurfaceSliding s = c.term(Mode.SLIDING);
        s.linearise(0, c.x());
        int nodes = c.x().length / 3;
        double[] iso = new double[nodes];
        s.addIsotropicStiffness(iso);
        double[] perCornerSquares = new double[nodes]; // sum over corner entries of (beta_c W_cj)^2 k / 3
        SurfacePairing surface = pairing(c);
        double[] points = new double[3 * c.mapping().pointCount()];
        c.mapping().apply(c.x(), points);
        double[] plane = new double[8];
        for (int e = 0; e < s.pairCount(); e++) {
            int t = surface.walk(points, s.pairedTriangle(e), c.x(), 3 * s.follower(e), plane);
            for (int corner = 0; corner < 3; corner++) {
                int p = c.triangles()[3 * t + corner];
                for (int k = 0; k < c.mapping().entries(p); k++) {
                    double bw = plane[4 + corner] * c.mapping().weight(p, k);
                    perCornerSquares[c.mapping().node(p, k)] += bw * bw * s.stiffness(e) / 3;
                }
            }
        }
        double apart = 0;
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
            apart = Math.max(apart, Math.abs(perCornerSquares[j] - trace / 3) / (1 + trace));
        }
        assertTrue(apart > 1e-3, "the corners' squares summed differ from the trace here: " + apart);
    }

    @Test
    void settingAndProductsDoNotAllocate() {
        Case c = blended(701, 12);
        SurfacePairing surface = pairing(c);
        SlidingTangent tangent = new SlidingTangent(SlidingChecks.nodeFollowers(c.followers(),
                c.x().length / 3), c.stiffness(), c.mapping(), surface);
        Random r = new Random(7);
        double[][] planes = new double[16][];
        for (int i = 0; i < planes.length; i++) {
            planes[i] = randomPlane(r);
        }
        double[] z = gaussian(r, c.x().length);
        double[] y = new double[z.length];
        double[] iso = new double[z.length / 3];
        int[] turn = {0};
        Runnable pass = () -> {
            for (int e = 0; e < c.followers().length; e++) {
                int k = turn[0]++;
                tangent.set(e, k % surface.triangleCount(), planes[k % planes.length]);
            }
            tangent.multiplyAdd(z, y, null, 1);
            tangent.addIsotropicStiffness(iso);
        };
        for (int warm = 0; warm < 2000; warm++) {
            pass.run();
        }
        assertEquals(0, AllocationCounter.currentThread().bytesAllocatedBy(pass, 5));
    }
}
