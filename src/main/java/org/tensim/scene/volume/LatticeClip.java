package org.tensim.scene.volume;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.thorax.TriangleTree;

/**
 * A regular lattice of cubic cells over a surface's bounds, and how much of each cell lies inside the surface, by
 * the generalised winding number w ({@link TriangleTree}): a point is inside where |w| &gt; 1/2 (|w|, so that a
 * surface wound inwards is filled too, and reported). The lattice starts at the surface's lowest corner (its
 * bounds' minimum), so a box's low faces lie on lattice planes; it has {@code ceil(extent / h)} cells along each
 * axis.
 *
 * <p>Inside fraction of a cell: a cell whose centre is farther from the surface than its half-diagonal
 * {@code h sqrt(3) / 2} lies wholly on one side, and is full (1) or empty (0) by the winding number at its centre;
 * a cell the surface may cross is sampled at the centres of {@code s^3} sub-cells, and its fraction is the share of
 * them inside. Features thinner than a sub-cell can be missed.
 *
 * <p>Closedness: at the centres of cells far from the surface (more than two cells, and more than
 * {@value #FAR_FRACTION} of the bounds' diagonal), a closed surface has w within
 * {@value #WINDING_TOLERANCE} of 0 or 1; the largest deviation is reported, and a larger one means the inside is
 * ambiguous (an open surface).
 */
final class LatticeClip {
    /**
     * Largest deviation of |w| from 0 or 1, far from the surface, of a surface taken as closed. The dipole
     * approximation alone leaves 0.015-0.021 on the closed shared rib r7 (10 and 5 mm cells), and the shared lobes'
     * and liver's 14-60 boundary edges 0.03-0.06; a box without a face leaves 0.17, an open bowl more.
     */
    static final double WINDING_TOLERANCE = 0.1;
    /**
     * The closedness check looks at cells farther from the surface than this fraction of its bounds' diagonal (and
     * than two cells): a small hole's effect on w fades with the square of the distance, so a finer lattice does not
     * bring the check closer to the holes.
     */
    static final double FAR_FRACTION = 0.1;
    /** Most cells the lattice's box may have (8 bytes each while building). */
    static final long MAX_CELLS = 20_000_000L;
    /** Far-field ratio of the winding number's dipole approximation (as DistanceGrid's). */
    private static final double BETA = 3;

    /** The lattice and its cells' inside fractions, cell (i, j, k) at index {@code (k ny + j) nx + i}. */
    record Result(double[] origin, int nx, int ny, int nz, double h, double[] fill, boolean[] holdsVertex,
            int crossedCells, double maxWindingDeviation, double[] worstPoint, boolean inward) {
        int cell(int i, int j, int k) {
            return (k * ny + j) * nx + i;
        }
    }

    private LatticeClip() {
    }

    static Result clip(TriangleMesh mesh, double h, int samples, String name) {
        if (mesh.triangleCount() == 0) {
            throw new IllegalArgumentException(name + " has no triangles: a volume needs a closed surface");
        }
        double[] b = mesh.bounds();
        int[] n = new int[3];
        long total = 1;
        for (int a = 0; a < 3; a++) {
            // a hair below the ratio, so that a box whose side is a whole number of cells gets exactly that many
            n[a] = (int) Math.max(1, Math.ceil((b[a + 3] - b[a]) / h * (1 - 1e-12)));
            total *= n[a];
        }
        if (total > MAX_CELLS) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "%s: a volume at %.3g mm"
                    + " cells over %.3g x %.3g x %.3g mm needs %d cells in its box, more than %d: expected a coarser"
                    + " cell size", name, h * 1e3, (b[3] - b[0]) * 1e3, (b[4] - b[1]) * 1e3, (b[5] - b[2]) * 1e3,
                    total, MAX_CELLS));
        }
        double[] o = {b[0], b[1], b[2]};
        TriangleTree tree = new TriangleTree(mesh.coordinates(), mesh.triangles(), BETA);
        double[] fill = new double[(int) total];
        boolean[] holds = new boolean[(int) total];
        for (int v = 0; v < mesh.vertexCount(); v++) {
            holds[cellOf(mesh, v, o, h, n)] = true;
        }
        double halfDiagonal = h * Math.sqrt(3) / 2 * (1 + 1e-9);
        double far = Math.max(2 * h, FAR_FRACTION * Math.sqrt(sq(b[3] - b[0]) + sq(b[4] - b[1]) + sq(b[5] - b[2])));
        // slabs of constant k in parallel, each with its own traversal stack; the cells' results do not depend on
        // the order, and the slabs' tallies are merged in k order, so the result is the same on any thread count
        Slab[] slabs = new Slab[n[2]];
        java.util.stream.IntStream.range(0, n[2]).parallel().forEach(k -> slabs[k] = slab(tree, k, n, o, h, samples,
                halfDiagonal, far, fill));
        double worst = 0;
        double[] worstPoint = null;
        long positive = 0;
        long negative = 0;
        int crossed = 0;
        for (Slab sl : slabs) {
            if (sl.worstPoint != null && sl.worst > worst) {
                worst = sl.worst;
                worstPoint = sl.worstPoint;
            }
            positive += sl.positive;
            negative += sl.negative;
            crossed += sl.crossed;
        }
        return new Result(o, n[0], n[1], n[2], h, fill, holds, crossed, worst, worstPoint, negative > positive);
    }

    /** What one slab of cells found. */
    private static final class Slab {
        double worst;
        double[] worstPoint;
        long positive;
        long negative;
        int crossed;
    }

    /** Fills the cells of slab k (constant z index) and tallies what they show. */
    private static Slab slab(TriangleTree tree, int k, int[] n, double[] o, double h, int samples, double halfDiagonal,
            double far, double[] fill) {
        Slab s = new Slab();
        int[] stack = tree.newStack();
        int c = k * n[1] * n[0];
        for (int j = 0; j < n[1]; j++) {
            for (int i = 0; i < n[0]; i++, c++) {
                double x = o[0] + (i + 0.5) * h;
                double y = o[1] + (j + 0.5) * h;
                double z = o[2] + (k + 0.5) * h;
                double d = tree.distance(x, y, z, stack);
                if (d <= halfDiagonal) {
                    s.crossed++;
                    fill[c] = sampled(tree, stack, x - h / 2, y - h / 2, z - h / 2, h, samples);
                    continue;
                }
                double w = tree.winding(x, y, z, stack);
                if (Math.abs(w) > 0.5) {
                    fill[c] = 1;
                    if (w > 0) {
                        s.positive++;
                    } else {
                        s.negative++;
                    }
                }
                if (d > far) {
                    double dev = Math.min(Math.abs(w), Math.abs(Math.abs(w) - 1));
                    if (dev > s.worst) {
                        s.worst = dev;
                        s.worstPoint = new double[] {x, y, z, w};
                    }
                }
            }
        }
        return s;
    }

    /** The share of a cell's s^3 sub-cell centres inside (|w| &gt; 1/2); the cell's low corner at (x, y, z). */
    private static double sampled(TriangleTree tree, int[] stack, double x, double y, double z, double h, int s) {
        int in = 0;
        double step = h / s;
        for (int c = 0; c < s; c++) {
            for (int b = 0; b < s; b++) {
                for (int a = 0; a < s; a++) {
                    double w = tree.winding(x + (a + 0.5) * step, y + (b + 0.5) * step, z + (c + 0.5) * step, stack);
                    in += Math.abs(w) > 0.5 ? 1 : 0;
                }
            }
        }
        return in / (double) (s * s * s);
    }

    /** The cell holding vertex v: the lattice's cell index along each axis, clamped to the lattice. */
    static int cellOf(TriangleMesh mesh, int v, double[] o, double h, int[] n) {
        int[] ijk = new int[3];
        for (int a = 0; a < 3; a++) {
            ijk[a] = cellIndex(mesh.coord(v, a), o[a], h, n[a]);
        }
        return (ijk[2] * n[1] + ijk[1]) * n[0] + ijk[0];
    }

    private static double sq(double v) {
        return v * v;
    }

    /** floor((x - o) / h), clamped to [0, n - 1] (a point on the lattice's far face belongs to its last cell). */
    static int cellIndex(double x, double o, double h, int n) {
        return (int) Math.max(0, Math.min(n - 1, Math.floor((x - o) / h)));
    }
}
