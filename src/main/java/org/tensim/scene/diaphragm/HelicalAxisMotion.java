package org.tensim.scene.diaphragm;

import org.tensim.model.RigidMotion;
import org.tensim.model.Vec3;

/**
 * A rib's kinematic law by the finite helical axis method (Woltring et al. 1985;
 * as the paper's reference [4]): the rib is rigid, and its pose at breathing level
 * {@code s(t)} is a rotation by {@code theta(t)} about an axis (unit direction
 * {@code n}, through point {@code p}) followed by a translation {@code d(t)} along
 * that same axis:
 * <pre>
 *   x(t) = p + R(n, theta) (x0 - p) + d n,   theta = A theta_max s(t),   d = A d_max s(t)
 * </pre>
 * with R by Rodrigues' formula and A the live rib amplitude of
 * {@link DiaphragmControls}. Allocation-free: it is evaluated inside the step.
 */
public final class HelicalAxisMotion implements RigidMotion {
    private final org.tensim.model.AxisRotation axis;
    private final double maxAngleRad;
    private final double maxTranslationM;
    private final BreathingCycle cycle;
    private final DiaphragmControls controls;
    // Small cache: the step asks for the same few times (t, t +/- eps) for every node of the rib.
    private final double[] cacheT = {Double.NaN, Double.NaN, Double.NaN, Double.NaN};
    private final double[] cacheCos = new double[4];
    private final double[] cacheSin = new double[4];
    private final double[] cacheD = new double[4];
    private final double[] cacheAmp = new double[4];
    private int cacheNext;

    /**
     * @param direction       axis direction (normalised here)
     * @param point           a point on the axis, m
     * @param maxAngleRad     rotation at end-inspiration for amplitude 1, rad (sign by the right-hand rule)
     * @param maxTranslationM translation along the axis at end-inspiration for amplitude 1, m
     */
    public HelicalAxisMotion(Vec3 direction, Vec3 point, double maxAngleRad, double maxTranslationM,
            BreathingCycle cycle, DiaphragmControls controls) {
        axis = new org.tensim.model.AxisRotation(direction, point);
        this.maxAngleRad = org.tensim.model.Check.finite("rib rotation", "rad", maxAngleRad);
        this.maxTranslationM = org.tensim.model.Check.finite("rib translation", "m", maxTranslationM);
        this.cycle = cycle;
        this.controls = controls;
    }

    /** Rotation at end-inspiration for amplitude 1, rad. */
    public double maxAngleRad() {
        return maxAngleRad;
    }

    public double maxTranslationM() {
        return maxTranslationM;
    }

    @Override
    public void position(double t, Vec3 rest, double[] out, int o) {
        double amp = controls.ribAmplitude();
        int slot = -1;
        for (int i = 0; i < cacheT.length; i++) {
            if (cacheT[i] == t && cacheAmp[i] == amp) {
                slot = i;
                break;
            }
        }
        if (slot < 0) {
            slot = cacheNext;
            cacheNext = (cacheNext + 1) % cacheT.length;
            double level = amp * cycle.level(t);
            double theta = level * maxAngleRad;
            cacheT[slot] = t;
            cacheAmp[slot] = amp;
            cacheCos[slot] = Math.cos(theta);
            cacheSin[slot] = Math.sin(theta);
            cacheD[slot] = level * maxTranslationM;
        }
        rotate(cacheCos[slot], cacheSin[slot], cacheD[slot], rest.x(), rest.y(), rest.z(), out, o);
    }

    /**
     * The pose at time t as a rotation R (row-major, Rodrigues: {@code R = cos I + sin [n]x + (1 - cos) n n^T})
     * and translation {@code c = p - R p + d n}: x = R x0 + c. Allocation-free.
     */
    @Override
    public void pose(double t, double[] r, int ro, double[] translation, int to) {
        double level = controls.ribAmplitude() * cycle.level(t);
        double theta = level * maxAngleRad;
        double c = Math.cos(theta);
        double s = Math.sin(theta);
        double d = level * maxTranslationM;
        axis.pose(c, s, d * axis.direction(0), d * axis.direction(1), d * axis.direction(2), r, ro, translation, to);
    }

    /** Applies a rotation by theta and a translation d along the axis to (x, y, z); writes out[o..o+2]. */
    void apply(double theta, double d, double x, double y, double z, double[] out, int o) {
        rotate(Math.cos(theta), Math.sin(theta), d, x, y, z, out, o);
    }

    private void rotate(double c, double s, double d, double x, double y, double z, double[] out, int o) {
        axis.apply(c, s, d * axis.direction(0), d * axis.direction(1), d * axis.direction(2), x, y, z, out, o);
    }
}
