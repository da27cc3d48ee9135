package org.tensim.solver.integrators;

import org.tensim.solver.SpringKernels;
import org.tensim.solver.SystemState;

/**
 * The springs' part of {@link ImplicitEuler}'s matrix (package-private), linearised once per step:
 * per spring the direction u and the coefficients of its blocks {@code alpha u u^T + beta I} in
 * {@code A = M + h C + h^2 S} ({@code alpha = h^2 k (1 - g) + h c}, {@code beta = h^2 k g}) and in the
 * stiffness S alone ({@code k (1 - g)}, {@code k g}), g = max(0, 1 - L / l) the transverse factor
 * clamped at zero for a compressed spring (Baraff and Witkin 1998). Arrays allocated once.
 */
final class SpringBlocks {
    private final double[] dir; // per spring: u_x, u_y, u_z
    private final double[] blockA; // per spring: alpha, beta of its block of A
    private final double[] blockS; // per spring: k (1 - g), k g

    SpringBlocks(int springs) {
        dir = new double[3 * springs];
        blockA = new double[2 * springs];
        blockS = new double[2 * springs];
    }

    /** Number of springs these blocks are for. */
    int springs() {
        return blockA.length / 2;
    }

    /** Linearises at positions px for the step h (s) and adds A's spring blocks' diagonal to dg (full layout). */
    void linearise(SystemState s, double[] px, double h, double[] dg) {
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] kk = s.springK;
        final double[] cc = s.springC;
        final double[] rl = s.springL;
        final double h2 = h * h;
        for (int i = 0; i < sa.length; i++) {
            final int a = 3 * sa[i];
            final int b = 3 * sb[i];
            final double len = SpringKernels.direction(px, a, b, dir, 3 * i);
            final double g = len > 0 ? Math.max(0, 1 - rl[i] / len) : 0;
            final double ux = dir[3 * i];
            final double uy = dir[3 * i + 1];
            final double uz = dir[3 * i + 2];
            final double alpha = h2 * kk[i] * (1 - g) + h * cc[i];
            final double beta = h2 * kk[i] * g;
            blockA[2 * i] = alpha;
            blockA[2 * i + 1] = beta;
            blockS[2 * i] = kk[i] * (1 - g);
            blockS[2 * i + 1] = kk[i] * g;
            final double ddx = alpha * ux * ux + beta;
            final double ddy = alpha * uy * uy + beta;
            final double ddz = alpha * uz * uz + beta;
            dg[a] += ddx;
            dg[a + 1] += ddy;
            dg[a + 2] += ddz;
            dg[b] += ddx;
            dg[b + 1] += ddy;
            dg[b + 2] += ddz;
        }
    }

    /** out += the springs' part of A times pv (full layout). */
    void addStep(SystemState s, double[] pv, double[] out) {
        add(s, blockA, pv, out);
    }

    /** out += the springs' stiffness S times pv (full layout). */
    void addStiffness(SystemState s, double[] pv, double[] out) {
        add(s, blockS, pv, out);
    }

    /**
     * out += sum over springs of the block {@code alpha u u^T + beta I} (coefficients
     * {@code coef[2i]}, {@code coef[2i + 1]}) times (p_b - p_a), added at b and subtracted at a.
     */
    private void add(SystemState s, double[] coef, double[] pv, double[] out) {
        final int[] sa = s.springA;
        final int[] sb = s.springB;
        final double[] u = dir;
        for (int i = 0; i < sa.length; i++) {
            final int a = 3 * sa[i];
            final int b = 3 * sb[i];
            final double ux = u[3 * i];
            final double uy = u[3 * i + 1];
            final double uz = u[3 * i + 2];
            final double beta = coef[2 * i + 1];
            final double rx = pv[b] - pv[a];
            final double ry = pv[b + 1] - pv[a + 1];
            final double rz = pv[b + 2] - pv[a + 2];
            final double ur = coef[2 * i] * (ux * rx + uy * ry + uz * rz);
            final double ax = ur * ux + beta * rx;
            final double ay = ur * uy + beta * ry;
            final double az = ur * uz + beta * rz;
            out[a] -= ax;
            out[a + 1] -= ay;
            out[a + 2] -= az;
            out[b] += ax;
            out[b + 1] += ay;
            out[b + 2] += az;
        }
    }
}
