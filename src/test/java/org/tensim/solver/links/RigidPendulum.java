package org.tensim.solver.links;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * A pendulum on a rigid link, for the implicit steps that keep the links within stage 1 (BDF2,
 * implicit Euler): a bob on a rigid link of length L from a fixed pivot at the origin, under
 * gravity, pulled sideways by a spring to a fixed anchor; the bob starts hanging straight down,
 * with the spring stretched by a quarter of its rest length. At large steps a stage 1 that ignores
 * the link relaxes the spring freely before the projection puts the link back, and comes to rest
 * off the constrained equilibrium, where the forces along the link's tangent balance.
 */
public final class RigidPendulum {
    public static final double G = 9.81;
    public static final double M = 0.05; // kg
    public static final double L = 0.1; // m, the link
    static final double K = 40; // N/m, the side spring
    static final double CX = 0.12; // m, the side spring's anchor (CX, 0, CZ)
    static final double CZ = -0.02;

    private RigidPendulum() {
    }

    /** Pivot (node 0, fixed), bob (node 1), anchor (node 2, fixed). */
    public static Topology topology() {
        Topology t = new Topology();
        Node pivot = t.addNode(0, 0, 0, M).fix();
        Node bob = t.addNode(0, 0, -L, M);
        Node anchor = t.addNode(CX, 0, CZ, M).fix();
        t.addRigidLink(pivot, bob);
        t.addSpring(bob.id(), anchor.id(), K, 0.8 * Math.hypot(CX, CZ + L), 0.2 * Math.sqrt(K * M));
        t.setGravity(new Vec3(0, 0, -G));
        t.setViscousDamping(0.5 * Math.sqrt(K * M));
        return t;
    }

    /** dE/dtheta of the bob at angle theta from the downward vertical (towards +x), J/rad. */
    static double energySlope(double theta) {
        double bx = L * Math.sin(theta);
        double bz = -L * Math.cos(theta);
        double dx = bx - CX;
        double dz = bz - CZ;
        double len = Math.hypot(dx, dz);
        double rest = 0.8 * Math.hypot(CX, CZ + L);
        double tension = K * (len - rest); // N, along (dx, dz) / len
        double dbx = L * Math.cos(theta);
        double dbz = L * Math.sin(theta);
        return M * G * dbz + tension * (dx * dbx + dz * dbz) / len;
    }

    /** The constrained equilibrium angle, by bisection of dE/dtheta on (0, pi/4) (about 16 degrees), rad. */
    public static double equilibriumAngle() {
        double lo = 0;
        double hi = Math.PI / 4;
        assertTrue(energySlope(lo) < 0 && energySlope(hi) > 0, "an equilibrium between 0 and 45 degrees");
        for (int i = 0; i < 200; i++) {
            double mid = 0.5 * (lo + hi);
            if (energySlope(mid) < 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    }

    /** The bob's angle from the downward vertical towards +x in positions x (full layout), rad. */
    public static double angle(double[] x) {
        return Math.atan2(x[3], -x[5]);
    }
}
