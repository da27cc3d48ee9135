package org.tensim.io.mesh;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * A tetrahedral mesh in metres: node coordinates (3 doubles per node, interleaved) and 4-node tetrahedra (4 node
 * indices each), every one positively oriented: {@code (b - a) . ((c - a) x (d - a)) > 0}, the convention of Gmsh's
 * element type 4 and of VTK_TETRA (the first three corners counter-clockwise seen from the fourth). Its boundary
 * surface, the faces used by one tetrahedron only, wound counter-clockwise seen from outside, is kept as a
 * {@link TriangleMesh} over the boundary's own vertices ({@link #boundaryNode} gives the node of each), for drawing,
 * contact and loads. Immutable: arrays are copied in and out.
 */
public final class TetMesh {
    /** A tetrahedron is degenerate when its volume is at most this fraction of its longest edge cubed. */
    public static final double DEGENERATE_FRACTION = 1e-9;

    /** The outward faces of tet (0, 1, 2, 3): the face opposite each corner, wound counter-clockwise from outside. */
    private static final int[][] FACES = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

    private final double[] xyz;
    private final int[] tet;
    private final TriangleMesh boundary;
    private final int[] boundaryNode;

    /**
     * @param xyzMetres node coordinates, m, length 3 * nodes, all finite
     * @param tets      node indices, length 4 * tets, each in range, every tet positively oriented
     * @throws IllegalArgumentException naming the tet when one is inverted, degenerate or out of range
     */
    public TetMesh(double[] xyzMetres, int[] tets) {
        if (xyzMetres.length % 3 != 0 || tets.length % 4 != 0 || tets.length == 0) {
            throw new IllegalArgumentException("a tet mesh needs whole triples of coordinates and at least one"
                    + " quadruple of indices, got " + xyzMetres.length + " coordinates and " + tets.length
                    + " indices");
        }
        int n = xyzMetres.length / 3;
        for (int i = 0; i < xyzMetres.length; i++) {
            if (!Double.isFinite(xyzMetres[i])) {
                throw new IllegalArgumentException("tet mesh node " + i / 3 + " has a non-finite coordinate "
                        + xyzMetres[i]);
            }
        }
        for (int i = 0; i < tets.length; i++) {
            if (tets[i] < 0 || tets[i] >= n) {
                throw new IllegalArgumentException("tet " + i / 4 + " refers to node " + tets[i]
                        + ": expected 0 <= index < " + n);
            }
        }
        this.xyz = xyzMetres.clone();
        this.tet = tets.clone();
        for (int t = 0; t < tetCount(); t++) {
            String bad = shapeProblem(t);
            if (bad != null) {
                throw new IllegalArgumentException("tet " + t + " " + bad);
            }
        }
        Map<Long, int[]> faces = new HashMap<>();
        for (int t = 0; t < tetCount(); t++) {
            for (int[] f : FACES) {
                int a = tet[4 * t + f[0]];
                int b = tet[4 * t + f[1]];
                int c = tet[4 * t + f[2]];
                long key = faceKey(a, b, c, n);
                int[] seen = faces.get(key);
                if (seen == null) {
                    faces.put(key, new int[] {a, b, c, 1});
                } else {
                    seen[3]++;
                }
            }
        }
        int[] local = new int[n];
        Arrays.fill(local, -1);
        int[] nodes = new int[n];
        int count = 0;
        int[] tri = new int[3 * faces.size()];
        int triangles = 0;
        // in tet order, so that the surface does not depend on the hash map's order
        for (int t = 0; t < tetCount(); t++) {
            for (int[] f : FACES) {
                int[] seen = faces.get(faceKey(tet[4 * t + f[0]], tet[4 * t + f[1]], tet[4 * t + f[2]], n));
                if (seen[3] != 1) {
                    continue;
                }
                seen[3] = 0;
                for (int k = 0; k < 3; k++) {
                    int v = seen[k];
                    if (local[v] < 0) {
                        local[v] = count;
                        nodes[count++] = v;
                    }
                    tri[3 * triangles + k] = local[v];
                }
                triangles++;
            }
        }
        double[] bxyz = new double[3 * count];
        for (int i = 0; i < count; i++) {
            System.arraycopy(xyz, 3 * nodes[i], bxyz, 3 * i, 3);
        }
        this.boundary = new TriangleMesh(bxyz, Arrays.copyOf(tri, 3 * triangles));
        this.boundaryNode = Arrays.copyOf(nodes, count);
    }

    private static long faceKey(int a, int b, int c, int n) {
        int lo = Math.min(a, Math.min(b, c));
        int hi = Math.max(a, Math.max(b, c));
        int mid = a + b + c - lo - hi;
        return ((long) lo * n + mid) * n + hi;
    }

    /** Why tet t cannot be used (inverted, degenerate), or null when it can. */
    String shapeProblem(int t) {
        double v = volume(t);
        double longest = 0;
        for (int i = 0; i < 4; i++) {
            for (int j = i + 1; j < 4; j++) {
                longest = Math.max(longest, distance(tet[4 * t + i], tet[4 * t + j]));
            }
        }
        if (!(Math.abs(v) > DEGENERATE_FRACTION * longest * longest * longest)) {
            return String.format(Locale.ROOT, "(nodes %s) is degenerate: volume %.3g m^3 for a longest edge of %.3g m;"
                    + " expected a volume above %.0e times the longest edge cubed", Arrays.toString(nodes(t)), v,
                    longest, DEGENERATE_FRACTION);
        }
        if (v < 0) {
            return String.format(Locale.ROOT, "(nodes %s) is inverted: signed volume %.3g m^3; expected its corners"
                    + " ordered so that (b - a) . ((c - a) x (d - a)) > 0", Arrays.toString(nodes(t)), v);
        }
        return null;
    }

    private double distance(int a, int b) {
        double dx = xyz[3 * b] - xyz[3 * a];
        double dy = xyz[3 * b + 1] - xyz[3 * a + 1];
        double dz = xyz[3 * b + 2] - xyz[3 * a + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    public int nodeCount() {
        return xyz.length / 3;
    }

    public int tetCount() {
        return tet.length / 4;
    }

    /** Coordinate {@code axis} (0 x, 1 y, 2 z) of node v, m. */
    public double coord(int v, int axis) {
        return xyz[3 * v + axis];
    }

    /** Node index {@code corner} (0..3) of tet t. */
    public int corner(int t, int corner) {
        return tet[4 * t + corner];
    }

    /** The four node indices of tet t. */
    public int[] nodes(int t) {
        return Arrays.copyOfRange(tet, 4 * t, 4 * t + 4);
    }

    /** Signed volume of tet t, {@code (b - a) . ((c - a) x (d - a)) / 6}, m^3 (positive in a built mesh). */
    public double volume(int t) {
        int a = 3 * tet[4 * t];
        double[] u = new double[9];
        for (int k = 0; k < 3; k++) {
            int p = 3 * tet[4 * t + k + 1];
            for (int ax = 0; ax < 3; ax++) {
                u[3 * k + ax] = xyz[p + ax] - xyz[a + ax];
            }
        }
        return (u[0] * (u[4] * u[8] - u[5] * u[7]) - u[1] * (u[3] * u[8] - u[5] * u[6])
                + u[2] * (u[3] * u[7] - u[4] * u[6])) / 6;
    }

    /** Sum of the tets' volumes, m^3. */
    public double totalVolume() {
        double s = 0;
        for (int t = 0; t < tetCount(); t++) {
            s += volume(t);
        }
        return s;
    }

    /** A copy of the coordinates, m. */
    public double[] coordinates() {
        return xyz.clone();
    }

    /** A copy of the tet indices. */
    public int[] tets() {
        return tet.clone();
    }

    /** The boundary surface (faces of one tet only), outward, over its own vertices. */
    public TriangleMesh boundary() {
        return boundary;
    }

    /** The mesh node of boundary vertex i. */
    public int boundaryNode(int i) {
        return boundaryNode[i];
    }

    @Override
    public String toString() {
        return "TetMesh[" + nodeCount() + " nodes, " + tetCount() + " tets, " + boundary.triangleCount()
                + " boundary triangles]";
    }
}
