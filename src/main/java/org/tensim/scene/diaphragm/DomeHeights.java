package org.tensim.scene.diaphragm;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The height of each hemidiaphragm's top in a state of the scene, read where {@link MeasuringSites} says: the run's
 * summary and the GUI's readouts read it through this one object.
 *
 * <ul>
 * <li>A half with a dome top of its own: the highest of its candidate nodes (free upper-surface nodes within a
 * horizontal radius of the top at rest), the local highest point.</li>
 * <li>A half without one (its upper surface rises towards the other, higher dome): the highest point of the upper
 * surface in the sagittal plane {@code x = x_mcl} of its midclavicular line, the coronal silhouette a frontal
 * radiograph shows on that line. Each free upper triangle (no corner attached) within {@link #LINE_BAND_M} of the
 * line at rest is cut by the plane in its current position; along an edge (a, b) with {@code x_a <= x_mcl <= x_b}
 * the cut is at {@code z = z_a + (x_mcl - x_a) (z_b - z_a) / (x_b - x_a)}, and the top is the highest cut. On a
 * sloping surface the highest node of a strip about the line lies on the strip's upper edge, off the line: the cut
 * reads the line itself, whatever the mesh's resolution.</li>
 * </ul>
 * Heights in m; {@code -infinity} when a half has nothing to read.
 */
public final class DomeHeights {
    /** Distance from the line at rest within which a triangle may be cut by it later, m (the sheet slides sideways). */
    public static final double LINE_BAND_M = 0.030;

    private final int[][] candidates;
    private final int[][] lineCorners;
    private final double[] lineX;

    DomeHeights(int[][] candidates, int[][] lineCorners, double[] lineX) {
        this.candidates = candidates;
        this.lineCorners = lineCorners;
        this.lineX = lineX;
    }

    /** Whether half d (0 right, 1 left) is read on its midclavicular line (else at its own top). */
    public boolean onLine(int d) {
        return lineCorners[d] != null;
    }

    /**
     * The height of half d's top, m.
     *
     * @param x positions, 3 per node (diaphragm nodes first, as the scene numbers them), m
     * @param d 0 the right half, 1 the left
     */
    public double top(double[] x, int d) {
        double top = Double.NEGATIVE_INFINITY;
        if (lineCorners[d] == null) {
            for (int v : candidates[d]) {
                top = Math.max(top, x[3 * v + 2]);
            }
            return top;
        }
        int[] c = lineCorners[d];
        double xl = lineX[d];
        for (int t = 0; t < c.length; t += 3) {
            for (int k = 0; k < 3; k++) {
                top = Math.max(top, cut(x, c[t + k], c[t + (k + 1) % 3], xl));
            }
        }
        return top;
    }

    /** Height where edge (a, b) crosses the plane x = xl, m; -infinity when it does not. */
    private static double cut(double[] x, int a, int b, double xl) {
        double xa = x[3 * a];
        double xb = x[3 * b];
        if ((xa - xl) * (xb - xl) > 0 || xa == xb) {
            return xa == xl ? x[3 * a + 2] : Double.NEGATIVE_INFINITY;
        }
        double s = (xl - xa) / (xb - xa);
        return x[3 * a + 2] + s * (x[3 * b + 2] - x[3 * a + 2]);
    }

    /**
     * The free upper triangles' corners (3 per triangle) within {@link #LINE_BAND_M} of the plane x = xl at rest.
     *
     * @param attached per node, whether it is attached (an attached corner leaves its triangle out)
     */
    static int[] lineTriangles(TwoSurfaces s, boolean[] attached, double xl) {
        TriangleMesh m = s.mesh();
        int[] up = s.upperTriangles();
        int[] out = new int[3 * up.length];
        int n = 0;
        for (int t : up) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            boolean free = true;
            for (int k = 0; k < 3; k++) {
                int v = m.corner(t, k);
                free &= !attached[v];
                lo = Math.min(lo, m.coord(v, 0));
                hi = Math.max(hi, m.coord(v, 0));
            }
            if (free && lo - LINE_BAND_M <= xl && xl <= hi + LINE_BAND_M) {
                for (int k = 0; k < 3; k++) {
                    out[n++] = m.corner(t, k);
                }
            }
        }
        return java.util.Arrays.copyOf(out, n);
    }
}
