package org.tensim.solver;

/**
 * Per-follower stiffnesses of a {@link SurfaceSliding} from a pressure-like stiffness: {@code k_i = k_A A_i} (N/m),
 * with k_A in Pa/m (the pressure that a penetration of 1 m would take) and A_i the follower's lumped area (m^2), a
 * third of the area of each of its own surface's triangles it is a corner of. So the held surface carries a pressure
 * {@code k_A pen} whatever the mesh's resolution, and refining the followers' surface does not stiffen it.
 *
 * <p>Choosing k_A: a penalty, not a material constant. A pressure P then costs a penetration P / k_A, so k_A = P /
 * tolerated penetration: the pleural pressure swings by about 3 cmH2O = 0.3 kPa over a quiet breath (-5 to -8
 * cmH2O; West, Respiratory Physiology: The Essentials, ch. 7), and a 0.1 mm tolerance gives k_A = 3e6 Pa/m. The explicit step then must stay below
 * {@code 2 sqrt(m_i / k_i)} for the lightest follower (and the surface nodes' share).
 */
public final class SlidingStiffness {
    private SlidingStiffness() {
    }

    /**
     * Lumped areas (m^2) of the followers on their own surface: each triangle's area at positions x shared in thirds
     * among its corners; a follower on no triangle gets 0.
     *
     * @param followers        node ids
     * @param followerSurface  3 node ids per triangle of the followers' own surface
     * @param x                positions, m, 3 per node
     * @throws IllegalArgumentException naming a triangle's node out of range
     */
    public static double[] lumpedAreas(int[] followers, int[] followerSurface, double[] x) {
        int nodes = x.length / 3;
        if (followerSurface.length % 3 != 0) {
            throw new IllegalArgumentException("a surface has 3 node ids per triangle: got " + followerSurface.length);
        }
        double[] nodeArea = new double[nodes];
        for (int t = 0; 3 * t < followerSurface.length; t++) {
            for (int c = 0; c < 3; c++) {
                int j = followerSurface[3 * t + c];
                if (j < 0 || j >= nodes) {
                    throw new IllegalArgumentException("follower surface triangle " + t + " has node " + j
                            + ": expected a node id in [0, " + nodes + ")");
                }
            }
            int a = 3 * followerSurface[3 * t];
            int b = 3 * followerSurface[3 * t + 1];
            int c = 3 * followerSurface[3 * t + 2];
            double e1x = x[b] - x[a], e1y = x[b + 1] - x[a + 1], e1z = x[b + 2] - x[a + 2];
            double e2x = x[c] - x[a], e2y = x[c + 1] - x[a + 1], e2z = x[c + 2] - x[a + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            double third = Math.sqrt(nx * nx + ny * ny + nz * nz) / 6;
            nodeArea[a / 3] += third;
            nodeArea[b / 3] += third;
            nodeArea[c / 3] += third;
        }
        double[] out = new double[followers.length];
        for (int e = 0; e < followers.length; e++) {
            if (followers[e] < 0 || followers[e] >= nodes) {
                throw new IllegalArgumentException("follower " + e + " is node " + followers[e]
                        + ": expected a node id in [0, " + nodes + ")");
            }
            out[e] = nodeArea[followers[e]];
        }
        return out;
    }

    /**
     * {@code k_i = k_A A_i}, N/m.
     *
     * @param pascalPerMetre k_A, Pa/m, positive and finite
     * @param areasM2        A_i, m^2, each positive (a follower without area would not be held)
     * @throws IllegalArgumentException naming the value that is not positive or finite
     */
    public static double[] fromPressure(double pascalPerMetre, double[] areasM2) {
        if (!(pascalPerMetre > 0) || Double.isInfinite(pascalPerMetre)) {
            throw new IllegalArgumentException("sliding stiffness " + pascalPerMetre
                    + " Pa/m: expected a positive finite pressure per length");
        }
        double[] k = new double[areasM2.length];
        for (int e = 0; e < k.length; e++) {
            if (!(areasM2[e] > 0) || Double.isInfinite(areasM2[e])) {
                throw new IllegalArgumentException("follower " + e + " has lumped area " + areasM2[e]
                        + " m^2: expected a positive area (is it on its surface's triangles?)");
            }
            k[e] = pascalPerMetre * areasM2[e];
        }
        return k;
    }
}
