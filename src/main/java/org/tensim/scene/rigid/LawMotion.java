package org.tensim.scene.rigid;

import org.tensim.model.AxisRotation;
import org.tensim.model.RigidMotion;
import org.tensim.model.Vec3;
import org.tensim.scene.conditions.TimeLaw;

/**
 * A rigid motion under a time law s(t): a rotation by {@code theta s(t)} about the axis of unit direction n through
 * the centre p (right-hand rule), then a translation {@code u s(t)}:
 * <pre>
 *   x(t) = p + R(n, theta s(t)) (x0 - p) + u s(t),   R by Rodrigues: cos I + sin [n]x + (1 - cos) n n^T
 * </pre>
 * A translation has theta = 0, a rotation u = 0. The rib law on a finite helical axis is
 * {@link org.tensim.scene.diaphragm.HelicalAxisMotion}. Allocation-free: evaluated inside the step.
 */
public final class LawMotion implements RigidMotion {
    private final AxisRotation axis;
    private final double angleRad;
    private final double ux;
    private final double uy;
    private final double uz;
    private final TimeLaw law;

    /**
     * @param axis         rotation axis (normalised here; any non-zero vector when angleRad is 0)
     * @param centre       a point of the axis, m
     * @param angleRad     rotation at s = 1, rad
     * @param displacement translation at s = 1, m
     * @param law          s(t), dimensionless
     */
    public LawMotion(Vec3 axis, Vec3 centre, double angleRad, Vec3 displacement, TimeLaw law) {
        this.axis = new AxisRotation(axis, centre);
        this.angleRad = angleRad;
        ux = displacement.x();
        uy = displacement.y();
        uz = displacement.z();
        this.law = law;
    }

    /** A translation by {@code displacement s(t)}, m. */
    public static LawMotion translation(Vec3 displacement, TimeLaw law) {
        return new LawMotion(new Vec3(0, 0, 1), Vec3.ZERO, 0, displacement, law);
    }

    @Override
    public void position(double t, Vec3 rest, double[] out, int o) {
        double s = law.value(t);
        double theta = angleRad * s;
        axis.apply(Math.cos(theta), Math.sin(theta), ux * s, uy * s, uz * s, rest.x(), rest.y(), rest.z(), out, o);
    }

    @Override
    public void pose(double t, double[] r, int ro, double[] translation, int to) {
        double s = law.value(t);
        double theta = angleRad * s;
        axis.pose(Math.cos(theta), Math.sin(theta), ux * s, uy * s, uz * s, r, ro, translation, to);
    }
}
