package org.tensim.scene.thorax;

import org.tensim.io.mesh.SurfaceDistance;

/**
 * Samples the signed distance to a triangle surface on a regular grid, in three passes:
 * <ol>
 * <li>exact distances in a band: every triangle sets the grid points within {@value #BAND} cells of its bounding
 * box to their distance to it, keeping the nearest; a point within {@value #BAND} cells of the surface thus gets
 * its exact distance;</li>
 * <li>everywhere else the nearest triangle is propagated by fast sweeping (eight sweeps, each point trying the
 * nearest triangles of its three upwind neighbours; Bridson's {@code makelevelset3}): the result is the exact
 * distance to a triangle, so never below the true distance, and in practice equal to it or within a small
 * fraction of a cell (checked against exact queries in the tests);</li>
 * <li>signs from the generalised winding number ({@link TriangleTree}) at every point. (Evaluating it once per
 * connected region of points far from the surface would be cheaper, but such a region leaks through any hole wider
 * than a few cells and takes one sign on both sides of it.)</li>
 * </ol>
 * The per-point cost is a few triangle tests instead of a nearest-triangle search, which matters for ribs: from
 * the middle of a rib's arc, every triangle is about equally far and a tree search prunes little.
 */
final class GridSampler {
    static final int BAND = 3;

    private final double[] x;
    private final int[] tri;
    private final int nx;
    private final int ny;
    private final int nz;
    private final double[] o;
    private final double h;

    GridSampler(double[] xyz, int[] triangles, int[] n, double[] origin, double h) {
        this.x = xyz;
        this.tri = triangles;
        this.nx = n[0];
        this.ny = n[1];
        this.nz = n[2];
        this.o = origin;
        this.h = h;
    }

    /** Result: signed distances (m) and the largest fractional winding number seen off the surface. */
    record Samples(float[] distance, double maxWindingDeviation) {
    }

    Samples sample(TriangleTree tree) {
        int total = nx * ny * nz;
        double[] d = new double[total];
        int[] near = new int[total];
        java.util.Arrays.fill(d, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(near, -1);
        band(d, near);
        for (int s = 0; s < 8; s++) {
            sweep(d, near, (s & 1) == 0 ? 1 : -1, (s & 2) == 0 ? 1 : -1, (s & 4) == 0 ? 1 : -1);
        }
        return sign(d, tree);
    }

    private void band(double[] d, int[] near) {
        for (int t = 0; t < tri.length / 3; t++) {
            int[] lo = new int[3];
            int[] hi = new int[3];
            int[] n = {nx, ny, nz};
            for (int a = 0; a < 3; a++) {
                double mn = Double.POSITIVE_INFINITY;
                double mx = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < 3; k++) {
                    double c = x[3 * tri[3 * t + k] + a];
                    mn = Math.min(mn, c);
                    mx = Math.max(mx, c);
                }
                lo[a] = Math.max(0, (int) Math.floor((mn - o[a]) / h) - BAND);
                hi[a] = Math.min(n[a] - 1, (int) Math.ceil((mx - o[a]) / h) + BAND);
            }
            for (int k = lo[2]; k <= hi[2]; k++) {
                for (int j = lo[1]; j <= hi[1]; j++) {
                    for (int i = lo[0]; i <= hi[0]; i++) {
                        int p = (k * ny + j) * nx + i;
                        double u = SurfaceDistance.closest(x, tri, t, o[0] + i * h, o[1] + j * h, o[2] + k * h, null);
                        if (u < d[p]) {
                            d[p] = u;
                            near[p] = t;
                        }
                    }
                }
            }
        }
        // squared distances above, as closest() returns them; roots once, here
        for (int p = 0; p < d.length; p++) {
            d[p] = Math.sqrt(d[p]);
        }
    }

    private void sweep(double[] d, int[] near, int di, int dj, int dk) {
        int sy = nx;
        int sz = nx * ny;
        for (int k = dk > 0 ? 0 : nz - 1; k >= 0 && k < nz; k += dk) {
            for (int j = dj > 0 ? 0 : ny - 1; j >= 0 && j < ny; j += dj) {
                for (int i = di > 0 ? 0 : nx - 1; i >= 0 && i < nx; i += di) {
                    int p = (k * ny + j) * nx + i;
                    int own = near[p];
                    int ii = i - di;
                    int jj = j - dj;
                    int kk = k - dk;
                    if (ii >= 0 && ii < nx) {
                        own = tryTriangle(d, near, p, own, near[p - di], i, j, k);
                    }
                    if (jj >= 0 && jj < ny) {
                        own = tryTriangle(d, near, p, own, near[p - dj * sy], i, j, k);
                    }
                    if (kk >= 0 && kk < nz) {
                        tryTriangle(d, near, p, own, near[p - dk * sz], i, j, k);
                    }
                }
            }
        }
    }

    private int tryTriangle(double[] d, int[] near, int p, int own, int t, int i, int j, int k) {
        if (t < 0 || t == own) {
            return own;
        }
        double u = Math.sqrt(SurfaceDistance.closest(x, tri, t, o[0] + i * h, o[1] + j * h, o[2] + k * h, null));
        if (u < d[p]) {
            d[p] = u;
            near[p] = t;
            return t;
        }
        return own;
    }

    /** Signs from the winding number at every point, z slices in parallel (each with its own traversal stack). */
    private Samples sign(double[] d, TriangleTree tree) {
        float[] out = new float[d.length];
        double[] deviation = new double[nz];
        java.util.stream.IntStream.range(0, nz).parallel().forEach(k -> {
            int[] stack = tree.newStack();
            double dev = 0;
            for (int j = 0; j < ny; j++) {
                for (int i = 0; i < nx; i++) {
                    int p = (k * ny + j) * nx + i;
                    double w = tree.winding(o[0] + i * h, o[1] + j * h, o[2] + k * h, stack);
                    out[p] = (float) (w > 0.5 ? -d[p] : d[p]);
                    if (d[p] > 2 * h) {
                        dev = Math.max(dev, Math.abs(w - Math.rint(w)));
                    }
                }
            }
            deviation[k] = dev;
        });
        double max = 0;
        for (double v : deviation) {
            max = Math.max(max, v);
        }
        return new Samples(out, max);
    }
}
