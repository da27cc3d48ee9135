package org.tensim.model;

/**
 * A rigid motion over time: the pose {@code x(t) = R(t) x0 + c(t)} that carries a
 * body's rest-frame point x0 to where it is at time t. As a {@link Motion} it moves
 * a driven node the same way. Allocation-free.
 */
public interface RigidMotion extends Motion {
    /**
     * Writes R(t) row-major into {@code rotation[ro..ro+8]} and c(t), m, into
     * {@code translation[to..to+2]}.
     */
    void pose(double tSeconds, double[] rotation, int ro, double[] translation, int to);

    /** A body that does not move: R = I, c = 0. */
    RigidMotion FIXED = new RigidMotion() {
        @Override
        public void position(double tSeconds, Vec3 rest, double[] out, int offset) {
            out[offset] = rest.x();
            out[offset + 1] = rest.y();
            out[offset + 2] = rest.z();
        }

        @Override
        public void pose(double tSeconds, double[] rotation, int ro, double[] translation, int to) {
            for (int i = 0; i < 9; i++) {
                rotation[ro + i] = i % 4 == 0 ? 1 : 0;
            }
            translation[to] = 0;
            translation[to + 1] = 0;
            translation[to + 2] = 0;
        }
    };
}
