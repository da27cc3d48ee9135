package org.tensim.scene.diaphragm;

/**
 * The coordinates of a point in a wedge of a two-surface shell ({@link ShellMapping}): face corners {@code F_k},
 * their partners across the thickness {@code G_k}, and {@code p = sum_k w_k ((1 - t) F_k + t G_k)} with
 * {@code sum_k w_k = 1} solved for (w, t) by Newton's method.
 */
final class Wedge {
    /** Coordinates found: face weights (sum 1), depth t from the face, the residual and column length (m). */
    record Solution(double[] weights, double depth, double residualM, double columnM) {
    }

    private Wedge() {
    }

    /**
     * @param x       node positions, m, 3 per node
     * @param f       the face triangle's corners
     * @param g       their partners on the other face
     * @param start   the closest point's weights on the face triangle (start[0..2])
     * @param exact   convergence: the residual below this fraction of the wedge's size
     * @param maxIter Newton iterations at most
     * @return the coordinates, or null when the wedge is degenerate (a column of no length, a flat Jacobian) or the
     *         iteration does not converge
     */
    static Solution solve(double[] x, int[] f, int[] g, double px, double py, double pz, double[] start, double exact,
            int maxIter) {
        double[] p = {px, py, pz};
        double[][] fk = new double[3][3];
        double[][] dk = new double[3][3];
        double size = 0;
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) {
                fk[k][a] = x[3 * f[k] + a];
                dk[k][a] = x[3 * g[k] + a] - fk[k][a];
            }
        }
        for (int k = 0; k < 3; k++) {
            size = Math.max(size, Math.sqrt(sq(fk[(k + 1) % 3], fk[k])));
            size = Math.max(size, norm(dk[k]));
        }
        double[] w = {start[0], start[1], start[2]};
        double[] d = new double[3];
        double[] q = new double[3];
        combine(w, fk, dk, 0, q, d);
        double dd = dot(d, d);
        if (!(dd > 0) || !(size > 0)) {
            return null;
        }
        // the first depth: the point's projection on the blended column at the closest point
        double t = ((p[0] - q[0]) * d[0] + (p[1] - q[1]) * d[1] + (p[2] - q[2]) * d[2]) / dd;
        double[] r = new double[3];
        double[][] c = new double[3][3];
        for (int it = 0; it <= maxIter; it++) {
            combine(w, fk, dk, t, q, d);
            for (int a = 0; a < 3; a++) {
                r[a] = q[a] - p[a];
            }
            double res = norm(r);
            if (res <= exact * size) {
                return new Solution(w, t, res, norm(d));
            }
            if (it == maxIter) {
                break;
            }
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++) {
                    c[k][a] = fk[k][a] + t * dk[k][a];
                }
            }
            // J = [C1 - C0, C2 - C0, sum w_k D_k]; solve J (da, db, dt) = -r by Cramer's rule
            double[] j0 = {c[1][0] - c[0][0], c[1][1] - c[0][1], c[1][2] - c[0][2]};
            double[] j1 = {c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]};
            double det = det(j0, j1, d);
            if (!(Math.abs(det) > 1e-12 * size * size * size)) {
                return null;
            }
            double[] mr = {-r[0], -r[1], -r[2]};
            double da = det(mr, j1, d) / det;
            double db = det(j0, mr, d) / det;
            double dt = det(j0, j1, mr) / det;
            w[1] += da;
            w[2] += db;
            w[0] = 1 - w[1] - w[2];
            t += dt;
        }
        return null;
    }

    /** The depth of the point's projection on the column at face weights w: {@code (p - q) . d / |d|^2}; 0 if none. */
    static double columnDepth(double[] x, int[] f, int[] g, double[] w, double px, double py, double pz) {
        double[] q = point(x, f, g, w, 0);
        double[] d = point(x, f, g, w, 1);
        double dd = 0;
        double pd = 0;
        double[] p = {px, py, pz};
        for (int a = 0; a < 3; a++) {
            d[a] -= q[a];
            dd += d[a] * d[a];
            pd += (p[a] - q[a]) * d[a];
        }
        return dd > 0 ? pd / dd : 0;
    }

    /** The wedge's point at face weights w and depth t: {@code sum_k w_k ((1 - t) F_k + t G_k)}, m. */
    static double[] point(double[] x, int[] f, int[] g, double[] w, double t) {
        double[] q = new double[3];
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) {
                q[a] += w[k] * ((1 - t) * x[3 * f[k] + a] + t * x[3 * g[k] + a]);
            }
        }
        return q;
    }

    /** q = sum w_k (F_k + t D_k), d = sum w_k D_k. */
    private static void combine(double[] w, double[][] fk, double[][] dk, double t, double[] q, double[] d) {
        for (int a = 0; a < 3; a++) {
            d[a] = w[0] * dk[0][a] + w[1] * dk[1][a] + w[2] * dk[2][a];
            q[a] = w[0] * fk[0][a] + w[1] * fk[1][a] + w[2] * fk[2][a] + t * d[a];
        }
    }

    private static double det(double[] a, double[] b, double[] c) {
        return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double norm(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    private static double sq(double[] a, double[] b) {
        return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
    }
}
