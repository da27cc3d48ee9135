package org.tensim.scene.rigid;

import org.tensim.model.SignedDistance;

/**
 * Exact signed distances of built-in rigid surfaces (m, negative inside, gradient the outward unit normal of the
 * nearest surface point), and the complement of any surface. Allocation-free and read-only: safe for the force
 * pass of several simulations at once.
 */
public final class RigidShapes {
    private RigidShapes() {
    }

    /**
     * The solid box of centre c and half-sides h (m, each &gt; 0): outside, the distance to the nearest point of the
     * box, {@code |max(q, 0)|} with {@code q = |p - c| - h}; inside, {@code max(q_x, q_y, q_z)} (minus the distance
     * to the nearest face), the gradient that face's normal.
     */
    public static SignedDistance box(double[] centre, double[] half) {
        double cx = centre[0];
        double cy = centre[1];
        double cz = centre[2];
        double hx = half[0];
        double hy = half[1];
        double hz = half[2];
        return (x, y, z, g, o) -> {
            double px = x - cx;
            double py = y - cy;
            double pz = z - cz;
            double qx = Math.abs(px) - hx;
            double qy = Math.abs(py) - hy;
            double qz = Math.abs(pz) - hz;
            if (qx > 0 || qy > 0 || qz > 0) {
                double ex = Math.max(qx, 0);
                double ey = Math.max(qy, 0);
                double ez = Math.max(qz, 0);
                double d = Math.sqrt(ex * ex + ey * ey + ez * ez);
                g[o] = Math.copySign(ex / d, px);
                g[o + 1] = Math.copySign(ey / d, py);
                g[o + 2] = Math.copySign(ez / d, pz);
                return d;
            }
            g[o] = 0;
            g[o + 1] = 0;
            g[o + 2] = 0;
            if (qx >= qy && qx >= qz) {
                g[o] = px >= 0 ? 1 : -1;
                return qx;
            }
            if (qy >= qz) {
                g[o + 1] = py >= 0 ? 1 : -1;
                return qy;
            }
            g[o + 2] = pz >= 0 ? 1 : -1;
            return qz;
        };
    }

    /** The solid ball of centre c and radius r (m, &gt; 0): {@code |p - c| - r}; at the centre the normal is +z. */
    public static SignedDistance sphere(double[] centre, double radius) {
        double cx = centre[0];
        double cy = centre[1];
        double cz = centre[2];
        return (x, y, z, g, o) -> {
            double px = x - cx;
            double py = y - cy;
            double pz = z - cz;
            double len = Math.sqrt(px * px + py * py + pz * pz);
            if (len == 0) {
                g[o] = 0;
                g[o + 1] = 0;
                g[o + 2] = 1;
            } else {
                g[o] = px / len;
                g[o + 1] = py / len;
                g[o + 2] = pz / len;
            }
            return len - radius;
        };
    }

    /**
     * The half-space below the plane through p with unit normal n (the solid is on the side away from n):
     * {@code (x - p) . n}.
     */
    public static SignedDistance plane(double[] point, double[] unitNormal) {
        double px = point[0];
        double py = point[1];
        double pz = point[2];
        double nx = unitNormal[0];
        double ny = unitNormal[1];
        double nz = unitNormal[2];
        return (x, y, z, g, o) -> {
            g[o] = nx;
            g[o + 1] = ny;
            g[o + 2] = nz;
            return (x - px) * nx + (y - py) * ny + (z - pz) * nz;
        };
    }

    /**
     * The complement of a surface's solid: {@code -phi}, gradient {@code -grad phi}. A box's complement is a cavity
     * (a block held inside it, a lung inside its chest wall); the pair of a surface and its complement holds a node
     * on the surface from both sides (sliding).
     */
    public static SignedDistance complement(SignedDistance s) {
        return (x, y, z, g, o) -> {
            double d = s.distance(x, y, z, g, o);
            g[o] = -g[o];
            g[o + 1] = -g[o + 1];
            g[o + 2] = -g[o + 2];
            return -d;
        };
    }
}
