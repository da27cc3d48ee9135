package org.tensim.experiment.diaphragm;

import java.util.Arrays;
import org.tensim.model.ContactBody;
import org.tensim.model.ContactPair;
import org.tensim.model.Topology;

/**
 * Each node's distance to the bones it may touch, at one instant: for the {@code displacements.csv} columns that
 * show where the sheet lies on the chest wall and where it has left it (docs/thorax.md).
 *
 * <p>For node i, {@code gap_i = min over its contact pairs with a bone of d_b(R_b(t)^T (x_i - c_b(t)))}, m: the
 * signed distance (negative inside) of the node's position to the bone's surface, the position taken back into the
 * bone's rest frame through its pose at time t. Only hard bodies count ({@link ContactBody#hard()}: ribs,
 * cartilages, sternum, vertebrae), not a compliant support such as the liver. Nodes without a pair with a bone get
 * NaN: nothing was within the contact range of them at rest.
 */
final class BoneGaps {
    private BoneGaps() {
    }

    /**
     * @param t     the scene's topology (its contact bodies and pairs)
     * @param x     positions, 3 per node, m
     * @param timeS the instant of {@code x}, s (the bones' poses)
     * @param nodes how many leading nodes to report on
     * @return per node its smallest signed distance to a bone it pairs with, m, or NaN
     */
    static double[] at(Topology t, double[] x, double timeS, int nodes) {
        double[] gap = new double[nodes];
        Arrays.fill(gap, Double.NaN);
        int bodies = t.contactBodies().size();
        double[] rot = new double[9 * bodies];
        double[] c = new double[3 * bodies];
        for (int b = 0; b < bodies; b++) {
            t.contactBodies().get(b).motion().pose(timeS, rot, 9 * b, c, 3 * b);
        }
        double[] grad = new double[3];
        for (ContactPair p : t.contacts()) {
            ContactBody body = t.contactBodies().get(p.body());
            if (p.node() >= nodes || !body.hard()) {
                continue;
            }
            int o = 3 * p.node();
            int r = 9 * p.body();
            double dx = x[o] - c[3 * p.body()];
            double dy = x[o + 1] - c[3 * p.body() + 1];
            double dz = x[o + 2] - c[3 * p.body() + 2];
            // R^T (x - c), R row-major: the inverse of the pose x = R x0 + c.
            double rx = rot[r] * dx + rot[r + 3] * dy + rot[r + 6] * dz;
            double ry = rot[r + 1] * dx + rot[r + 4] * dy + rot[r + 7] * dz;
            double rz = rot[r + 2] * dx + rot[r + 5] * dy + rot[r + 8] * dz;
            double d = body.surface().distance(rx, ry, rz, grad, 0);
            if (!(d >= gap[p.node()])) {
                gap[p.node()] = d; // NaN compares false: the first pair sets it
            }
        }
        return gap;
    }
}
