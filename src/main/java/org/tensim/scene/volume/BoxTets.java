package org.tensim.scene.volume;

import org.tensim.io.mesh.TetMesh;

/**
 * A structured tetrahedral mesh of a box {@code [0, lx] x [0, ly] x [0, lz]} (m) of nx x ny x nz cells (cubes when
 * the sides are in the ratio of the counts), each cut into tetrahedra ({@link Split}): six around its diagonal from
 * (0, 0, 0) to (1, 1, 1) (Kuhn's subdivision: the tets {@code 0 -> e_a -> e_a + e_b -> (1, 1, 1)} for the six orders
 * of the axes, congruent or mirror images, each with three cube edges, two face diagonals and the body diagonal),
 * or five. Both conform across cells.
 */
public final class BoxTets {
    private BoxTets() {
    }

    /** How a cube is cut. */
    public enum Split {
        /** Six congruent tets around the diagonal (0, 0, 0)-(1, 1, 1), every cube alike (Kuhn). */
        SIX,
        /**
         * Five tets: a regular one on four corners no two of which share a cube edge, and four right-angled corner
         * tets; the cubes alternate between the two choices of those four corners (by the parity of i + j + k), so
         * that the face diagonals match across faces.
         */
        FIVE
    }

    /** Kuhn's six tets, corners as bits (x 1, y 2, z 4), each positively oriented. */
    private static final int[][] KUHN = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7},
        {0, 5, 1, 7}};
    /** The five tets of an even cube: the regular tet (1, 2, 4, 7) and the corners 0, 3, 5, 6. */
    private static final int[][] FIVE_EVEN = {{1, 2, 4, 7}, {0, 1, 2, 4}, {3, 2, 1, 7}, {5, 1, 4, 7},
        {6, 4, 2, 7}};
    /** The five tets of an odd cube: the regular tet (0, 3, 5, 6) and the corners 1, 2, 4, 7. */
    private static final int[][] FIVE_ODD = {{0, 5, 3, 6}, {1, 3, 0, 5}, {2, 0, 3, 6}, {4, 5, 0, 6},
        {7, 5, 6, 3}};

    /** As {@link #of(double, double, double, int, int, int, Split)} with six tets a cube. */
    public static TetMesh of(double lx, double ly, double lz, int nx, int ny, int nz) {
        return of(lx, ly, lz, nx, ny, nz, Split.SIX);
    }

    /** The box's mesh, its nodes in lattice order (x fastest), every tet positively oriented. */
    public static TetMesh of(double lx, double ly, double lz, int nx, int ny, int nz, Split split) {
        if (nx < 1 || ny < 1 || nz < 1) {
            throw new IllegalArgumentException("a tet box needs at least one cube along each axis, got " + nx + " x "
                    + ny + " x " + nz);
        }
        int px = nx + 1;
        int py = ny + 1;
        int pz = nz + 1;
        double[] xyz = new double[3 * px * py * pz];
        for (int k = 0; k < pz; k++) {
            for (int j = 0; j < py; j++) {
                for (int i = 0; i < px; i++) {
                    int q = (k * py + j) * px + i;
                    xyz[3 * q] = lx * i / nx;
                    xyz[3 * q + 1] = ly * j / ny;
                    xyz[3 * q + 2] = lz * k / nz;
                }
            }
        }
        int[][] even = split == Split.SIX ? KUHN : FIVE_EVEN;
        int[][] odd = split == Split.SIX ? KUHN : FIVE_ODD;
        int[] tets = new int[4 * even.length * nx * ny * nz];
        int t = 0;
        for (int k = 0; k < nz; k++) {
            for (int j = 0; j < ny; j++) {
                for (int i = 0; i < nx; i++) {
                    for (int[] corner : (i + j + k) % 2 == 0 ? even : odd) {
                        for (int c = 0; c < 4; c++) {
                            int bits = corner[c];
                            tets[4 * t + c] = ((k + (bits >> 2 & 1)) * py + j + (bits >> 1 & 1)) * px + i
                                    + (bits & 1);
                        }
                        t++;
                    }
                }
            }
        }
        return new TetMesh(xyz, tets);
    }

    /**
     * The same mesh with each node strictly inside the box moved by a uniform random offset of up to
     * {@code fraction} of the local cell size h along each axis (seeded: the same seed gives the same mesh), the
     * boundary's nodes kept, so that the faces stay planar: an irregular mesh of the same box, for measuring what
     * the identification gives on tets of many shapes.
     *
     * @param fraction at most 0.15: a node moves at most {@code 0.15 sqrt(3) h = 0.26 h}, less than half the smallest
     *                 height of the splits' tets (0.577 h for the five-tet split's corners, 0.707 h for Kuhn's), so
     *                 that no tet inverts
     * @param h        the cell size of {@code mesh}, m
     */
    public static TetMesh jittered(TetMesh mesh, double h, double fraction, long seed) {
        if (!(fraction >= 0 && fraction <= 0.15)) {
            throw new IllegalArgumentException("tet jitter must be 0 to 0.15 of a cell, got " + fraction);
        }
        double[] xyz = mesh.coordinates();
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int v = 0; v < mesh.nodeCount(); v++) {
            for (int a = 0; a < 3; a++) {
                lo[a] = Math.min(lo[a], xyz[3 * v + a]);
                hi[a] = Math.max(hi[a], xyz[3 * v + a]);
            }
        }
        java.util.Random r = new java.util.Random(seed);
        double eps = 1e-9 * h;
        for (int v = 0; v < mesh.nodeCount(); v++) {
            boolean inside = true;
            for (int a = 0; a < 3; a++) {
                inside &= xyz[3 * v + a] > lo[a] + eps && xyz[3 * v + a] < hi[a] - eps;
            }
            if (inside) {
                for (int a = 0; a < 3; a++) {
                    xyz[3 * v + a] += fraction * h * (2 * r.nextDouble() - 1);
                }
            }
        }
        return new TetMesh(xyz, mesh.tets());
    }
}
