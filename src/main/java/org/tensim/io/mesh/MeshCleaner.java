package org.tensim.io.mesh;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import org.tensim.model.Check;

/**
 * Repairs what imported meshes commonly get wrong before a topology is built
 * from them: duplicate vertices (STL stores each triangle's corners separately;
 * seams), degenerate triangles, and small disconnected pieces (decimation
 * leftovers: the BodyParts3D diaphragm has 57 specks besides its main body). It
 * also counts what it found ({@link MeshReport}): components, boundary loops and
 * non-manifold edges. Unused vertices are removed; vertex order is otherwise kept.
 */
public final class MeshCleaner {
    /**
     * Cleaning settings.
     *
     * @param weldToleranceM         vertices closer than this are merged, m (>= 0; 0 merges exact duplicates)
     * @param minComponentFraction   components with fewer than this fraction of all triangles are dropped
     *                               (0 keeps every piece; 0.01 drops specks under 1 %), in [0, 1)
     */
    public record Options(double weldToleranceM, double minComponentFraction) {
        public Options {
            Check.nonNegative("weld tolerance", "m", weldToleranceM);
            if (!(minComponentFraction >= 0 && minComponentFraction < 1)) {
                throw new IllegalArgumentException("smallest kept component must be a fraction in [0, 1) of the"
                        + " triangles, got " + minComponentFraction);
            }
        }

        /** 1 micrometre welding, components under 1 % of the triangles dropped. */
        public static Options defaults() {
            return new Options(1e-6, 0.01);
        }

        /** The same with every component kept. */
        public Options keepingAllComponents() {
            return new Options(weldToleranceM, 0);
        }
    }

    /** A cleaned mesh and the report of what was done. */
    public record Result(TriangleMesh mesh, MeshReport report) {
    }

    private MeshCleaner() {
    }

    /** Welds, drops degenerate triangles and small components; {@code name} labels the report. */
    public static Result clean(TriangleMesh raw, Options o, String name) {
        int nv = raw.vertexCount();
        int[] rep = weld(raw, o.weldToleranceM());
        int welded = 0;
        for (int i = 0; i < nv; i++) {
            welded += rep[i] != i ? 1 : 0;
        }
        // Degenerate triangles: repeated corner after welding, or an area below (1e-12 of the edge scale)^2.
        int nt = raw.triangleCount();
        int[] tri = new int[3 * nt];
        int kept = 0;
        int degenerate = 0;
        double[] n = new double[3];
        for (int t = 0; t < nt; t++) {
            int a = rep[raw.corner(t, 0)];
            int b = rep[raw.corner(t, 1)];
            int c = rep[raw.corner(t, 2)];
            raw.normal(t, n);
            double twiceArea = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            double scale = edgeScale(raw, t);
            if (a == b || b == c || a == c || !(twiceArea > 1e-12 * scale * scale)) {
                degenerate++;
                continue;
            }
            tri[3 * kept] = a;
            tri[3 * kept + 1] = b;
            tri[3 * kept + 2] = c;
            kept++;
        }
        tri = Arrays.copyOf(tri, 3 * kept);
        int used = countUsed(tri, nv);

        // Components: triangles joined through shared edges (a bow-tie vertex does not join two pieces).
        int[] parent = componentsByEdges(tri, nv);
        Map<Integer, Integer> compTriangles = new HashMap<>();
        for (int t = 0; t < kept; t++) {
            compTriangles.merge(find(parent, t), 1, Integer::sum);
        }
        int[] edgeStats = edgeStatistics(tri, nv);

        int minTriangles = (int) Math.ceil(o.minComponentFraction() * kept);
        int droppedComponents = 0;
        int droppedTriangles = 0;
        for (int count : compTriangles.values()) {
            if (count < minTriangles) {
                droppedComponents++;
                droppedTriangles += count;
            }
        }
        int[] finalTri = new int[3 * (kept - droppedTriangles)];
        int k = 0;
        for (int t = 0; t < kept; t++) {
            if (compTriangles.get(find(parent, t)) >= minTriangles) {
                System.arraycopy(tri, 3 * t, finalTri, 3 * k++, 3);
            }
        }
        // Compact: keep used vertices in their original order.
        int[] newIndex = new int[nv];
        Arrays.fill(newIndex, -1);
        for (int idx : finalTri) {
            newIndex[idx] = 0;
        }
        int m = 0;
        double[] xyz = new double[3 * nv];
        for (int i = 0; i < nv; i++) {
            if (newIndex[i] == 0) {
                newIndex[i] = m;
                for (int a = 0; a < 3; a++) {
                    xyz[3 * m + a] = raw.coord(i, a);
                }
                m++;
            }
        }
        for (int i = 0; i < finalTri.length; i++) {
            finalTri[i] = newIndex[finalTri[i]];
        }
        TriangleMesh mesh = new TriangleMesh(Arrays.copyOf(xyz, 3 * m), finalTri);
        MeshReport r = new MeshReport(name, nv, nt, welded, degenerate, used, kept, compTriangles.size(),
                edgeStats[2], edgeStats[0], edgeStats[1], droppedComponents, droppedTriangles, m, k);
        return new Result(mesh, r);
    }

    /** Representative of each vertex: itself, or the first earlier vertex within tol. */
    private static int[] weld(TriangleMesh raw, double tol) {
        int nv = raw.vertexCount();
        int[] rep = new int[nv];
        Map<Long, int[]> cells = new HashMap<>();
        double cell = tol > 0 ? tol : 1;
        double tol2 = tol * tol;
        for (int i = 0; i < nv; i++) {
            double x = raw.coord(i, 0);
            double y = raw.coord(i, 1);
            double z = raw.coord(i, 2);
            long cx = (long) Math.floor(x / cell);
            long cy = (long) Math.floor(y / cell);
            long cz = (long) Math.floor(z / cell);
            int found = -1;
            search:
            for (long dx = -1; dx <= 1; dx++) {
                for (long dy = -1; dy <= 1; dy++) {
                    for (long dz = -1; dz <= 1; dz++) {
                        int[] list = cells.get(key(cx + dx, cy + dy, cz + dz));
                        if (list == null) {
                            continue;
                        }
                        for (int j = 1; j <= list[0]; j++) {
                            int r = list[j];
                            double ex = raw.coord(r, 0) - x;
                            double ey = raw.coord(r, 1) - y;
                            double ez = raw.coord(r, 2) - z;
                            double d2 = ex * ex + ey * ey + ez * ez;
                            if (tol > 0 ? d2 <= tol2 : d2 == 0) {
                                found = r;
                                break search;
                            }
                        }
                    }
                }
            }
            if (found >= 0) {
                rep[i] = found;
            } else {
                rep[i] = i;
                cells.merge(key(cx, cy, cz), new int[] {1, i}, (old, add) -> {
                    int[] grown = old[0] + 1 < old.length ? old : Arrays.copyOf(old, 2 * old.length);
                    grown[++grown[0]] = add[1];
                    return grown;
                });
            }
        }
        return rep;
    }

    private static long key(long x, long y, long z) {
        return (x * 73856093L) ^ (y * 19349663L) ^ (z * 83492791L);
    }

    private static double edgeScale(TriangleMesh m, int t) {
        double s = 0;
        for (int k = 0; k < 3; k++) {
            int a = m.corner(t, k);
            int b = m.corner(t, (k + 1) % 3);
            double dx = m.coord(a, 0) - m.coord(b, 0);
            double dy = m.coord(a, 1) - m.coord(b, 1);
            double dz = m.coord(a, 2) - m.coord(b, 2);
            s = Math.max(s, Math.sqrt(dx * dx + dy * dy + dz * dz));
        }
        return s;
    }

    private static int countUsed(int[] tri, int nv) {
        boolean[] used = new boolean[nv];
        int c = 0;
        for (int i : tri) {
            if (!used[i]) {
                used[i] = true;
                c++;
            }
        }
        return c;
    }

    /** Union-find parents over triangles: triangles sharing an edge are in one set. */
    private static int[] componentsByEdges(int[] tri, int nv) {
        int nt = tri.length / 3;
        int[] parent = new int[nt];
        for (int t = 0; t < nt; t++) {
            parent[t] = t;
        }
        Map<Long, Integer> firstUse = new HashMap<>();
        for (int t = 0; t < nt; t++) {
            for (int k = 0; k < 3; k++) {
                int a = tri[3 * t + k];
                int b = tri[3 * t + (k + 1) % 3];
                Integer other = firstUse.putIfAbsent(Math.min(a, b) * (long) nv + Math.max(a, b), t);
                if (other != null) {
                    union(parent, other, t);
                }
            }
        }
        return parent;
    }

    /** How many triangles use each edge, keyed {@code min * nv + max} of its two vertices. */
    private static Map<Long, Integer> edgeUses(int[] tri, int nv) {
        Map<Long, Integer> uses = new HashMap<>();
        for (int t = 0; t < tri.length / 3; t++) {
            for (int k = 0; k < 3; k++) {
                int a = tri[3 * t + k];
                int b = tri[3 * t + (k + 1) % 3];
                uses.merge(Math.min(a, b) * (long) nv + Math.max(a, b), 1, Integer::sum);
            }
        }
        return uses;
    }

    /** Per vertex: an end of a boundary edge (an edge used by one triangle only): on a hole or an open rim. */
    public static boolean[] boundaryVertices(TriangleMesh m) {
        int nv = m.vertexCount();
        boolean[] onBoundary = new boolean[nv];
        for (Map.Entry<Long, Integer> e : edgeUses(m.triangles(), nv).entrySet()) {
            if (e.getValue() == 1) {
                onBoundary[(int) (e.getKey() / nv)] = true;
                onBoundary[(int) (e.getKey() % nv)] = true;
            }
        }
        return onBoundary;
    }

    /** {boundary edges, non-manifold edges, boundary loops}. */
    static int[] edgeStatistics(int[] tri, int nv) {
        Map<Long, Integer> uses = edgeUses(tri, nv);
        int boundary = 0;
        int nonManifold = 0;
        int[] parent = new int[nv];
        for (int i = 0; i < nv; i++) {
            parent[i] = i;
        }
        boolean[] onBoundary = new boolean[nv];
        for (Map.Entry<Long, Integer> e : uses.entrySet()) {
            if (e.getValue() == 1) {
                boundary++;
                int a = (int) (e.getKey() / nv);
                int b = (int) (e.getKey() % nv);
                onBoundary[a] = true;
                onBoundary[b] = true;
                union(parent, a, b);
            } else if (e.getValue() > 2) {
                nonManifold++;
            }
        }
        int loops = 0;
        for (int i = 0; i < nv; i++) {
            if (onBoundary[i] && find(parent, i) == i) {
                loops++;
            }
        }
        return new int[] {boundary, nonManifold, loops};
    }

    static int find(int[] p, int i) {
        while (p[i] != i) {
            p[i] = p[p[i]];
            i = p[i];
        }
        return i;
    }

    static void union(int[] p, int a, int b) {
        int ra = find(p, a);
        int rb = find(p, b);
        if (ra != rb) {
            p[Math.max(ra, rb)] = Math.min(ra, rb);
        }
    }
}
