package org.tensim.solver;

/**
 * The per-element loops of the membrane triangles ({@link org.tensim.model.TriangleElement}):
 * static, allocation-free, on the flat arrays of {@link SystemState}. Element e has corners
 * {@code y_k = (x[P[3e+k]] + x[Q[3e+k]]) / 2} (P, Q as array offsets, 3 x node id), the rest-frame
 * inverse {@code R = D_m^-1} at {@code r[4e..4e+3]} (row-major, 1/m), and {@code A t mu},
 * {@code A t lambda} (J) at {@code mu[e]}, {@code la[e]}.
 *
 * <pre>
 *   F = [y_1 - y_0, y_2 - y_0] R,   E = (F^T F - I) / 2,   S = 2 mu E + lambda tr(E) I,
 *   W = mu tr(E^2) + lambda / 2 tr(E)^2,   dW/d(y_a - y_0) = (F S R^T)_{:, a},  a = 1, 2
 * </pre>
 *
 * A corner's force is split equally between its two nodes (the chain rule of the midpoint).
 */
public final class TriangleKernels {
    private TriangleKernels() {
    }

    /**
     * Adds the forces (N) of elements [0, count) at positions x (m) to f: elastic, and when
     * {@code v} is not null the Kelvin-Voigt damping of the elements whose {@code beta[e]} (s) is
     * not 0, at velocities v (m/s): {@code S += beta (2 mu dE/dt + lambda tr(dE/dt) I)},
     * {@code dE/dt = sym(F^T dF/dt)}.
     */
    public static void forces(int[] pp, int[] qq, double[] r, double[] mu, double[] la, double[] beta, int count,
            double[] x, double[] v, double[] f) {
        for (int e = 0; e < count; e++) {
            final int o = 3 * e;
            final int p0 = pp[o];
            final int q0 = qq[o];
            final int p1 = pp[o + 1];
            final int q1 = qq[o + 1];
            final int p2 = pp[o + 2];
            final int q2 = qq[o + 2];
            final double r00 = r[4 * e];
            final double r01 = r[4 * e + 1];
            final double r10 = r[4 * e + 2];
            final double r11 = r[4 * e + 3];
            final double ax = 0.5 * (x[p1] + x[q1] - x[p0] - x[q0]);
            final double ay = 0.5 * (x[p1 + 1] + x[q1 + 1] - x[p0 + 1] - x[q0 + 1]);
            final double az = 0.5 * (x[p1 + 2] + x[q1 + 2] - x[p0 + 2] - x[q0 + 2]);
            final double bx = 0.5 * (x[p2] + x[q2] - x[p0] - x[q0]);
            final double by = 0.5 * (x[p2 + 1] + x[q2 + 1] - x[p0 + 1] - x[q0 + 1]);
            final double bz = 0.5 * (x[p2 + 2] + x[q2 + 2] - x[p0 + 2] - x[q0 + 2]);
            // F = [a b] R: columns u, w.
            final double ux = ax * r00 + bx * r10;
            final double uy = ay * r00 + by * r10;
            final double uz = az * r00 + bz * r10;
            final double wx = ax * r01 + bx * r11;
            final double wy = ay * r01 + by * r11;
            final double wz = az * r01 + bz * r11;
            final double m2 = 2 * mu[e];
            double e00 = 0.5 * (ux * ux + uy * uy + uz * uz - 1);
            double e11 = 0.5 * (wx * wx + wy * wy + wz * wz - 1);
            double e01 = 0.5 * (ux * wx + uy * wy + uz * wz);
            final double b = v == null ? 0 : beta[e];
            if (b != 0) {
                // Strain rate from the corners' velocities, added as beta dE/dt (same moduli).
                final double vax = 0.5 * (v[p1] + v[q1] - v[p0] - v[q0]);
                final double vay = 0.5 * (v[p1 + 1] + v[q1 + 1] - v[p0 + 1] - v[q0 + 1]);
                final double vaz = 0.5 * (v[p1 + 2] + v[q1 + 2] - v[p0 + 2] - v[q0 + 2]);
                final double vbx = 0.5 * (v[p2] + v[q2] - v[p0] - v[q0]);
                final double vby = 0.5 * (v[p2 + 1] + v[q2 + 1] - v[p0 + 1] - v[q0 + 1]);
                final double vbz = 0.5 * (v[p2 + 2] + v[q2 + 2] - v[p0 + 2] - v[q0 + 2]);
                final double dux = vax * r00 + vbx * r10;
                final double duy = vay * r00 + vby * r10;
                final double duz = vaz * r00 + vbz * r10;
                final double dwx = vax * r01 + vbx * r11;
                final double dwy = vay * r01 + vby * r11;
                final double dwz = vaz * r01 + vbz * r11;
                e00 += b * (ux * dux + uy * duy + uz * duz);
                e11 += b * (wx * dwx + wy * dwy + wz * dwz);
                e01 += b * 0.5 * (ux * dwx + uy * dwy + uz * dwz + wx * dux + wy * duy + wz * duz);
            }
            final double tr = la[e] * (e00 + e11);
            final double s00 = m2 * e00 + tr;
            final double s11 = m2 * e11 + tr;
            final double s01 = m2 * e01;
            // P = F S, then the gradient on the edges a, b: P R^T.
            final double c0x = ux * s00 + wx * s01;
            final double c0y = uy * s00 + wy * s01;
            final double c0z = uz * s00 + wz * s01;
            final double c1x = ux * s01 + wx * s11;
            final double c1y = uy * s01 + wy * s11;
            final double c1z = uz * s01 + wz * s11;
            final double gax = c0x * r00 + c1x * r01;
            final double gay = c0y * r00 + c1y * r01;
            final double gaz = c0z * r00 + c1z * r01;
            final double gbx = c0x * r10 + c1x * r11;
            final double gby = c0y * r10 + c1y * r11;
            final double gbz = c0z * r10 + c1z * r11;
            addHalf(f, p1, q1, -gax, -gay, -gaz);
            addHalf(f, p2, q2, -gbx, -gby, -gbz);
            addHalf(f, p0, q0, gax + gbx, gay + gby, gaz + gbz);
        }
    }

    private static void addHalf(double[] f, int p, int q, double fx, double fy, double fz) {
        f[p] += 0.5 * fx;
        f[p + 1] += 0.5 * fy;
        f[p + 2] += 0.5 * fz;
        f[q] += 0.5 * fx;
        f[q + 1] += 0.5 * fy;
        f[q + 2] += 0.5 * fz;
    }

    /** Elastic energy of elements [0, count) at positions x, J (allocation-free). */
    public static double energy(int[] pp, int[] qq, double[] r, double[] mu, double[] la, int count, double[] x) {
        double sum = 0;
        for (int e = 0; e < count; e++) {
            double uu = 0;
            double ww = 0;
            double uw = 0;
            final int o = 3 * e;
            for (int d = 0; d < 3; d++) {
                final double y0 = x[pp[o] + d] + x[qq[o] + d];
                final double a = 0.5 * (x[pp[o + 1] + d] + x[qq[o + 1] + d] - y0);
                final double b = 0.5 * (x[pp[o + 2] + d] + x[qq[o + 2] + d] - y0);
                final double u = a * r[4 * e] + b * r[4 * e + 2];
                final double w = a * r[4 * e + 1] + b * r[4 * e + 3];
                uu += u * u;
                ww += w * w;
                uw += u * w;
            }
            final double e00 = 0.5 * (uu - 1);
            final double e11 = 0.5 * (ww - 1);
            final double e01 = 0.5 * uw;
            final double tr = e00 + e11;
            sum += mu[e] * (e00 * e00 + 2 * e01 * e01 + e11 * e11) + 0.5 * la[e] * tr * tr;
        }
        return sum;
    }

    /** F of element e at positions x into out[0..5]: column 0 (x, y, z), then column 1. */
    static void deformationGradient(int[] pp, int[] qq, double[] r, int e, double[] x, double[] out) {
        deformationGradient(pp, qq, r, e, x, out, 0);
    }

    /** F of element e at positions x into out[oo..oo+5]: column 0 (x, y, z), then column 1. */
    static void deformationGradient(int[] pp, int[] qq, double[] r, int e, double[] x, double[] out, int oo) {
        final int o = 3 * e;
        for (int d = 0; d < 3; d++) {
            final double y0 = x[pp[o] + d] + x[qq[o] + d];
            final double a = 0.5 * (x[pp[o + 1] + d] + x[qq[o + 1] + d] - y0);
            final double b = 0.5 * (x[pp[o + 2] + d] + x[qq[o + 2] + d] - y0);
            out[oo + d] = a * r[4 * e] + b * r[4 * e + 2];
            out[oo + 3 + d] = a * r[4 * e + 1] + b * r[4 * e + 3];
        }
    }
}
