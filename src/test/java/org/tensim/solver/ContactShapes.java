package org.tensim.solver;

import org.tensim.model.ContactBody;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Vec3;

/** Analytic contact bodies and rigid motions for the contact tests. */
final class ContactShapes {
    static final double[] BOUNDS = {-1, -1, -1, 1, 1, 1};

    private ContactShapes() {
    }

    /** The half-space below the plane {@code n . y = h} (n normalised here): d = n . y - h. */
    static SignedDistance plane(double nx, double ny, double nz, double h) {
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double ax = nx / len;
        double ay = ny / len;
        double az = nz / len;
        return (x, y, z, g, o) -> {
            g[o] = ax;
            g[o + 1] = ay;
            g[o + 2] = az;
            return ax * x + ay * y + az * z - h;
        };
    }

    /** The ball of radius r about c: d = |y - c| - r. */
    static SignedDistance sphere(double cx, double cy, double cz, double r) {
        return (x, y, z, g, o) -> {
            double dx = x - cx;
            double dy = y - cy;
            double dz = z - cz;
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            g[o] = dx / len;
            g[o + 1] = dy / len;
            g[o + 2] = dz / len;
            return len - r;
        };
    }

    static ContactBody body(String name, SignedDistance sdf, RigidMotion motion) {
        return new ContactBody(name, sdf, motion, BOUNDS);
    }

    /** Turns by {@code w t} (rad) about z and translates by {@code c0 + u t} (m): x = R x0 + c. */
    static RigidMotion moving(Vec3 c0, Vec3 u, double w) {
        return new RigidMotion() {
            @Override
            public void pose(double t, double[] r, int ro, double[] c, int to) {
                double cs = Math.cos(w * t);
                double sn = Math.sin(w * t);
                r[ro] = cs;
                r[ro + 1] = -sn;
                r[ro + 2] = 0;
                r[ro + 3] = sn;
                r[ro + 4] = cs;
                r[ro + 5] = 0;
                r[ro + 6] = 0;
                r[ro + 7] = 0;
                r[ro + 8] = 1;
                c[to] = c0.x() + u.x() * t;
                c[to + 1] = c0.y() + u.y() * t;
                c[to + 2] = c0.z() + u.z() * t;
            }

            @Override
            public void position(double t, Vec3 rest, double[] out, int o) {
                double cs = Math.cos(w * t);
                double sn = Math.sin(w * t);
                out[o] = cs * rest.x() - sn * rest.y() + c0.x() + u.x() * t;
                out[o + 1] = sn * rest.x() + cs * rest.y() + c0.y() + u.y() * t;
                out[o + 2] = rest.z() + c0.z() + u.z() * t;
            }
        };
    }

    /** A translation at constant velocity u (m/s), no rotation. */
    static RigidMotion translating(Vec3 u) {
        return moving(Vec3.ZERO, u, 0);
    }
}
