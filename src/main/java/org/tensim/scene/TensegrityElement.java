package org.tensim.scene;

import java.util.ArrayList;
import java.util.List;
import org.tensim.model.Check;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * The tensegrity element of the paper's Fig. 1: 12 mass points and 6 rigid
 * elements (struts) held by springs (cables). This builder makes the classic
 * six-strut "expanded octahedron": three pairs of parallel struts, one pair along
 * each axis, with 24 cables joining each node to its four nearest nodes on struts
 * of the other two directions. (The paper's caption counts 22 springs; it gives no
 * drawing precise enough to tell which two of the 24 were left out, so the
 * symmetric 24 are used.)
 *
 * <p>With half-size h and half-spacing s, the struts along x join
 * (-h, 0, +-s) to (h, 0, +-s) about the centre; along y (+-s, -h, 0) to
 * (+-s, h, 0); along z (0, +-s, -h) to (0, +-s, h). Every node lies on a face of
 * the cube of side 2h: two nodes per face. Struts are {@code 2h} long.
 */
public final class TensegrityElement {
    /** The 12 nodes, in strut order: strut i joins nodes 2i and 2i+1. */
    public final List<Node> nodes;
    /** Strut pairs as node index pairs into {@link #nodes}. */
    public static final int STRUTS = 6;

    private TensegrityElement(List<Node> nodes) {
        this.nodes = nodes;
    }

    /**
     * Adds one element to a topology.
     *
     * @param centre        centre of the element, m
     * @param halfSize      h, half the strut length, m (> 0)
     * @param halfSpacing   s, half the distance between parallel struts, m (0 < s < h); h/2 is classic
     * @param nodeMass      mass of each node, kg
     * @param cableStiffness spring stiffness, N/m
     * @param cableDamping  axial damping of each cable, N s/m
     * @param rigid         true: the six struts are rigid links (tensegrity); false: no struts (mass-spring only)
     */
    public static TensegrityElement build(Topology t, Vec3 centre, double halfSize, double halfSpacing,
            double nodeMass, double cableStiffness, double cableDamping, boolean rigid) {
        Check.positive("tensegrity half size", "m", halfSize);
        Check.positive("tensegrity half spacing", "m", halfSpacing);
        if (halfSpacing >= halfSize) {
            throw new IllegalArgumentException("tensegrity half spacing must be smaller than the half size "
                    + halfSize + " m, got " + halfSpacing + " m");
        }
        double h = halfSize;
        double s = halfSpacing;
        double[][] p = {
            {-h, 0, -s}, {h, 0, -s}, {-h, 0, s}, {h, 0, s},     // struts along x
            {-s, -h, 0}, {-s, h, 0}, {s, -h, 0}, {s, h, 0},     // struts along y
            {0, -s, -h}, {0, -s, h}, {0, s, -h}, {0, s, h},     // struts along z
        };
        List<Node> nodes = new ArrayList<>();
        for (double[] q : p) {
            nodes.add(t.addNode(centre.x() + q[0], centre.y() + q[1], centre.z() + q[2], nodeMass));
        }
        if (rigid) {
            for (int i = 0; i < STRUTS; i++) {
                t.addRigidLink(nodes.get(2 * i), nodes.get(2 * i + 1));
            }
        }
        // Cables: every pair of nodes on struts of different directions at the shortest such distance.
        double shortest = Double.MAX_VALUE;
        for (int i = 0; i < 12; i++) {
            for (int j = i + 1; j < 12; j++) {
                if (i / 4 != j / 4) {
                    shortest = Math.min(shortest, nodes.get(i).position().distance(nodes.get(j).position()));
                }
            }
        }
        for (int i = 0; i < 12; i++) {
            for (int j = i + 1; j < 12; j++) {
                double d = nodes.get(i).position().distance(nodes.get(j).position());
                if (i / 4 != j / 4 && d < shortest * (1 + 1e-9)) {
                    t.addSpring(nodes.get(i), nodes.get(j), cableStiffness, cableDamping);
                }
            }
        }
        return new TensegrityElement(List.copyOf(nodes));
    }
}
