package org.tensim.io.mesh;

import java.util.Arrays;

/**
 * A triangle mesh that edge collapses change in place ({@link QuadricDecimation}): vertex-to-triangle lists,
 * the topological and geometric guards a collapse must pass, and the collapse itself.
 *
 * <p>Vertices carry a group (e.g. the two faces of a thin shell). A triangle whose corners are in one group is
 * pure; an edge between two vertices of a group is a border edge where the group's own surface ends: used by
 * one triangle (an open rim, a hole) or by two of which one is not pure (where a shell turns over from one face
 * to the other). A vertex is free when none of its triangles is mixed and none of its edges is a border edge;
 * on a border when it has exactly two border edges (it may only slide along them); locked otherwise (a corner,
 * a non-manifold edge).
 */
final class CollapseMesh {
    static final byte FREE = 0;
    static final byte BORDER = 1;
    static final byte LOCKED = 2;
    /** The smallest cosine between a triangle's normal before and after a collapse (60 degrees): no folds. */
    static final double MIN_NORMAL_COSINE = 0.5;
    /**
     * A collapse may not leave a triangle of quality 4 sqrt(3) A / (sum of squared edges) below this unless it was
     * lower before: a sliver is stiff across itself and sets a spring network's stable step alone.
     */
    static final double MIN_QUALITY = 0.2;

    final double[] xyz;
    final int[] tri;
    final int[] group;
    final boolean[] triangleAlive;
    final byte[] kind;
    int aliveTriangles;
    private int[][] vt;
    private final int[] vtCount;
    private final int[] mark;
    private int stamp;

    CollapseMesh(TriangleMesh m, int[] groups) {
        int nv = m.vertexCount();
        int nt = m.triangleCount();
        xyz = m.coordinates();
        tri = m.triangles();
        group = groups.clone();
        triangleAlive = new boolean[nt];
        Arrays.fill(triangleAlive, true);
        aliveTriangles = nt;
        vtCount = new int[nv];
        for (int i : tri) {
            vtCount[i]++;
        }
        vt = new int[nv][];
        for (int v = 0; v < nv; v++) {
            vt[v] = new int[Math.max(4, vtCount[v])];
            vtCount[v] = 0;
        }
        for (int t = 0; t < nt; t++) {
            for (int k = 0; k < 3; k++) {
                int v = tri[3 * t + k];
                vt[v][vtCount[v]++] = t;
            }
        }
        mark = new int[nv];
        kind = classify();
    }

    private byte[] classify() {
        int nv = vtCount.length;
        int[] borderEdges = new int[nv];
        boolean[] constrained = new boolean[nv];
        boolean[] locked = new boolean[nv];
        for (int v = 0; v < nv; v++) {
            stamp++;
            for (int i = 0; i < vtCount[v]; i++) {
                int t = vt[v][i];
                constrained[v] |= !pure(t);
                for (int c = 0; c < 3; c++) {
                    int w = tri[3 * t + c];
                    if (w <= v || mark[w] == stamp) {
                        continue; // each edge once, from its lower end
                    }
                    mark[w] = stamp;
                    int[] use = edgeUse(v, w);
                    if (use[0] > 2 || use[0] == 1 && group[v] != group[w]) {
                        locked[v] = locked[w] = true; // a non-manifold edge, or where an open rim meets a group's
                    } else if (border(v, w)) {
                        borderEdges[v]++;
                        borderEdges[w]++;
                    }
                }
            }
        }
        byte[] k = new byte[nv];
        for (int v = 0; v < nv; v++) {
            boolean onBorder = constrained[v] || borderEdges[v] > 0;
            k[v] = locked[v] || onBorder && borderEdges[v] != 2 ? LOCKED : onBorder ? BORDER : FREE;
        }
        return k;
    }

    boolean pure(int t) {
        int g = group[tri[3 * t]];
        return group[tri[3 * t + 1]] == g && group[tri[3 * t + 2]] == g;
    }

    boolean contains(int t, int v) {
        return tri[3 * t] == v || tri[3 * t + 1] == v || tri[3 * t + 2] == v;
    }

    /** {triangles using edge (a, b), pure ones among them}. */
    int[] edgeUse(int a, int b) {
        int n = 0;
        int p = 0;
        for (int i = 0; i < vtCount[a]; i++) {
            int t = vt[a][i];
            if (contains(t, b)) {
                n++;
                p += pure(t) ? 1 : 0;
            }
        }
        return new int[] {n, p};
    }

    /** Whether (a, b) is a border edge (see the class comment). */
    boolean border(int a, int b) {
        int[] use = edgeUse(a, b);
        return group[a] == group[b] && (use[0] == 1 || use[0] == 2 && use[1] == 1);
    }

    int triangleCount(int v) {
        return vtCount[v];
    }

    int triangle(int v, int i) {
        return vt[v][i];
    }

    /**
     * Whether removing vertex {@code a} into {@code b}, moved to (px, py, pz), keeps the mesh a 2-manifold
     * (the link condition: the vertices adjacent to both are exactly the third corners of the edge's triangles)
     * and unfolded (no surviving triangle turns by more than 60 degrees or falls below the quality floor).
     */
    boolean canCollapse(int a, int b, double px, double py, double pz) {
        int[] use = edgeUse(a, b);
        if (use[0] < 1 || use[0] > 2 || aliveTriangles - use[0] < 4) {
            return false;
        }
        stamp += 2;
        for (int i = 0; i < vtCount[a]; i++) {
            int t = vt[a][i];
            for (int c = 0; c < 3; c++) {
                mark[tri[3 * t + c]] = stamp;
            }
        }
        int common = 0;
        for (int i = 0; i < vtCount[b]; i++) {
            int t = vt[b][i];
            for (int c = 0; c < 3; c++) {
                int w = tri[3 * t + c];
                if (w != a && w != b && mark[w] == stamp) {
                    mark[w] = stamp + 1;
                    common++;
                }
            }
        }
        if (common != use[0]) {
            return false;
        }
        return keepsShape(a, b, a, px, py, pz) && keepsShape(b, a, b, px, py, pz);
    }

    /** The triangles of v without w, with corner {@code moved} at p: neither folded nor degenerate. */
    private boolean keepsShape(int v, int w, int moved, double px, double py, double pz) {
        double[] before = new double[3];
        double[] after = new double[3];
        for (int i = 0; i < vtCount[v]; i++) {
            int t = vt[v][i];
            if (contains(t, w)) {
                continue;
            }
            double ab = normal(t, -1, 0, 0, 0, before);
            double aa = normal(t, moved, px, py, pz, after);
            if (aa <= 0 || (before[0] * after[0] + before[1] * after[1] + before[2] * after[2])
                    < MIN_NORMAL_COSINE * ab * aa) {
                return false;
            }
            double q = quality(t, moved, px, py, pz, aa);
            if (q < MIN_QUALITY && q < quality(t, -1, 0, 0, 0, ab)) {
                return false;
            }
        }
        return true;
    }

    /** Twice the area normal of t (corner {@code moved} at p), into n; returns its length. */
    private double normal(int t, int moved, double px, double py, double pz, double[] n) {
        double[] p = corners(t, moved, px, py, pz);
        double ux = p[3] - p[0];
        double uy = p[4] - p[1];
        double uz = p[5] - p[2];
        double vx = p[6] - p[0];
        double vy = p[7] - p[1];
        double vz = p[8] - p[2];
        n[0] = uy * vz - uz * vy;
        n[1] = uz * vx - ux * vz;
        n[2] = ux * vy - uy * vx;
        return Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }

    /** 4 sqrt(3) A / (sum of squared edges): 1 for an equilateral triangle, 0 for a degenerate one. */
    private double quality(int t, int moved, double px, double py, double pz, double twiceArea) {
        double[] p = corners(t, moved, px, py, pz);
        double s = 0;
        for (int k = 0; k < 3; k++) {
            int l = (k + 1) % 3;
            for (int a = 0; a < 3; a++) {
                double d = p[3 * l + a] - p[3 * k + a];
                s += d * d;
            }
        }
        return s > 0 ? 2 * Math.sqrt(3) * twiceArea / s : 0;
    }

    private double[] corners(int t, int moved, double px, double py, double pz) {
        double[] p = new double[9];
        for (int k = 0; k < 3; k++) {
            int v = tri[3 * t + k];
            p[3 * k] = v == moved ? px : xyz[3 * v];
            p[3 * k + 1] = v == moved ? py : xyz[3 * v + 1];
            p[3 * k + 2] = v == moved ? pz : xyz[3 * v + 2];
        }
        return p;
    }

    /** Removes vertex a into b, b moved to p: the edge's triangles go, a's other triangles take b. */
    void collapse(int a, int b, double px, double py, double pz) {
        for (int i = 0; i < vtCount[a]; i++) {
            int t = vt[a][i];
            if (contains(t, b)) {
                triangleAlive[t] = false;
                aliveTriangles--;
                for (int c = 0; c < 3; c++) {
                    int w = tri[3 * t + c];
                    if (w != a) {
                        remove(w, t);
                    }
                }
            } else {
                for (int c = 0; c < 3; c++) {
                    if (tri[3 * t + c] == a) {
                        tri[3 * t + c] = b;
                    }
                }
                append(b, t);
            }
        }
        vtCount[a] = 0;
        xyz[3 * b] = px;
        xyz[3 * b + 1] = py;
        xyz[3 * b + 2] = pz;
    }

    private void remove(int v, int t) {
        for (int i = 0; i < vtCount[v]; i++) {
            if (vt[v][i] == t) {
                vt[v][i] = vt[v][--vtCount[v]];
                return;
            }
        }
    }

    private void append(int v, int t) {
        if (vtCount[v] == vt[v].length) {
            vt[v] = Arrays.copyOf(vt[v], 2 * vt[v].length);
        }
        vt[v][vtCount[v]++] = t;
    }
}
