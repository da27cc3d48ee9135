package org.tensim.solver;

import org.tensim.model.LinearMapping;

/**
 * The tangent stiffness of {@link SurfaceSliding} for the implicit integrators' products: the Gauss-Newton part of
 * {@code K = -df/dx} at the pairing and planes of one linearisation.
 *
 * <p>With follower i's displacement {@code z_i} and the surface points' {@code (W z)_p}, a paired follower (unit
 * normal n, barycentric coordinates beta of its projection on triangle (a, b, c), stiffness k) sees its distance
 * change by {@code n . u}, {@code u = z_i - sum_c beta_c (W z)_c}, so
 * <pre>
 *   (K z)_i  =  k n (n . u)
 *   (K z)_c  = -beta_c k n (n . u)     carried to the nodes by W^T
 * </pre>
 * the exact stiffness of the penalty along the normal with the plane's rotation and the projection's slide left out
 * (terms of order k pen / size, small against k while the followers stay near their gaps). It is symmetric and
 * positive semi-definite, so Newton-Krylov keeps a positive-definite system; the residual it solves is the exact
 * force, so leaving these terms out changes the iterations' count, not the answer. A CONTACT follower counts only
 * where it touches at the linearisation (pen &gt; 0, on the surface). Allocation-free after construction.
 */
final class SlidingTangent {
    private final int[] follower;
    private final double[] stiffness;
    private final LinearMapping mapping;
    private final SurfacePairing surface;
    private final int[] tri; // per follower: its triangle at the linearisation, -1 when it takes no force
    private final double[] normal; // 3 per follower
    private final double[] beta; // 3 per follower

    SlidingTangent(int[] follower, double[] stiffness, LinearMapping mapping, SurfacePairing surface) {
        this.follower = follower;
        this.stiffness = stiffness;
        this.mapping = mapping;
        this.surface = surface;
        this.tri = new int[follower.length];
        java.util.Arrays.fill(tri, -1);
        this.normal = new double[3 * follower.length];
        this.beta = new double[3 * follower.length];
    }

    /**
     * Records follower e's plane for the products: its triangle {@code t} (or -1: no force at the linearisation) and
     * {@code plane} = (n, d, beta) as {@link SurfacePairing#plane} writes it.
     */
    void set(int e, int t, double[] plane) {
        tri[e] = t;
        if (t < 0) {
            return;
        }
        for (int a = 0; a < 3; a++) {
            normal[3 * e + a] = plane[a];
            beta[3 * e + a] = plane[4 + a];
        }
    }

    /** {@code y += w K z}, layouts as {@link ForceTerm#multiplyAdd}. */
    void multiplyAdd(double[] z, double[] y, int[] offset, double w) {
        for (int e = 0; e < follower.length; e++) {
            final int t = tri[e];
            if (t < 0) {
                continue;
            }
            final double nx = normal[3 * e];
            final double ny = normal[3 * e + 1];
            final double nz = normal[3 * e + 2];
            final int of = offset == null ? 3 * follower[e] : offset[follower[e]];
            double nu = of >= 0 ? nx * z[of] + ny * z[of + 1] + nz * z[of + 2] : 0;
            for (int c = 0; c < 3; c++) {
                final int p = surface.corner(t, c);
                final double b = beta[3 * e + c];
                for (int k = 0, m = mapping.entries(p); k < m; k++) {
                    final int n = mapping.node(p, k);
                    final int o = offset == null ? 3 * n : offset[n];
                    if (o >= 0) {
                        nu -= b * mapping.weight(p, k) * (nx * z[o] + ny * z[o + 1] + nz * z[o + 2]);
                    }
                }
            }
            final double s = w * stiffness[e] * nu;
            if (s == 0) {
                continue;
            }
            if (of >= 0) {
                y[of] += s * nx;
                y[of + 1] += s * ny;
                y[of + 2] += s * nz;
            }
            for (int c = 0; c < 3; c++) {
                final int p = surface.corner(t, c);
                final double b = beta[3 * e + c];
                for (int k = 0, m = mapping.entries(p); k < m; k++) {
                    final int n = mapping.node(p, k);
                    final int o = offset == null ? 3 * n : offset[n];
                    if (o >= 0) {
                        final double q = -b * mapping.weight(p, k) * s;
                        y[o] += q * nx;
                        y[o + 1] += q * ny;
                        y[o + 2] += q * nz;
                    }
                }
            }
        }
    }

    /**
     * Adds each node's isotropic part, the trace of its diagonal block over 3: k / 3 on a follower, and
     * {@code (beta_c w)^2 k / 3} on a node carrying corner c of its triangle by weight w, at the planes recorded
     * (every follower counted as touching).
     */
    void addIsotropicStiffness(double[] perNode) {
        for (int e = 0; e < follower.length; e++) {
            final double k = stiffness[e];
            perNode[follower[e]] += k / 3;
            final int t = tri[e];
            if (t < 0) {
                continue;
            }
            for (int c = 0; c < 3; c++) {
                final int p = surface.corner(t, c);
                final double b = beta[3 * e + c];
                for (int q = 0, m = mapping.entries(p); q < m; q++) {
                    final double bw = b * mapping.weight(p, q);
                    perNode[mapping.node(p, q)] += bw * bw * k / 3;
                }
            }
        }
    }
}
