package org.tensim.solver.parallel;

/**
 * The per-spring loops of {@link ParallelSpringPass}: static, monomorphic, no
 * allocation, no boxing, no calls. Each spring is two int offsets {@code ab[2i]},
 * {@code ab[2i+1]} (3 x node index, relative to the block's first node) and two
 * doubles {@code kl[2i]} = stiffness (N/m), {@code kl[2i+1]} = rest length (m),
 * interleaved so that one spring's data share a cache line.
 *
 * <p>The arithmetic is written exactly as in {@code ForceModel.springs} and
 * {@code ForceModel.springsDamped}, operation for operation, so that the same
 * springs summed in the same order give the same bits.
 */
final class SpringKernels {
    private SpringKernels() {
    }

    /**
     * Undamped springs [0, count): positions read at {@code x[xo + ab]}, forces added
     * at {@code f[ab]} (end a) and subtracted at {@code f[ab]} (end b).
     */
    static void springs(int[] ab, double[] kl, int count, double[] x, int xo, double[] f) {
        for (int i = 0; i < count; i++) {
            final int a = ab[2 * i];
            final int b = ab[2 * i + 1];
            final int xa = xo + a;
            final int xb = xo + b;
            final double dx = x[xb] - x[xa];
            final double dy = x[xb + 1] - x[xa + 1];
            final double dz = x[xb + 2] - x[xa + 2];
            final double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            // k (l - L) / l; coincident nodes exert no force (direction undefined).
            final double sc = len > 0 ? kl[2 * i] * (len - kl[2 * i + 1]) / len : 0;
            final double fx = sc * dx;
            final double fy = sc * dy;
            final double fz = sc * dz;
            f[a] += fx;
            f[a + 1] += fy;
            f[a + 2] += fz;
            f[b] -= fx;
            f[b + 1] -= fy;
            f[b + 2] -= fz;
        }
    }

    /** Springs with axial damping {@code c[i]} (N s/m); velocities read at {@code v[xo + ab]}. */
    static void springsDamped(int[] ab, double[] kl, double[] c, int count, double[] x, double[] v, int xo,
            double[] f) {
        for (int i = 0; i < count; i++) {
            final int a = ab[2 * i];
            final int b = ab[2 * i + 1];
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
            final double mag = kl[2 * i] * (len - kl[2 * i + 1]) + c[i] * vrel;
            final double fx = mag * ux;
            final double fy = mag * uy;
            final double fz = mag * uz;
            f[a] += fx;
            f[a + 1] += fy;
            f[a + 2] += fz;
            f[b] -= fx;
            f[b + 1] -= fy;
            f[b + 2] -= fz;
        }
    }
}
