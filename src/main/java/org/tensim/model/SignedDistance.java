package org.tensim.model;

/**
 * A closed surface as a signed distance function in its own (rest) frame: negative
 * inside, positive outside, zero on the surface, in metres. Used for contact
 * against rigid bodies ({@link ContactBody}).
 *
 * <p>Implementations must not allocate and must be safe to call from several
 * threads at once: they are evaluated inside the force pass.
 */
@FunctionalInterface
public interface SignedDistance {
    /**
     * The signed distance at point (x, y, z) of the body's rest frame, m, and its gradient (the
     * outward unit normal of the nearest surface point, dimensionless) into
     * {@code gradient[offset..offset+2]}.
     */
    double distance(double x, double y, double z, double[] gradient, int offset);
}
