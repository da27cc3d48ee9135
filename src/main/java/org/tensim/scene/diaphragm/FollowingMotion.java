package org.tensim.scene.diaphragm;

import java.util.List;
import org.tensim.model.RigidMotion;
import org.tensim.model.Vec3;

/**
 * A body carried by the mean displacement of some points of other moving bodies (the sternum by the
 * anterior ends of the true ribs): {@code x(t) = x0 + (1/n) sum_i (M_i(t) p_i - p_i)}, a translation.
 * Allocation-free; evaluated on the simulation's thread, like the ribs' own laws (the shift is recomputed at
 * every call: the rib amplitude may change between two calls at the same time).
 */
final class FollowingMotion implements RigidMotion {
    private final HelicalAxisMotion[] motions;
    private final Vec3[] points;
    private final double[] scratch = new double[3];
    private final double[] shift = new double[3];
    private double cachedT = Double.NaN;

    FollowingMotion(List<HelicalAxisMotion> motions, List<Vec3> points) {
        if (motions.isEmpty() || motions.size() != points.size()) {
            throw new IllegalArgumentException("a following motion needs as many points as motions, at least one");
        }
        this.motions = motions.toArray(new HelicalAxisMotion[0]);
        this.points = points.toArray(new Vec3[0]);
    }

    private synchronized void update(double t) {
        if (t == cachedT) {
            return;
        }
        double sx = 0;
        double sy = 0;
        double sz = 0;
        for (int i = 0; i < motions.length; i++) {
            motions[i].position(t, points[i], scratch, 0);
            sx += scratch[0] - points[i].x();
            sy += scratch[1] - points[i].y();
            sz += scratch[2] - points[i].z();
        }
        shift[0] = sx / motions.length;
        shift[1] = sy / motions.length;
        shift[2] = sz / motions.length;
        cachedT = t;
    }

    @Override
    public void position(double t, Vec3 rest, double[] out, int o) {
        // The rib amplitude may change between two calls at the same time (a GUI retune): no cache then.
        cachedT = Double.NaN;
        update(t);
        out[o] = rest.x() + shift[0];
        out[o + 1] = rest.y() + shift[1];
        out[o + 2] = rest.z() + shift[2];
    }

    @Override
    public void pose(double t, double[] rotation, int ro, double[] translation, int to) {
        cachedT = Double.NaN;
        update(t);
        for (int i = 0; i < 9; i++) {
            rotation[ro + i] = i % 4 == 0 ? 1 : 0;
        }
        translation[to] = shift[0];
        translation[to + 1] = shift[1];
        translation[to + 2] = shift[2];
    }
}
