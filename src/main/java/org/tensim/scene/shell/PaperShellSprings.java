package org.tensim.scene.shell;

import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.tensim.io.mesh.TriangleMesh;

/**
 * The springs of {@link TissueModel#PAPER} that {@link ShellNetwork} does not share with the
 * material model: folding springs and the columns-with-diagonals across the thickness
 * (package-private; formulas in docs/diaphragm.md).
 */
final class PaperShellSprings {
    private PaperShellSprings() {
    }

    /**
     * Across every edge shared by two triangles of the same face, a spring between the two
     * opposite vertices: it resists folding about the edge (as in cloth models), which keeps
     * the thin compressed walls from buckling at the scale of the mesh.
     */
    static void folding(TwoSurfaces s, Map<Long, double[]> edgeArea, ShellNetwork.EdgeModulus young,
            double thickness, double bendingFactor, ShellNetwork.Sink springs) {
        if (bendingFactor == 0) {
            return;
        }
        TriangleMesh mesh = s.mesh();
        java.util.Map<Long, Integer> firstOpposite = new java.util.HashMap<>();
        for (int tr = 0; tr < mesh.triangleCount(); tr++) {
            for (int k = 0; k < 3; k++) {
                int i = mesh.corner(tr, k);
                int j = mesh.corner(tr, (k + 1) % 3);
                int o = mesh.corner(tr, (k + 2) % 3);
                if (s.isUpper(i) != s.isUpper(o) || s.isUpper(j) != s.isUpper(o) || s.isUpper(i) != s.isUpper(j)) {
                    continue;
                }
                Integer other = firstOpposite.putIfAbsent(ShellNetwork.key(i, j), o);
                if (other != null && other != o) {
                    double len = TwoSurfaces.distance(mesh, o, other);
                    double a = edgeArea.get(ShellNetwork.key(i, j))[0];
                    springs.add(o, other, bendingFactor * young.youngPa(o, other) * (thickness / 2) * a / (len * len));
                }
            }
        }
    }

    /**
     * Each upper node u to its partner and to its upper neighbours' partners, sharing the column
     * {@code E A_u / L} among them; lower nodes left unconnected get a column from their partner.
     */
    static void thickness(TwoSurfaces s, double[] area, double youngPa, List<List<Integer>> neighbours,
            ShellNetwork.Sink springs, Set<Long> linkPairs, boolean[] linked) {
        TriangleMesh mesh = s.mesh();
        double thickness = s.thicknessM();
        int nv = mesh.vertexCount();
        boolean[] connected = new boolean[nv];
        double maxLen = 3 * thickness;
        for (int u = 0; u < nv; u++) {
            if (!s.isUpper(u)) {
                continue;
            }
            Set<Integer> targets = new TreeSet<>();
            targets.add(s.partner(u));
            double longestEdge = 0;
            for (int j : neighbours.get(u)) {
                longestEdge = Math.max(longestEdge, TwoSurfaces.distance(mesh, u, j));
                if (s.isUpper(j)) {
                    targets.add(s.partner(j));
                }
            }
            // The diagonals couple the two faces in shear: they must exist at every element size, so the
            // cap (against a partner found on the far side of a badly paired mesh) grows with the local
            // edge length. A cap of 3 thicknesses alone dropped every diagonal on meshes coarser than
            // about 7 mm and left the faces free to slide (docs/diaphragm.md, resolution study).
            final double cap = 3 * (thickness + longestEdge);
            final int up = u;
            targets.removeIf(l -> l < 0 || s.isUpper(l) || springs.contains(up, l)
                    || linkPairs.contains(ShellNetwork.key(up, l)) || TwoSurfaces.distance(mesh, up, l) > cap);
            for (int l : targets) {
                double len = TwoSurfaces.distance(mesh, u, l);
                // Across the thickness the tendon is held by its rigid links; its springs there are muscle-like.
                springs.add(u, l, youngPa * area[u] / (targets.size() * len));
                connected[u] = true;
                connected[l] = true;
            }
            connected[u] |= linked[u];
        }
        for (int l = 0; l < nv; l++) {
            int u = s.partner(l);
            if (s.isUpper(l) || connected[l] || linked[l] || u < 0 || springs.contains(u, l)) {
                continue;
            }
            double len = TwoSurfaces.distance(mesh, u, l);
            if (len > 0 && len <= maxLen) {
                springs.add(u, l, youngPa * area[l] / len);
            }
        }
    }
}
