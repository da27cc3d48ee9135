package org.tensim.scene.shell;

/**
 * Edge springs of a linear triangle membrane (identification of Van Gelder 1998, "Approximate
 * simulation of elastic membranes by triangulated spring meshes", J. Graphics Tools 3(2)).
 *
 * <p>An edge e shared by the triangles T gets {@code k_e = E t sum_T A_T / |e|^2} (N/m). For an
 * equilateral triangle this is {@code sqrt(3)/4 E t} per triangle, the value that Lloyd, Szekely
 * and Harders (IEEE TVCG 13(5), 2007) derive by matching the linear finite element's stiffness
 * matrix; the match is exact there for Poisson's ratio 1/3 only (a network of pure edge springs
 * has that ratio whatever E), so on equilateral triangles the network reproduces a uniaxial
 * stretch {@code sigma / E} exactly. Other shapes are approximated (measured by the patch test,
 * {@code docs/diaphragm.md}).
 */
public final class TriangleMembrane {
    /** Poisson's ratio of a network of edge springs on equilateral triangles. */
    public static final double NETWORK_POISSON = 1.0 / 3;

    private TriangleMembrane() {
    }

    /**
     * Stiffness of one edge spring, N/m.
     *
     * @param membraneNPerM   in-plane modulus times thickness carried by this network, E t, N/m
     * @param adjacentAreaM2  sum of the areas of the triangles on the edge, m^2
     * @param edgeLengthM     rest length of the edge, m
     */
    public static double edgeStiffness(double membraneNPerM, double adjacentAreaM2, double edgeLengthM) {
        return membraneNPerM * adjacentAreaM2 / (edgeLengthM * edgeLengthM);
    }
}
