package org.tensim.scene.volume;

import java.util.HashMap;
import java.util.Map;
import org.tensim.io.mesh.TetMesh;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;

/**
 * Builds the tetrahedral variant of a {@link VolumeBody} (package-private; the entry is
 * {@link VolumeBody#buildTets}): the mesh's nodes are the mechanical nodes, of mass {@code rho V_t / 4} from each tet
 * t they belong to, its edges the springs ({@link TetSprings}, shares of the tets around an edge summed), and its
 * boundary surface's vertices are carried by their own nodes with weight 1.
 */
final class TetVolume {
    private TetVolume() {
    }

    static VolumeBody build(Topology t, TetMesh mesh, VolumeParameters p, String name) {
        if (p.fit() != SpringFit.ISOTROPIC) {
            throw new IllegalArgumentException(name + ": the " + p.fit().key() + " spring fit needs "
                    + (p.fit() == SpringFit.AXIAL ? "a lattice's axes" : "a lattice's cells") + ";"
                    + " expected the isotropic fit for a tetrahedral mesh (its springs give nu = 1/4, docs/volume.md)");
        }
        int n = mesh.nodeCount();
        double[] mass = new double[n];
        TetSprings fit = new TetSprings(p.youngPa());
        Map<Long, Integer> edgeIndex = new HashMap<>();
        int[] edgeA = new int[6 * mesh.tetCount()];
        int[] edgeB = new int[edgeA.length];
        double[] edgeK = new double[edgeA.length];
        int edges = 0;
        double[] corners = new double[12];
        double volume = 0;
        for (int tet = 0; tet < mesh.tetCount(); tet++) {
            double v = mesh.volume(tet);
            volume += v;
            for (int c = 0; c < 4; c++) {
                int node = mesh.corner(tet, c);
                mass[node] += p.densityKgPerM3() * v / 4;
                for (int a = 0; a < 3; a++) {
                    corners[3 * c + a] = mesh.coord(node, a);
                }
            }
            double[] k = fit.stiffness(corners);
            for (int e = 0; e < 6; e++) {
                int a = mesh.corner(tet, TetSprings.EDGES[e][0]);
                int b = mesh.corner(tet, TetSprings.EDGES[e][1]);
                long key = (long) Math.min(a, b) * n + Math.max(a, b);
                Integer at = edgeIndex.get(key);
                if (at == null) {
                    at = edges++;
                    edgeIndex.put(key, at);
                    edgeA[at] = Math.min(a, b);
                    edgeB[at] = Math.max(a, b);
                }
                edgeK[at] += k[e];
            }
        }
        int first = t.nodeCount();
        for (int i = 0; i < n; i++) {
            t.addNode(mesh.coord(i, 0), mesh.coord(i, 1), mesh.coord(i, 2), mass[i]);
        }
        int springs = 0;
        double lengthSum = 0;
        for (int e = 0; e < edges; e++) {
            double dx = mesh.coord(edgeB[e], 0) - mesh.coord(edgeA[e], 0);
            double dy = mesh.coord(edgeB[e], 1) - mesh.coord(edgeA[e], 1);
            double dz = mesh.coord(edgeB[e], 2) - mesh.coord(edgeA[e], 2);
            double rest = Math.sqrt(dx * dx + dy * dy + dz * dz);
            lengthSum += rest;
            if (edgeK[e] > 0) {
                t.addSpring(first + edgeA[e], first + edgeB[e], edgeK[e], rest, p.dampingTimeS() * edgeK[e]);
                springs++;
            }
        }
        TriangleMesh surface = mesh.boundary();
        LinearMapping.Builder m = new LinearMapping.Builder(t.nodeCount());
        for (int i = 0; i < surface.vertexCount(); i++) {
            m.add(new int[] {first + mesh.boundaryNode(i)}, new double[] {1});
        }
        double[] b = surface.bounds();
        VolumeReport r = new VolumeReport(surface.vertexCount(), surface.triangleCount(), surface.boundaryEdgeCount(),
                Double.NaN, false, lengthSum / edges, mesh.tetCount(), mesh.tetCount(), 0, n, springs, volume,
                Math.abs(surface.signedVolume()), volume * p.densityKgPerM3(), 0.25, p.poisson(), p.fit(), true);
        return new VolumeBody(first, n, m.build(), surface, r, new double[] {b[0], b[1], b[2]},
                fit.negativeDropped());
    }
}
