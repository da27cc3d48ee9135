package org.tensim.scene.diaphragm;

import org.hipparchus.linear.Array2DRowRealMatrix;
import org.hipparchus.linear.ArrayRealVector;
import org.hipparchus.linear.QRDecomposition;
import org.hipparchus.linear.RealVector;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The highest point of each half (x below and from the mesh's centre) of the upper surface,
 * where the default action lines go ({@link DiaphragmScene#defaultActionLines}), taken on the
 * surface rather than at a vertex.
 *
 * <p>Why: the domes' tops are flat (the double dome's height changes by 1.5 mm over 20 mm
 * around the right dome's top), so the highest <em>vertex</em> wanders with the mesh: on the
 * double dome it lay at x = -44.5, -41.7, -37.3 and -38.8 mm at 14, 20, 28 and 43 rings
 * (analytic top: -40.6 mm), and the muscle's load moved with it. Measured (2026-11-23, RK2,
 * one inspiration): with the lines fixed in space the end-inspiration fields of 14 and 20 rings
 * differ from 28 rings' by 0.19 and 0.19, against 0.45 and 0.27 with the highest vertices.
 *
 * <p>How: around the half's highest vertex (x0, y0), the quadratic
 * {@code z = c0 + c1 dx + c2 dy + c3 dx^2 + c4 dx dy + c5 dy^2} is fitted by least squares to the
 * upper vertices within the horizontal radius {@code rho}, each weighted by its area (a third of its
 * upper triangles'), which makes the fit a quadrature of the continuous least-squares problem and
 * its limit independent of the mesh. Its maximum is the top: the stationary point when the fit is
 * concave there and it lies in the half within {@code rho}; otherwise the maximum along the half's
 * edge x = centre (the double dome's left half, whose highest point is next to the higher right
 * dome); when neither exists (too few vertices, a saddle) the highest vertex. {@code rho} is a
 * tenth of the mesh's transverse width, and at least twice its mean upper edge so that a coarse
 * mesh still has the fit's six unknowns well covered.
 */
final class DomeTops {
    /** Fitting radius as a fraction of the mesh's transverse width. */
    static final double RADIUS_FRACTION = 0.1;
    /** Smallest fitting radius, in mean upper-edge lengths. */
    static final double MIN_RADIUS_EDGES = 2;
    /** Fewest vertices the fit takes (twice its unknowns). */
    private static final int MIN_VERTICES = 12;

    private DomeTops() {
    }

    /**
     * The top of each half, {x, y} in m: index 0 the half with x below {@code centreX}, 1 the rest;
     * null for a half without upper vertices.
     */
    static double[][] tops(TwoSurfaces s, double centreX) {
        TriangleMesh m = s.mesh();
        double[] area = new double[m.vertexCount()];
        int[] up = s.upperTriangles();
        double edges = 0;
        for (int t : up) {
            for (int k = 0; k < 3; k++) {
                area[m.corner(t, k)] += m.area(t) / 3;
                edges += distance(m, m.corner(t, k), m.corner(t, (k + 1) % 3));
            }
        }
        double[] b = m.bounds();
        double rho = Math.max(RADIUS_FRACTION * (b[3] - b[0]), up.length == 0 ? 0
                : MIN_RADIUS_EDGES * edges / (3 * up.length));
        int[] top = {-1, -1};
        for (int v = 0; v < m.vertexCount(); v++) {
            int side = m.coord(v, 0) < centreX ? 0 : 1;
            if (s.isUpper(v) && (top[side] < 0 || m.coord(v, 2) > m.coord(top[side], 2))) {
                top[side] = v;
            }
        }
        double[][] out = new double[2][];
        for (int side = 0; side < 2; side++) {
            if (top[side] >= 0) {
                out[side] = top(s, area, top[side], side, centreX, rho);
            }
        }
        return out;
    }

    private static double[] top(TwoSurfaces s, double[] area, int v0, int side, double centreX, double rho) {
        TriangleMesh m = s.mesh();
        double x0 = m.coord(v0, 0);
        double y0 = m.coord(v0, 1);
        double[] vertex = {x0, y0};
        int n = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            if (s.isUpper(v) && area[v] > 0 && Math.hypot(m.coord(v, 0) - x0, m.coord(v, 1) - y0) <= rho) {
                n++;
            }
        }
        if (n < MIN_VERTICES) {
            return vertex;
        }
        double[][] a = new double[n][];
        double[] z = new double[n];
        int row = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            double dx = m.coord(v, 0) - x0;
            double dy = m.coord(v, 1) - y0;
            if (s.isUpper(v) && area[v] > 0 && Math.hypot(dx, dy) <= rho) {
                double w = Math.sqrt(area[v]);
                // unknowns scaled by rho so that the columns are of one size
                double u = dx / rho;
                double t = dy / rho;
                a[row] = new double[] {w, w * u, w * t, w * u * u, w * u * t, w * t * t};
                z[row++] = w * (m.coord(v, 2) - m.coord(v0, 2)) / rho;
            }
        }
        RealVector c = new QRDecomposition(new Array2DRowRealMatrix(a, false), 1e-12).getSolver()
                .solve(new ArrayRealVector(z, false));
        double c1 = c.getEntry(1);
        double c2 = c.getEntry(2);
        double c3 = c.getEntry(3);
        double c4 = c.getEntry(4);
        double c5 = c.getEntry(5);
        double det = 4 * c3 * c5 - c4 * c4;
        if (c3 < 0 && det > 0) { // concave: a maximum
            double u = (-2 * c5 * c1 + c4 * c2) / det;
            double t = (c4 * c1 - 2 * c3 * c2) / det;
            double[] p = {x0 + rho * u, y0 + rho * t};
            if (Math.hypot(u, t) <= 1 && (p[0] < centreX) == (side == 0)) {
                return p;
            }
        }
        if (c5 < 0) { // the maximum along the half's edge x = centre
            double u = (centreX - x0) / rho;
            double t = -(c2 + c4 * u) / (2 * c5);
            if (Math.hypot(u, t) <= 1) {
                return new double[] {centreX, y0 + rho * t};
            }
        }
        return vertex;
    }

    private static double distance(TriangleMesh m, int i, int j) {
        double dx = m.coord(i, 0) - m.coord(j, 0);
        double dy = m.coord(i, 1) - m.coord(j, 1);
        double dz = m.coord(i, 2) - m.coord(j, 2);
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
