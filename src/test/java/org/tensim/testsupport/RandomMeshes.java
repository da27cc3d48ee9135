package org.tensim.testsupport;

import java.util.Random;
import org.tensim.model.Topology;

/**
 * Small random element sets among a few nodes, drawn from a seeded generator, for the tests of the
 * element kernels (forces against the energy's gradient, tangents against the forces' derivative).
 */
public final class RandomMeshes {
    /** Young's modulus of the random triangles, Pa (each drawn from [E/2, 3E/2)). */
    public static final double TRIANGLE_E = 30e3;
    /** Thickness of the random triangles, m (each drawn from [T/2, 3T/2)). */
    public static final double TRIANGLE_T = 2e-3;
    /** Transverse shear modulus kappa G of the random shear elements, Pa (each from [G/2, 3G/2)). */
    public static final double SHEAR_KAPPA_G = 5.0 / 6 * 40e3 / (2 * 1.45);
    /** Thickness of the random shear elements (the gap between the two faces), m. */
    public static final double SHEAR_T = 2.5e-3;

    private RandomMeshes() {
    }

    /**
     * Six membrane triangles among nine nodes of mass 1 kg in the unit cube, Poisson's ratio nu;
     * every other one with midpoint corners (its corners' two nodes differ).
     */
    public static Topology triangles(Random rnd, double nu) {
        Topology t = new Topology();
        int n = 9;
        for (int i = 0; i < n; i++) {
            t.addNode(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), 1);
        }
        for (int e = 0; e < 6; e++) {
            int[] p = new int[3];
            int[] q = new int[3];
            for (int k = 0; k < 3; k++) {
                p[k] = 3 * k + rnd.nextInt(3);
                q[k] = e % 2 == 0 ? p[k] : 3 * k + rnd.nextInt(3);
            }
            t.addTriangle(p, q, TRIANGLE_T * (0.5 + rnd.nextDouble()), TRIANGLE_E * (0.5 + rnd.nextDouble()), nu, 0);
        }
        return t;
    }

    /**
     * Eight transverse shear elements among a few nodes (upper 0..5 in a 1 cm square, lower 6..11 about
     * {@link #SHEAR_T} below them, perturbed), each with a damping time drawn from [beta/2, 3 beta/2)
     * (s; none for 0).
     */
    public static Topology shears(Random rnd, double beta) {
        Topology t = new Topology();
        for (int i = 0; i < 6; i++) {
            t.addNode(0.01 * rnd.nextDouble(), 0.01 * rnd.nextDouble(), 0, 1);
        }
        for (int i = 0; i < 6; i++) {
            var u = t.node(i).position();
            t.addNode(u.x() + 1e-3 * rnd.nextGaussian(), u.y() + 1e-3 * rnd.nextGaussian(), -SHEAR_T, 1);
        }
        for (int e = 0; e < 8; e++) {
            int i = rnd.nextInt(6);
            int j = (i + 1 + rnd.nextInt(5)) % 6;
            int k = j;
            while (k == i || k == j) {
                k = rnd.nextInt(6);
            }
            t.addShear(new int[] {i, j, k}, new int[] {6 + i, 6 + j, 6 + k}, SHEAR_KAPPA_G * (0.5 + rnd.nextDouble()),
                    SHEAR_T, beta == 0 ? 0 : beta * (0.5 + rnd.nextDouble()));
        }
        return t;
    }
}
