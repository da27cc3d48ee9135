package org.tensim.io.mesh;

import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.tensim.model.Check;

/**
 * Mesh simplification by vertex clustering (Rossignac and Borrel 1993): space is cut
 * into cubes of a given size, the vertices in one cube (and one group) become a
 * single vertex at their mean position, and triangles that lose a corner are
 * dropped. Groups keep apart what must not merge although it is close, such as the
 * two faces of a 3 mm thin shell simplified with 8 mm cubes.
 */
public final class VertexClustering {
    /** A simplified mesh and the group of each of its vertices. */
    public record Result(TriangleMesh mesh, int[] groups) {
    }

    private VertexClustering() {
    }

    /**
     * @param groups one group number per vertex (vertices of different groups never merge)
     * @param cellM  cube size, m (> 0)
     */
    public static Result simplify(TriangleMesh m, int[] groups, double cellM) {
        Check.positive("clustering cell size", "m", cellM);
        int nv = m.vertexCount();
        if (groups.length != nv) {
            throw new IllegalArgumentException("clustering needs one group per vertex: got " + groups.length
                    + " groups for " + nv + " vertices");
        }
        Map<String, Integer> cellId = new HashMap<>();
        int[] cluster = new int[nv];
        double[] sum = new double[3 * nv];
        int[] count = new int[nv];
        int[] clusterGroup = new int[nv];
        int nc = 0;
        for (int v = 0; v < nv; v++) {
            String key = groups[v] + ":" + (long) Math.floor(m.coord(v, 0) / cellM) + ":"
                    + (long) Math.floor(m.coord(v, 1) / cellM) + ":" + (long) Math.floor(m.coord(v, 2) / cellM);
            Integer c = cellId.get(key);
            if (c == null) {
                c = nc++;
                cellId.put(key, c);
                clusterGroup[c] = groups[v];
            }
            cluster[v] = c;
            for (int a = 0; a < 3; a++) {
                sum[3 * c + a] += m.coord(v, a);
            }
            count[c]++;
        }
        int[] tri = new int[3 * m.triangleCount()];
        int nt = 0;
        Set<String> seen = new HashSet<>();
        for (int t = 0; t < m.triangleCount(); t++) {
            int a = cluster[m.corner(t, 0)];
            int b = cluster[m.corner(t, 1)];
            int c = cluster[m.corner(t, 2)];
            if (a == b || b == c || a == c) {
                continue;
            }
            int[] sorted = {a, b, c};
            Arrays.sort(sorted);
            if (!seen.add(sorted[0] + "," + sorted[1] + "," + sorted[2])) {
                continue;
            }
            tri[3 * nt] = a;
            tri[3 * nt + 1] = b;
            tri[3 * nt + 2] = c;
            nt++;
        }
        int[] index = new int[nc];
        Arrays.fill(index, -1);
        int k = 0;
        double[] xyz = new double[3 * nc];
        int[] g = new int[nc];
        for (int i = 0; i < 3 * nt; i++) {
            int c = tri[i];
            if (index[c] < 0) {
                index[c] = k;
                for (int a = 0; a < 3; a++) {
                    xyz[3 * k + a] = sum[3 * c + a] / count[c];
                }
                g[k] = clusterGroup[c];
                k++;
            }
            tri[i] = index[c];
        }
        return new Result(new TriangleMesh(Arrays.copyOf(xyz, 3 * k), Arrays.copyOf(tri, 3 * nt)),
                Arrays.copyOf(g, k));
    }
}
