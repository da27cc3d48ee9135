package org.tensim.scene;

import org.tensim.model.Check;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * The benchmark lattice: n x n x n nodes on a grid of spacing {@code spacingM},
 * springs between axis neighbours and along both diagonals of every face of every
 * grid cell, bottom face (y = 0) fixed, gravity along -y. With n = 31:
 * 29,791 nodes and 253,890 springs.
 */
public final class LatticeScene {
    private LatticeScene() {
    }

    /** Number of springs of the lattice of side n: 3 n^2 (n - 1) axis + 6 n (n - 1)^2 diagonal. */
    public static long springCount(int n) {
        return 3L * n * n * (n - 1) + 6L * n * (n - 1) * (n - 1);
    }

    /**
     * @param n               nodes per side (>= 2)
     * @param spacingM        grid spacing, m
     * @param nodeMassKg      node mass, kg
     * @param stiffnessNPerM  spring stiffness, N/m
     * @param dampingNsPerM   spring axial damping, N s/m
     * @param rigidDiagonals  also put rigid links along one body diagonal of every cell (times the projection)
     */
    public static Topology build(int n, double spacingM, double nodeMassKg, double stiffnessNPerM,
            double dampingNsPerM, boolean rigidDiagonals) {
        Check.atLeast("lattice size n", n, 2);
        Topology t = new Topology();
        Node[] g = new Node[n * n * n];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                for (int k = 0; k < n; k++) {
                    Node node = t.addNode(i * spacingM, j * spacingM, k * spacingM, nodeMassKg);
                    if (j == 0) {
                        node.fix();
                    }
                    g[(i * n + j) * n + k] = node;
                }
            }
        }
        int[][] offsets = {
            {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
            {1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1},
        };
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                for (int k = 0; k < n; k++) {
                    for (int[] o : offsets) {
                        int a = i + o[0];
                        int b = j + o[1];
                        int c = k + o[2];
                        if (a < n && b >= 0 && b < n && c >= 0 && c < n) {
                            t.addSpring(g[(i * n + j) * n + k], g[(a * n + b) * n + c], stiffnessNPerM,
                                    dampingNsPerM);
                        }
                    }
                    if (rigidDiagonals && i + 1 < n && j + 1 < n && k + 1 < n) {
                        t.addRigidLink(g[(i * n + j) * n + k], g[((i + 1) * n + j + 1) * n + k + 1]);
                    }
                }
            }
        }
        t.setGravity(new Vec3(0, -9.81, 0));
        return t;
    }
}
