package org.tensim.scene.lungs;

import java.util.Arrays;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.thorax.TriangleTree;

/**
 * A lung's outer surface: its merged lobes' surface ({@link LungVolumes#surfaces}) without the fissure sheets, where
 * one lobe's surface lies on another's. The merged mesh's connected components (triangles joined through shared
 * vertex ids: the lobes) are found; a vertex is a <em>fissure vertex</em> when it lies within {@code fissureM} of
 * another component's surface or inside another component (winding number above 1/2); a triangle whose three
 * corners are all fissure vertices is dropped. A mesh of one component keeps every triangle.
 *
 * <p>The kept surface is compacted: only the vertices its triangles use, in increasing order of their merged ids,
 * with {@link #mergedVertex()} giving each one's id in the merged mesh.
 */
public final class LungOuterSurface {
    /**
     * Default fissure distance, m: 2 mm. The shared thorax's lobes' fissure surfaces lie within 0.5 mm of each
     * other for most of their vertices, with a tail to several mm near the fissures' rims; 2 mm drops the sheets,
     * and with them a strip of about 2 mm of outer surface beside each rim line.
     */
    public static final double DEFAULT_FISSURE_M = 0.002;

    private final TriangleMesh outer;
    private final int[] mergedVertex;
    private final int dropped;
    private final int components;

    private LungOuterSurface(TriangleMesh outer, int[] mergedVertex, int dropped, int components) {
        this.outer = outer;
        this.mergedVertex = mergedVertex;
        this.dropped = dropped;
        this.components = components;
    }

    /**
     * The outer surface of a merged lung surface.
     *
     * @param merged   the union of the lobes' closed, outward-wound surfaces, m
     * @param fissureM distance within which a vertex of one lobe lies on another lobe's surface, m, positive
     * @throws IllegalArgumentException when fissureM is not positive and finite, the mesh has no triangle, or no
     *                                  triangle is left
     */
    public static LungOuterSurface of(TriangleMesh merged, double fissureM) {
        if (!(fissureM > 0) || !Double.isFinite(fissureM)) {
            throw new IllegalArgumentException("fissure distance must be positive and finite (m), got " + fissureM);
        }
        if (merged.triangleCount() == 0) {
            throw new IllegalArgumentException("the merged lung surface has no triangle (" + merged + ")");
        }
        double[] xyz = merged.coordinates();
        int[] tri = merged.triangles();
        int nv = merged.vertexCount();
        int nt = merged.triangleCount();
        int[] comp = components(nv, tri);
        int nc = 0;
        for (int v = 0; v < nv; v++) {
            nc = Math.max(nc, comp[v] + 1);
        }
        boolean[] fissure = new boolean[nv];
        if (nc > 1) {
            TriangleTree[] trees = new TriangleTree[nc];
            int[][] byComp = new int[nc][];
            int[] fill = new int[nc];
            for (int t = 0; t < nt; t++) {
                fill[comp[tri[3 * t]]]++;
            }
            for (int c = 0; c < nc; c++) {
                byComp[c] = new int[3 * fill[c]];
                fill[c] = 0;
            }
            for (int t = 0; t < nt; t++) {
                int c = comp[tri[3 * t]];
                System.arraycopy(tri, 3 * t, byComp[c], fill[c], 3);
                fill[c] += 3;
            }
            int[] stack = new int[0];
            for (int c = 0; c < nc; c++) {
                trees[c] = new TriangleTree(xyz, byComp[c], 3);
                if (trees[c].newStack().length > stack.length) {
                    stack = trees[c].newStack();
                }
            }
            for (int v = 0; v < nv; v++) {
                if (comp[v] < 0) {
                    continue;
                }
                double x = xyz[3 * v], y = xyz[3 * v + 1], z = xyz[3 * v + 2];
                for (int c = 0; c < nc && !fissure[v]; c++) {
                    if (c == comp[v]) {
                        continue;
                    }
                    fissure[v] = trees[c].distance(x, y, z, stack) <= fissureM
                            || trees[c].winding(x, y, z, stack) > 0.5;
                }
            }
        }
        int[] keptTri = new int[tri.length];
        int kept = 0;
        boolean[] used = new boolean[nv];
        for (int t = 0; t < nt; t++) {
            int a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
            if (fissure[a] && fissure[b] && fissure[c]) {
                continue;
            }
            keptTri[3 * kept] = a;
            keptTri[3 * kept + 1] = b;
            keptTri[3 * kept + 2] = c;
            used[a] = used[b] = used[c] = true;
            kept++;
        }
        if (kept == 0) {
            throw new IllegalArgumentException("no triangle of the merged lung surface (" + merged
                    + ") is left outside the fissures at fissure distance " + fissureM + " m");
        }
        int[] newId = new int[nv];
        int[] toMerged = new int[nv];
        int n = 0;
        for (int v = 0; v < nv; v++) {
            if (used[v]) {
                newId[v] = n;
                toMerged[n++] = v;
            }
        }
        double[] oxyz = new double[3 * n];
        for (int i = 0; i < n; i++) {
            System.arraycopy(xyz, 3 * toMerged[i], oxyz, 3 * i, 3);
        }
        int[] otri = Arrays.copyOf(keptTri, 3 * kept);
        for (int i = 0; i < otri.length; i++) {
            otri[i] = newId[otri[i]];
        }
        return new LungOuterSurface(new TriangleMesh(oxyz, otri), Arrays.copyOf(toMerged, n), nt - kept, nc);
    }

    /** Component index 0.. of each vertex (by first appearance in the triangles), -1 for a vertex no triangle uses. */
    private static int[] components(int nv, int[] tri) {
        int[] parent = new int[nv];
        for (int v = 0; v < nv; v++) {
            parent[v] = v;
        }
        for (int i = 0; i < tri.length; i += 3) {
            union(parent, tri[i], tri[i + 1]);
            union(parent, tri[i], tri[i + 2]);
        }
        int[] label = new int[nv];
        Arrays.fill(label, -1);
        int[] comp = new int[nv];
        Arrays.fill(comp, -1);
        int n = 0;
        for (int v : tri) {
            int r = find(parent, v);
            if (label[r] < 0) {
                label[r] = n++;
            }
            comp[v] = label[r];
        }
        return comp;
    }

    private static int find(int[] parent, int v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    }

    private static void union(int[] parent, int a, int b) {
        parent[find(parent, a)] = find(parent, b);
    }

    /** The outer surface, m: the kept triangles over the vertices they use. */
    public TriangleMesh outer() {
        return outer;
    }

    /** For each outer vertex, its vertex id in the merged mesh (increasing). */
    public int[] mergedVertex() {
        return mergedVertex.clone();
    }

    /** Triangles of the merged mesh dropped as fissure sheet. */
    public int droppedTriangles() {
        return dropped;
    }

    /** Connected components of the merged mesh (the lobes). */
    public int components() {
        return components;
    }
}
