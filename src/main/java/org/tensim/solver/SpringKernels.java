package org.tensim.solver;

/**
 * The per-spring loops, shared by {@link ForceModel} and the parallel spring pass
 * ({@code org.tensim.solver.parallel.ParallelSpringPass}): static, monomorphic, no
 * allocation, no boxing, no calls. Spring i is two int offsets {@code sa[i]},
 * {@code sb[i]} (3 x node index, relative to the block's first node), its stiffness
 * {@code k[i]} (N/m) and rest length {@code rl[i]} (m), in separate arrays: measured
 * 5-10 % faster than one interleaved int array and one interleaved double array,
 * whose stride-2 indexing the JIT handles less well.
 *
 * <p>Being one loop for both, the same springs summed in the same order give the
 * same bits whether one thread or several compute them.
 */
public final class SpringKernels {
    private SpringKernels() {
    }

    /**
     * Undamped springs [0, count): positions read at {@code x[xo + sa[i]]}, forces added
     * at {@code f[sa[i]]} (end a) and subtracted at {@code f[sb[i]]} (end b).
     */
    public static void springs(int[] sa, int[] sb, double[] k, double[] rl, int count, double[] x, int xo, double[] f) {
        for (int i = 0; i < count; i++) {
            final int a = sa[i];
            final int b = sb[i];
            final int xa = xo + a;
            final int xb = xo + b;
            final double dx = x[xb] - x[xa];
            final double dy = x[xb + 1] - x[xa + 1];
            final double dz = x[xb + 2] - x[xa + 2];
            final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            // k (l - L) / l; coincident nodes exert no force (direction undefined).
            final double sc = len > 0 ? k[i] * (len - rl[i]) / len : 0;
            final double fx = sc * dx;
            final double fy = sc * dy;
            final double fz = sc * dz;
            addPair(f, a, b, fx, fy, fz);
        }
    }

    /** Springs with axial damping {@code c[i]} (N s/m); velocities read at {@code v[xo + sa[i]]}. */
    public static void springsDamped(int[] sa, int[] sb, double[] k, double[] rl, double[] c, int count, double[] x,
            double[] v, int xo, double[] f) {
        for (int i = 0; i < count; i++) {
            final int a = sa[i];
            final int b = sb[i];
            final int xa = xo + a;
            final int xb = xo + b;
            final double dx = x[xb] - x[xa];
            final double dy = x[xb + 1] - x[xa + 1];
            final double dz = x[xb + 2] - x[xa + 2];
            final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (len == 0) {
                continue;
            }
            final double inv = 1 / len;
            final double ux = dx * inv;
            final double uy = dy * inv;
            final double uz = dz * inv;
            final double vrel = (v[xb] - v[xa]) * ux + (v[xb + 1] - v[xa + 1]) * uy + (v[xb + 2] - v[xa + 2]) * uz;
            final double mag = k[i] * (len - rl[i]) + c[i] * vrel;
            final double fx = mag * ux;
            final double fy = mag * uy;
            final double fz = mag * uz;
            addPair(f, a, b, fx, fy, fz);
        }
    }

    /** f_a += (fx, fy, fz), f_b -= (fx, fy, fz): a spring's equal and opposite forces at offsets a, b. */
    private static void addPair(double[] f, int a, int b, double fx, double fy, double fz) {
        f[a] += fx;
        f[a + 1] += fy;
        f[a + 2] += fz;
        f[b] -= fx;
        f[b + 1] -= fy;
        f[b + 2] -= fz;
    }

    /**
     * The unit vector from a to b (offsets of their x components in x) into {@code dir[o..o+2]}, zero
     * when the two coincide (no direction); returns the distance |x_b - x_a| (m). The linearisations
     * of the springs and links of the implicit solvers share it, so that they see the same bits.
     */
    public static double direction(double[] x, int a, int b, double[] dir, int o) {
        final double dx = x[b] - x[a];
        final double dy = x[b + 1] - x[a + 1];
        final double dz = x[b + 2] - x[a + 2];
        final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        final double inv = len > 0 ? 1 / len : 0;
        dir[o] = dx * inv;
        dir[o + 1] = dy * inv;
        dir[o + 2] = dz * inv;
        return len;
    }
}
