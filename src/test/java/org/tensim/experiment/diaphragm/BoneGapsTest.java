package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.ContactBody;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

class BoneGapsTest {
    private static final double[] BOUNDS = {-10, -10, -10, 10, 10, 10};

    /** The plane x0 = 0 of its rest frame, normal +x0. */
    private static final SignedDistance PLANE = (x, y, z, g, o) -> {
        g[o] = 1;
        g[o + 1] = 0;
        g[o + 2] = 0;
        return x;
    };

    /** A ball of radius 0.1 m about the origin of its rest frame. */
    private static final SignedDistance BALL = (x, y, z, g, o) -> {
        double r = Math.sqrt(x * x + y * y + z * z);
        g[o] = x / r;
        g[o + 1] = y / r;
        g[o + 2] = z / r;
        return r - 0.1;
    };

    /** Turned by w t about z and moved to (0, v t, 0): x = R x0 + c. */
    private static RigidMotion turning(double w, double v) {
        return new RigidMotion() {
            @Override
            public void pose(double t, double[] r, int ro, double[] c, int to) {
                double cs = Math.cos(w * t);
                double sn = Math.sin(w * t);
                double[] m = {cs, -sn, 0, sn, cs, 0, 0, 0, 1};
                System.arraycopy(m, 0, r, ro, 9);
                c[to] = 0;
                c[to + 1] = v * t;
                c[to + 2] = 0;
            }

            @Override
            public void position(double t, Vec3 rest, double[] out, int o) {
                double cs = Math.cos(w * t);
                double sn = Math.sin(w * t);
                out[o] = cs * rest.x() - sn * rest.y();
                out[o + 1] = sn * rest.x() + cs * rest.y() + v * t;
                out[o + 2] = rest.z();
            }
        };
    }

    @Test
    void gapIsTheSignedDistanceToTheNearestBoneInItsPoseAtThatTime() {
        Topology t = new Topology();
        for (int i = 0; i < 4; i++) {
            t.addNode(0, 0, 0, 1);
        }
        // At t = 2 s the plane body has turned a quarter turn (its x0 axis along world +y) and moved to y = 0.5 m:
        // it is the world plane y = 0.5 with its outside towards +y.
        double w = Math.PI / 4;
        int plane = t.addContactBody(new ContactBody("rib", PLANE, turning(w, 0.25), BOUNDS, true));
        int ball = t.addContactBody(new ContactBody("sternum", BALL, RigidMotion.FIXED, BOUNDS, true));
        int liver = t.addContactBody(new ContactBody("liver", PLANE, RigidMotion.FIXED, BOUNDS, false));
        t.addContact(0, plane, 1, 0);
        t.addContact(1, plane, 1, 0);
        t.addContact(1, ball, 1, 0);
        t.addContact(2, liver, 1, 0);
        double[] x = {
            3, 0.8, 1, // 0.3 m outside the plane
            0, 0.05, 0, // 0.45 m inside the plane, 0.05 m inside the ball: the plane's is the smaller
            -2, 0, 0, // only the liver, a soft support: no bone
            1, 1, 1}; // no pair
        double[] gap = BoneGaps.at(t, x, 2, 4);
        assertEquals(0.3, gap[0], 1e-12);
        assertEquals(-0.45, gap[1], 1e-12);
        assertTrue(Double.isNaN(gap[2]), "the liver is not a bone");
        assertTrue(Double.isNaN(gap[3]), "a node without a pair has no gap");

        // At rest the plane is the world plane x = 0: node 0 is 3 m outside it, node 1 0.05 m inside the ball.
        double[] rest = BoneGaps.at(t, x, 0, 4);
        assertEquals(3, rest[0], 1e-12);
        assertEquals(-0.05, rest[1], 1e-12);
        // Only the first nodes asked for are reported on.
        assertEquals(1, BoneGaps.at(t, x, 2, 1).length);
    }
}
