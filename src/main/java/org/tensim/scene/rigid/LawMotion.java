package org.tensim.scene.rigid;

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
    private final double nx;
    private final double ny;
    private final double nz;
    private final double px;
    private final double py;
    private final double pz;
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
        Vec3 n = axis.normalized();
        nx = n.x();
        ny = n.y();
        nz = n.z();
        px = centre.x();
        py = centre.y();
        pz = centre.z();
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
        double c = Math.cos(theta);
        double sn = Math.sin(theta);
        double rx = rest.x() - px;
        double ry = rest.y() - py;
        double rz = rest.z() - pz;
        double dot = nx * rx + ny * ry + nz * rz;
        double cx = ny * rz - nz * ry;
        double cy = nz * rx - nx * rz;
        double cz = nx * ry - ny * rx;
        out[o] = px + rx * c + cx * sn + nx * dot * (1 - c) + ux * s;
        out[o + 1] = py + ry * c + cy * sn + ny * dot * (1 - c) + uy * s;
        out[o + 2] = pz + rz * c + cz * sn + nz * dot * (1 - c) + uz * s;
    }

    @Override
    public void pose(double t, double[] r, int ro, double[] translation, int to) {
        double s = law.value(t);
        double theta = angleRad * s;
        double c = Math.cos(theta);
        double sn = Math.sin(theta);
        double k = 1 - c;
        r[ro] = c + k * nx * nx;
        r[ro + 1] = -sn * nz + k * nx * ny;
        r[ro + 2] = sn * ny + k * nx * nz;
        r[ro + 3] = sn * nz + k * ny * nx;
        r[ro + 4] = c + k * ny * ny;
        r[ro + 5] = -sn * nx + k * ny * nz;
        r[ro + 6] = -sn * ny + k * nz * nx;
        r[ro + 7] = sn * nx + k * nz * ny;
        r[ro + 8] = c + k * nz * nz;
        translation[to] = px - (r[ro] * px + r[ro + 1] * py + r[ro + 2] * pz) + ux * s;
        translation[to + 1] = py - (r[ro + 3] * px + r[ro + 4] * py + r[ro + 5] * pz) + uy * s;
        translation[to + 2] = pz - (r[ro + 6] * px + r[ro + 7] * py + r[ro + 8] * pz) + uz * s;
    }
}
