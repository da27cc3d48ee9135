package org.tensim.model;

/**
 * A rotation about an axis of unit direction n through a point p, followed by a translation t: the pose
 * {@code x = p + R (x0 - p) + t} with R by Rodrigues' formula, {@code R = cos I + sin [n]x + (1 - cos) n n^T}
 * (right-hand rule). The rib law on a helical axis ({@code t = d n}) and a scene file's rotation and translation
 * laws share it. Allocation-free: evaluated inside the step, the angle given as its cosine and sine.
 */
public final class AxisRotation {
    private final double nx;
    private final double ny;
    private final double nz;
    private final double px;
    private final double py;
    private final double pz;

    /**
     * @param direction axis direction (normalised here)
     * @param point     a point of the axis, m
     */
    public AxisRotation(Vec3 direction, Vec3 point) {
        Vec3 n = direction.normalized();
        nx = n.x();
        ny = n.y();
        nz = n.z();
        px = point.x();
        py = point.y();
        pz = point.z();
    }

    /** The axis' unit direction's component a (0 x, 1 y, 2 z). */
    public double direction(int a) {
        return a == 0 ? nx : a == 1 ? ny : nz;
    }

    /**
     * Writes {@code p + R (x - p) + t} into out[o..o+2], R the rotation of cosine c and sine s, t = (tx, ty, tz), m.
     */
    public void apply(double c, double s, double tx, double ty, double tz, double x, double y, double z,
            double[] out, int o) {
        double rx = x - px;
        double ry = y - py;
        double rz = z - pz;
        double dot = nx * rx + ny * ry + nz * rz;
        double cx = ny * rz - nz * ry;
        double cy = nz * rx - nx * rz;
        double cz = nx * ry - ny * rx;
        out[o] = px + rx * c + cx * s + nx * dot * (1 - c) + tx;
        out[o + 1] = py + ry * c + cy * s + ny * dot * (1 - c) + ty;
        out[o + 2] = pz + rz * c + cz * s + nz * dot * (1 - c) + tz;
    }

    /**
     * Writes R (row-major) into r[ro..ro+8] and the pose's translation {@code p - R p + t} into tr[to..to+2], so
     * that x = R x0 + tr.
     */
    public void pose(double c, double s, double tx, double ty, double tz, double[] r, int ro, double[] tr, int to) {
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
        tr[to] = px - (r[ro] * px + r[ro + 1] * py + r[ro + 2] * pz) + tx;
        tr[to + 1] = py - (r[ro + 3] * px + r[ro + 4] * py + r[ro + 5] * pz) + ty;
        tr[to + 2] = pz - (r[ro + 6] * px + r[ro + 7] * py + r[ro + 8] * pz) + tz;
    }
}
