package org.tensim.model;

/**
 * A prescribed trajectory of a driven node (kinematic boundary condition, e.g. a
 * rib moved by a finite-helical-axis law).
 */
@FunctionalInterface
public interface Motion {
    /**
     * Writes the node's position at time {@code tSeconds} (m) into
     * {@code out[offset..offset+2]}. Must not allocate: it is called inside the step.
     *
     * @param tSeconds simulated time, s
     * @param rest     the node's initial position, m
     */
    void position(double tSeconds, Vec3 rest, double[] out, int offset);
}
