package org.tensim.scene.thorax;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.SignedDistance;

/**
 * The signed distance to a bone's surface sampled once on a regular grid, for contact ({@link SignedDistance}):
 * negative inside, in metres, in the mesh's (rest) frame.
 *
 * <p>Built from a triangle mesh ({@link GridSampler}): exact distances to the nearest triangle within three cells
 * of the surface, nearest triangles propagated by fast sweeping beyond, and the sign of the generalised winding
 * number at every point (inside where it exceeds 1/2), which tolerates the small holes and non-manifold edges of
 * segmented bones where a ray-parity or normal-based sign would flip. The winding number sums clusters farther than
 * three times their radius as dipoles ({@link TriangleTree}); exact near the surface, where the sign matters.
 *
 * <p>Measured on the shared thorax (2 shared cores, load about 4; run of 2026-11-26): the 24 ribs at the
 * defaults (1.5 mm, 20 mm margin) take 0.4-3.6 s each, 48 s in all, and 114 MB of floats (0.3-1.9 M points, 1.2-7.5
 * MB each); the 20 costal cartilages 0.1-1.4 s and 15 MB. A build needs about 16 bytes a point while it runs (30 MB
 * for the largest rib). Against exact distances, rib r7's grid is within 0.67 mm of the truth 2 mm off its surface.
 *
 * <p>Lookup is trilinear interpolation (error below a cell near a smooth surface, larger at edges thinner than a
 * cell); the gradient is the trilinear one, normalised. Outside the grid the value at the nearest grid point plus
 * the distance to the grid's box is returned (a lower bound of the true distance, positive), with the gradient
 * pointing out of the box. Values are stored as floats (4 bytes a grid point; a few nanometres of resolution at
 * these sizes). Lookups do not allocate and only read, so one grid serves any number of threads.
 */
public final class DistanceGrid implements SignedDistance {
    /** Default grid spacing, m: 1.5 mm (the 24 shared ribs take 114 MB of floats at this spacing). */
    public static final double DEFAULT_CELL_M = 1.5e-3;
    /** Default margin around the mesh's bounds, m. */
    public static final double DEFAULT_MARGIN_M = 20e-3;
    /** Most grid points one grid may have (200 MB of floats, 800 MB while building): a finer request is refused. */
    public static final long MAX_POINTS = 50_000_000L;
    /** A mesh is reported closed by the winding number when it is within this of an integer away from it. */
    static final double WINDING_TOLERANCE = 0.05;
    /** Far-field ratio of the winding-number approximation: Barill et al.'s 2 left 0.07 of error on closed ribs. */
    private static final double BETA = 3;

    /**
     * What a build did.
     *
     * @param triangles            triangles of the mesh
     * @param boundaryEdges        edges used by one triangle only (holes); 0 for a closed mesh
     * @param nx                   grid points along x (likewise ny, nz)
     * @param cellM                grid spacing, m
     * @param marginM              margin around the mesh's bounds, m
     * @param buildSeconds         wall-clock time of the build, s
     * @param bytes                memory of the samples, bytes
     * @param maxWindingDeviation  largest distance of the winding number from 0 or 1 at grid points more than two
     *                             cells from the surface (0 for a closed surface, up to 0.5 near a large hole)
     */
    public record Report(int triangles, int boundaryEdges, int nx, int ny, int nz, double cellM, double marginM,
            double buildSeconds, long bytes, double maxWindingDeviation) {
        /** Grid points. */
        public long points() {
            return (long) nx * ny * nz;
        }

        /**
         * Whether the winding number was everywhere (two cells off the surface) within 0.05 of 0 or 1: the surface
         * is closed as far as the sign is concerned. Holes smaller than a few cells (the shared cartilages' 6-32
         * boundary edges) pass; a hole that makes the inside ambiguous does not.
         */
        public boolean windingClosed() {
            return maxWindingDeviation < WINDING_TOLERANCE;
        }

        /** One line for a console. */
        public String describe() {
            return String.format(java.util.Locale.ROOT, "%d triangles (%d boundary edges), grid %d x %d x %d = %d"
                    + " points at %.2f mm, %.1f MB, built in %.2f s; winding number %s (max deviation %.3f)",
                    triangles, boundaryEdges, nx, ny, nz, points(), cellM * 1e3, bytes / 1e6, buildSeconds,
                    windingClosed() ? "closed" : "open", maxWindingDeviation);
        }
    }

    private final float[] d;
    private final int nx;
    private final int ny;
    private final int nz;
    private final double ox;
    private final double oy;
    private final double oz;
    private final double h;
    private final double[] meshBounds;
    private final Report report;

    private DistanceGrid(float[] d, int nx, int ny, int nz, double[] origin, double h, double[] meshBounds,
            Report report) {
        this.d = d;
        this.nx = nx;
        this.ny = ny;
        this.nz = nz;
        this.ox = origin[0];
        this.oy = origin[1];
        this.oz = origin[2];
        this.h = h;
        this.meshBounds = meshBounds;
        this.report = report;
    }

    /** Builds with {@link #DEFAULT_CELL_M} and {@link #DEFAULT_MARGIN_M}. */
    public static DistanceGrid build(TriangleMesh mesh) {
        return build(mesh, DEFAULT_CELL_M, DEFAULT_MARGIN_M);
    }

    /**
     * Samples the signed distance to {@code mesh} (m, triangles counter-clockwise seen from outside).
     *
     * @param cellM   grid spacing, m (> 0)
     * @param marginM how far the grid extends beyond the mesh's bounds, m (>= 0); lookups beyond it are lower bounds
     */
    public static DistanceGrid build(TriangleMesh mesh, double cellM, double marginM) {
        if (!(cellM > 0) || !Double.isFinite(cellM)) {
            throw new IllegalArgumentException("distance grid cell size must be a positive number of metres, got "
                    + cellM);
        }
        if (!(marginM >= 0) || !Double.isFinite(marginM)) {
            throw new IllegalArgumentException("distance grid margin must be >= 0 m, got " + marginM);
        }
        if (mesh.triangleCount() == 0) {
            throw new IllegalArgumentException("a distance grid needs a mesh with triangles, got " + mesh);
        }
        long t0 = System.nanoTime();
        double[] b = mesh.bounds();
        double[] origin = new double[3];
        int[] n = new int[3];
        for (int a = 0; a < 3; a++) {
            origin[a] = b[a] - marginM;
            long points = (long) Math.ceil((b[a + 3] + marginM - origin[a]) / cellM) + 1;
            n[a] = (int) Math.max(2, Math.min(points, Integer.MAX_VALUE));
        }
        long total = (long) n[0] * n[1] * n[2];
        if (total > MAX_POINTS) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "a distance grid at %.3g mm"
                    + " over %.3g x %.3g x %.3g mm (margin %.3g mm) needs %d points, more than %d: expected a"
                    + " coarser cell", cellM * 1e3, (b[3] - b[0]) * 1e3, (b[4] - b[1]) * 1e3, (b[5] - b[2]) * 1e3,
                    marginM * 1e3, total, MAX_POINTS));
        }
        TriangleTree tree = new TriangleTree(mesh.coordinates(), mesh.triangles(), BETA);
        GridSampler.Samples samples = new GridSampler(mesh.coordinates(), mesh.triangles(), n, origin, cellM)
                .sample(tree);
        float[] d = samples.distance();
        double maxDev = samples.maxWindingDeviation();
        double seconds = (System.nanoTime() - t0) * 1e-9;
        Report r = new Report(mesh.triangleCount(), mesh.boundaryEdgeCount(), n[0], n[1], n[2], cellM, marginM, seconds,
                4L * total, maxDev);
        return new DistanceGrid(d, n[0], n[1], n[2], origin, cellM, b, r);
    }

    @Override
    public double distance(double x, double y, double z, double[] gradient, int offset) {
        double fx = (x - ox) / h;
        double fy = (y - oy) / h;
        double fz = (z - oz) / h;
        double cx = Math.max(0, Math.min(nx - 1, fx));
        double cy = Math.max(0, Math.min(ny - 1, fy));
        double cz = Math.max(0, Math.min(nz - 1, fz));
        int i = Math.min((int) cx, nx - 2);
        int j = Math.min((int) cy, ny - 2);
        int k = Math.min((int) cz, nz - 2);
        double tx = cx - i;
        double ty = cy - j;
        double tz = cz - k;
        int p = (k * ny + j) * nx + i;
        int sy = nx;
        int sz = nx * ny;
        double c000 = d[p], c100 = d[p + 1], c010 = d[p + sy], c110 = d[p + sy + 1];
        double c001 = d[p + sz], c101 = d[p + sz + 1], c011 = d[p + sz + sy], c111 = d[p + sz + sy + 1];
        double c00 = c000 + tx * (c100 - c000);
        double c10 = c010 + tx * (c110 - c010);
        double c01 = c001 + tx * (c101 - c001);
        double c11 = c011 + tx * (c111 - c011);
        double c0 = c00 + ty * (c10 - c00);
        double c1 = c01 + ty * (c11 - c01);
        double value = c0 + tz * (c1 - c0);
        double ex = (fx - cx) * h;
        double ey = (fy - cy) * h;
        double ez = (fz - cz) * h;
        double outside = Math.sqrt(ex * ex + ey * ey + ez * ez);
        if (outside > 0) {
            gradient[offset] = ex / outside;
            gradient[offset + 1] = ey / outside;
            gradient[offset + 2] = ez / outside;
            return value + outside;
        }
        // derivative of the trilinear interpolant, per grid unit; only its direction is used
        double gx = (1 - tz) * ((1 - ty) * (c100 - c000) + ty * (c110 - c010))
                + tz * ((1 - ty) * (c101 - c001) + ty * (c111 - c011));
        double gy = (1 - tz) * (c10 - c00) + tz * (c11 - c01);
        double gz = c1 - c0;
        double g = Math.sqrt(gx * gx + gy * gy + gz * gz);
        if (g > 0) {
            gradient[offset] = gx / g;
            gradient[offset + 1] = gy / g;
            gradient[offset + 2] = gz / g;
        } else {
            // a flat spot (a medial point of a symmetric shape): any direction is as good; +z keeps it defined
            gradient[offset] = 0;
            gradient[offset + 1] = 0;
            gradient[offset + 2] = 1;
        }
        return value;
    }

    /** The mesh's bounds {min x, min y, min z, max x, max y, max z}, m (the grid extends a margin beyond them). */
    public double[] boundsM() {
        return meshBounds.clone();
    }

    /** The grid's box {min x, min y, min z, max x, max y, max z}, m. */
    public double[] gridBoundsM() {
        return new double[] {ox, oy, oz, ox + (nx - 1) * h, oy + (ny - 1) * h, oz + (nz - 1) * h};
    }

    /** What the build did: grid size, time, memory, triangles, holes. */
    public Report report() {
        return report;
    }
}
