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
    private final double nx;
    private final double ny;
    private final double nz;
    private final double px;
    private final double py;
    private final double pz;
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
        Vec3 n = direction.normalized();
        nx = n.x();
        ny = n.y();
        nz = n.z();
        px = point.x();
        py = point.y();
        pz = point.z();
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
        double k = 1 - c;
        r[ro] = c + k * nx * nx;
        r[ro + 1] = -s * nz + k * nx * ny;
        r[ro + 2] = s * ny + k * nx * nz;
        r[ro + 3] = s * nz + k * ny * nx;
        r[ro + 4] = c + k * ny * ny;
        r[ro + 5] = -s * nx + k * ny * nz;
        r[ro + 6] = -s * ny + k * nz * nx;
        r[ro + 7] = s * nx + k * nz * ny;
        r[ro + 8] = c + k * nz * nz;
        translation[to] = px - (r[ro] * px + r[ro + 1] * py + r[ro + 2] * pz) + d * nx;
        translation[to + 1] = py - (r[ro + 3] * px + r[ro + 4] * py + r[ro + 5] * pz) + d * ny;
        translation[to + 2] = pz - (r[ro + 6] * px + r[ro + 7] * py + r[ro + 8] * pz) + d * nz;
    }

    /** Applies a rotation by theta and a translation d along the axis to (x, y, z); writes out[o..o+2]. */
    void apply(double theta, double d, double x, double y, double z, double[] out, int o) {
        rotate(Math.cos(theta), Math.sin(theta), d, x, y, z, out, o);
    }

    private void rotate(double c, double s, double d, double x, double y, double z, double[] out, int o) {
        double rx = x - px;
        double ry = y - py;
        double rz = z - pz;
        double dot = nx * rx + ny * ry + nz * rz;
        double cx = ny * rz - nz * ry;
        double cy = nz * rx - nx * rz;
        double cz = nx * ry - ny * rx;
        out[o] = px + rx * c + cx * s + nx * dot * (1 - c) + d * nx;
        out[o + 1] = py + ry * c + cy * s + ny * dot * (1 - c) + d * ny;
        out[o + 2] = pz + rz * c + cz * s + nz * dot * (1 - c) + d * nz;
    }
}
