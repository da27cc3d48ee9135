package org.tensim.model;

/**
 * An immutable 3D vector, used where scenes are authored (directions, points).
 * The solver never uses it: it works on flat arrays.
 *
 * @param x first component
 * @param y second component
 * @param z third component
 */
public record Vec3(double x, double y, double z) {
    public static final Vec3 ZERO = new Vec3(0, 0, 0);

    public Vec3 {
        Check.finite("vector x", "", x);
        Check.finite("vector y", "", y);
        Check.finite("vector z", "", z);
    }

    public static Vec3 of(double x, double y, double z) {
        return new Vec3(x, y, z);
    }

    public double norm() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** Returns a new vector of unit length; refuses the zero vector. */
    public Vec3 normalized() {
        double n = norm();
        if (n == 0) {
            throw new IllegalArgumentException("a direction must not be the zero vector");
        }
        return new Vec3(x / n, y / n, z / n);
    }

    /** Returns {@code this + o} as a new vector. */
    public Vec3 plus(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    /** Returns {@code this - o} as a new vector. */
    public Vec3 minus(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    /** Returns {@code s * this} as a new vector. */
    public Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    /** Returns the cross product {@code this x o} as a new vector. */
    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double distance(Vec3 o) {
        return minus(o).norm();
    }
}
