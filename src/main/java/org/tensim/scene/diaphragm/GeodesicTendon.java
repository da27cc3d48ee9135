package org.tensim.scene.diaphragm;

import java.util.Arrays;
import java.util.PriorityQueue;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The central tendon as the region of the upper surface nearest, along the surface, to a few
 * seed points: vertices are taken in order of their geodesic distance to the nearest seed until
 * their area reaches a share F of the upper surface's, and each lower-surface vertex takes the
 * label of its paired upper vertex ({@link TwoSurfaces#partner}).
 *
 * <p><b>A stand-in.</b> The real central tendon is a trefoil (three leaflets: right, left,
 * anterior) in the middle of the diaphragm, making 10-15 % of its surface (du Plessis et al.,
 * Surg Radiol Anat 2015). With seeds at the two dome tops and the midpoint between them
 * ({@link #defaultSeeds}) the union of geodesic balls is central and of the right area, which is
 * what the mechanics feel first; its outline is rounder than the leaflets, and it is no
 * anatomical segmentation. Against the scene's plane cut ({@code DiaphragmParameters.tendonNormal}),
 * it follows the surface rather than a height, so a tilted or asymmetric mesh keeps its tendon
 * around the tops instead of on whichever side is higher.
 *
 * <p><b>Distances</b> are Dijkstra's along the edges of the upper triangles (those with three
 * upper corners), m, from all seeds at once. A seed is a point {x, y} on the upper surface: the
 * corners of the upper triangle above it (the highest, where the surface folds over) start at their
 * straight distance to it, so the region does not jump with the vertex nearest to a seed when the
 * mesh changes. Edge paths overestimate true geodesics by a few per cent depending on the edges'
 * directions; the share is unaffected (it is counted in area), the outline slightly.
 *
 * <p><b>Areas</b> are {@code SurfaceGeometry.vertexAreas} (a third of every triangle a vertex
 * belongs to) summed over upper vertices, the measure the scene's tendon share uses. The last
 * vertex is taken only when that brings the share nearer to F than stopping before it, so the
 * share is within half a vertex's area of F.
 *
 * <p>Measured (GeodesicTendonTest, 2026-12): on the double dome at F = 0.10, 0.12, 0.15 the shares
 * are within 0.0005 of F at 14 and 28 rings and the regions' centroids 2.1, 1.8, 0.8 mm apart; on
 * the BodyParts3D mesh within 0.0002, geodesic radii 49-64 mm; one piece in every case.
 */
public final class GeodesicTendon {
    /**
     * The tendon's region and how it came out.
     *
     * @param tendon   per mesh vertex, true for tendon (upper and lower surfaces)
     * @param share    the tendon's share of the upper surface's area (0..1)
     * @param radiusM  geodesic distance of the farthest upper tendon vertex to its seed, m
     * @param centroid area-weighted centroid of the upper tendon vertices, {x, y, z} m
     * @param level    per mesh vertex, the signed geodesic distance to the tendon's edge, m: {@code radiusM - d}
     *                 with d the vertex's distance to its seed (a lower vertex its partner's), positive on the
     *                 tendon, not below {@code -radiusM} (unreached vertices and lower ones without a partner
     *                 take that); its zero level, interpolated linearly in each triangle, is the edge that the
     *                 muscle's fibres are clipped at, as at the paper's plane (the arrays are fresh, the
     *                 caller's to keep)
     */
    public record Region(boolean[] tendon, double share, double radiusM, double[] centroid, double[] level) {
    }

    private GeodesicTendon() {
    }

    /**
     * The tendon grown from {@link #defaultSeeds} (the dome tops and the midpoint between them).
     *
     * @param share the tendon's share F of the upper surface's area, in (0, 1): 0.10-0.15 in adults
     */
    public static Region grow(TwoSurfaces s, double share) {
        return grow(s, defaultSeeds(s), share);
    }

    /**
     * The tendon grown from the given seeds.
     *
     * @param seeds points {x, y} (m) over the upper surface; at least one
     * @param share the tendon's share F of the upper surface's area, in (0, 1)
     */
    public static Region grow(TwoSurfaces s, double[][] seeds, double share) {
        if (!(share > 0 && share < 1)) {
            throw new IllegalArgumentException("tendon area share must be in (0, 1) (a fraction of the upper"
                    + " surface's area; 0.10-0.15 in adults), got " + share);
        }
        if (seeds.length == 0) {
            throw new IllegalArgumentException("no seed for the tendon; expected at least one point {x, y} in m");
        }
        TriangleMesh m = s.mesh();
        int nv = m.vertexCount();
        int[] tri = s.upperTriangles();
        if (tri.length == 0) {
            throw new IllegalArgumentException("the mesh has no triangle with three upper corners (" + s.upperCount()
                    + " upper vertices of " + nv + "); expected an upper surface to grow the tendon on");
        }
        double[] dist = new double[nv];
        Arrays.fill(dist, Double.POSITIVE_INFINITY);
        for (int i = 0; i < seeds.length; i++) {
            double[] p = seeds[i];
            if (p == null || p.length != 2 || !Double.isFinite(p[0]) || !Double.isFinite(p[1])) {
                throw new IllegalArgumentException("tendon seed " + i + " is " + Arrays.toString(p)
                        + "; expected a point {x, y} in m with finite coordinates");
            }
            start(m, tri, p[0], p[1], dist);
        }
        int[][] adj = adjacency(m, tri);
        double[] area = SurfaceGeometry.vertexAreas(m);
        double upperArea = 0;
        for (int v = 0; v < nv; v++) {
            upperArea += s.isUpper(v) ? area[v] : 0;
        }
        double target = share * upperArea;
        boolean[] tendon = new boolean[nv];
        boolean[] done = new boolean[nv];
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        for (int v = 0; v < nv; v++) {
            if (dist[v] < Double.POSITIVE_INFINITY) {
                queue.add(new double[] {dist[v], v});
            }
        }
        double taken = 0;
        double radius = 0;
        boolean grown = false;
        while (!queue.isEmpty()) {
            double[] e = queue.poll();
            int v = (int) e[1];
            if (done[v] || e[0] > dist[v]) {
                continue; // a stale entry: v was reached by a shorter path since
            }
            done[v] = true;
            // Taking v overshoots by taken + a - target; stopping undershoots by target - taken.
            // The first vertex is always taken, so that the region is never empty. Once grown, the
            // search goes on over the upper surface for the distances beyond the edge (the level).
            if (!grown && taken > 0 && taken + area[v] - target > target - taken) {
                grown = true;
            }
            if (!grown) {
                tendon[v] = true;
                taken += area[v];
                radius = dist[v];
            }
            for (int w : adj[v]) {
                double d = dist[v] + TwoSurfaces.distance(m, v, w);
                if (d < dist[w]) {
                    dist[w] = d;
                    queue.add(new double[] {d, w});
                }
            }
        }
        double[] c = new double[3];
        for (int v = 0; v < nv; v++) {
            if (tendon[v]) {
                for (int a = 0; a < 3; a++) {
                    c[a] += area[v] * m.coord(v, a) / taken;
                }
            }
        }
        double[] level = new double[nv];
        for (int v = 0; v < nv; v++) {
            int u = s.isUpper(v) ? v : s.partner(v);
            level[v] = u < 0 ? -radius : Math.max(-radius, radius - dist[u]);
        }
        for (int v = 0; v < nv; v++) {
            if (!s.isUpper(v) && s.partner(v) >= 0) {
                tendon[v] = tendon[s.partner(v)];
            }
        }
        return new Region(tendon, taken / upperArea, radius, c, level);
    }

    /**
     * The default seeds, {x, y} m: the tops of the two domes ({@link DomeTops}, halves split at the
     * centre of the mesh's bounding box in x) and the midpoint between them; only the top found when a
     * half has no upper vertex.
     */
    public static double[][] defaultSeeds(TwoSurfaces s) {
        double[] b = s.mesh().bounds();
        double[][] tops = DomeTops.tops(s, 0.5 * (b[0] + b[3]));
        if (tops[0] == null || tops[1] == null) {
            return new double[][] {tops[0] == null ? tops[1] : tops[0]};
        }
        double[] mid = {0.5 * (tops[0][0] + tops[1][0]), 0.5 * (tops[0][1] + tops[1][1])};
        return new double[][] {tops[0], tops[1], mid};
    }

    /**
     * Starts the search at the point of the upper surface above (x, y): the corners of the highest
     * upper triangle whose projection holds it, each at its straight distance from that point; where
     * no triangle holds it (outside the footprint, a hole), the upper vertex nearest in x and y, at its
     * horizontal distance.
     */
    private static void start(TriangleMesh m, int[] tri, double x, double y, double[] dist) {
        int best = -1;
        double bestZ = Double.NEGATIVE_INFINITY;
        double[] bary = new double[3];
        for (int t : tri) {
            if (barycentric(m, t, x, y, bary)) {
                double z = 0;
                for (int k = 0; k < 3; k++) {
                    z += bary[k] * m.coord(m.corner(t, k), 2);
                }
                if (z > bestZ) {
                    bestZ = z;
                    best = t;
                }
            }
        }
        if (best >= 0) {
            for (int k = 0; k < 3; k++) {
                int v = m.corner(best, k);
                double d = Math.sqrt(sq(m.coord(v, 0) - x) + sq(m.coord(v, 1) - y) + sq(m.coord(v, 2) - bestZ));
                dist[v] = Math.min(dist[v], d);
            }
            return;
        }
        int near = -1;
        double nearD = Double.POSITIVE_INFINITY;
        for (int t : tri) {
            for (int k = 0; k < 3; k++) {
                int v = m.corner(t, k);
                double d = Math.hypot(m.coord(v, 0) - x, m.coord(v, 1) - y);
                if (d < nearD) {
                    nearD = d;
                    near = v;
                }
            }
        }
        dist[near] = Math.min(dist[near], nearD);
    }

    /** Barycentric coordinates of (x, y) in triangle t projected on z = 0; false when outside. */
    private static boolean barycentric(TriangleMesh m, int t, double x, double y, double[] out) {
        int i = m.corner(t, 0);
        int j = m.corner(t, 1);
        int k = m.corner(t, 2);
        double ax = m.coord(i, 0);
        double ay = m.coord(i, 1);
        double e1x = m.coord(j, 0) - ax;
        double e1y = m.coord(j, 1) - ay;
        double e2x = m.coord(k, 0) - ax;
        double e2y = m.coord(k, 1) - ay;
        double det = e1x * e2y - e1y * e2x;
        if (det == 0) {
            return false; // a vertical triangle: no area over (x, y)
        }
        double u = ((x - ax) * e2y - (y - ay) * e2x) / det;
        double w = (e1x * (y - ay) - e1y * (x - ax)) / det;
        out[0] = 1 - u - w;
        out[1] = u;
        out[2] = w;
        return u >= 0 && w >= 0 && u + w <= 1;
    }

    /** Neighbours of each vertex along the given triangles' edges (each edge once per side). */
    static int[][] adjacency(TriangleMesh m, int[] tri) {
        int nv = m.vertexCount();
        int[] deg = new int[nv];
        for (int t : tri) {
            for (int k = 0; k < 3; k++) {
                deg[m.corner(t, k)] += 2;
            }
        }
        int[][] adj = new int[nv][];
        for (int v = 0; v < nv; v++) {
            adj[v] = new int[deg[v]];
        }
        int[] n = new int[nv];
        for (int t : tri) {
            for (int k = 0; k < 3; k++) {
                int a = m.corner(t, k);
                int b = m.corner(t, (k + 1) % 3);
                adj[a][n[a]++] = b;
                adj[b][n[b]++] = a;
            }
        }
        for (int v = 0; v < nv; v++) {
            // interior edges appear once from each of their two triangles: keep one copy
            adj[v] = Arrays.stream(adj[v], 0, n[v]).distinct().toArray();
        }
        return adj;
    }

    private static double sq(double x) {
        return x * x;
    }
}
