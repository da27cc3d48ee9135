package org.tensim.io.mesh;

/**
 * Quadric error metrics (Garland and Heckbert 1997), ten coefficients per vertex in one flat array: the
 * symmetric 4 x 4 matrix Q = sum of w p p^T over planes p = (n, d) with n . x + d = 0 and |n| = 1, stored as
 * (aa, ab, ac, ad, bb, bc, bd, cc, cd, dd). The error of a point x is [x 1] Q [x 1]^T: the weighted sum of
 * the squared distances from x to the planes, m^2 times the weights' unit.
 */
final class Quadrics {
    /** Coefficients per quadric. */
    static final int SIZE = 10;

    private Quadrics() {
    }

    /** Adds w times the plane through point (px, py, pz) with unit normal (a, b, c) to quadric q of array qs. */
    static void addPlane(double[] qs, int q, double a, double b, double c, double px, double py, double pz,
            double w) {
        double d = -(a * px + b * py + c * pz);
        int o = SIZE * q;
        qs[o] += w * a * a;
        qs[o + 1] += w * a * b;
        qs[o + 2] += w * a * c;
        qs[o + 3] += w * a * d;
        qs[o + 4] += w * b * b;
        qs[o + 5] += w * b * c;
        qs[o + 6] += w * b * d;
        qs[o + 7] += w * c * c;
        qs[o + 8] += w * c * d;
        qs[o + 9] += w * d * d;
    }

    /** Adds quadric {@code from} to quadric {@code to}. */
    static void add(double[] qs, int to, int from) {
        for (int i = 0; i < SIZE; i++) {
            qs[SIZE * to + i] += qs[SIZE * from + i];
        }
    }

    /** The error at (x, y, z) of the sum of quadrics i and j. */
    static double error(double[] qs, int i, int j, double x, double y, double z) {
        double[] s = new double[SIZE];
        for (int k = 0; k < SIZE; k++) {
            s[k] = qs[SIZE * i + k] + qs[SIZE * j + k];
        }
        return s[0] * x * x + 2 * s[1] * x * y + 2 * s[2] * x * z + 2 * s[3] * x + s[4] * y * y
                + 2 * s[5] * y * z + 2 * s[6] * y + s[7] * z * z + 2 * s[8] * z + s[9];
    }

    /**
     * The point minimising the sum of quadrics i and j, written to out; false (out untouched) when the 3 x 3
     * system is ill-conditioned (a flat or cylindrical neighbourhood, where the minimum is a plane or a line).
     */
    static boolean minimum(double[] qs, int i, int j, double[] out) {
        double[] s = new double[SIZE];
        for (int k = 0; k < SIZE; k++) {
            s[k] = qs[SIZE * i + k] + qs[SIZE * j + k];
        }
        double a = s[0];
        double b = s[1];
        double c = s[2];
        double e = s[4];
        double f = s[5];
        double h = s[7];
        double c00 = e * h - f * f;
        double c01 = c * f - b * h;
        double c02 = b * f - c * e;
        double det = a * c00 + b * c01 + c * c02;
        double scale = Math.abs(a) + Math.abs(e) + Math.abs(h);
        if (!(Math.abs(det) > 1e-9 * scale * scale * scale)) {
            return false;
        }
        double c11 = a * h - c * c;
        double c12 = b * c - a * f;
        double c22 = a * e - b * b;
        double rx = -s[3];
        double ry = -s[6];
        double rz = -s[8];
        out[0] = (c00 * rx + c01 * ry + c02 * rz) / det;
        out[1] = (c01 * rx + c11 * ry + c12 * rz) / det;
        out[2] = (c02 * rx + c12 * ry + c22 * rz) / det;
        return true;
    }
}
