package org.tensim.scene.lungs;

import java.util.ArrayList;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.RibCage;
import org.tensim.scene.thorax.TriangleTree;
import org.tensim.scene.volume.VolumeBody;

/**
 * What {@link ThoraxOrgans} finds and makes at build time: the ribs' centrelines, the followers near a surface,
 * the liver's bare-area hold, the diaphragm's lower surface, the mappings re-based on the final state, the rest
 * distances, and the damping check.
 */
final class OrganGeometry {
    private OrganGeometry() {
    }

    /** The ribs' centrelines with their motions, from the cage's rib segments (consecutive by name). */
    static List<PleuraCarriers.Rib> ribs(Topology t, List<RibCage.Segment> segs) {
        java.util.Map<String, List<RibCage.Segment>> byName = new java.util.LinkedHashMap<>();
        for (RibCage.Segment s : segs) {
            if (s.kind() == RibCage.Kind.RIB && s.motion() != null) {
                byName.computeIfAbsent(s.name(), k -> new ArrayList<>()).add(s);
            }
        }
        List<PleuraCarriers.Rib> out = new ArrayList<>();
        for (var e : byName.entrySet()) {
            List<RibCage.Segment> l = e.getValue();
            double[] line = new double[6 * l.size()];
            int k = 0;
            for (RibCage.Segment s : l) {
                for (int end : new int[] {s.a(), s.b()}) {
                    Vec3 p = t.node(end).position();
                    line[k++] = p.x();
                    line[k++] = p.y();
                    line[k++] = p.z();
                }
            }
            out.add(new PleuraCarriers.Rib(e.getKey(), l.get(0).motion(), line));
        }
        return out;
    }

    /**
     * The body's nodes within {@code band} of its surface (either side) and, with a tree, within {@code reach} of
     * the tree's surface.
     */
    static int[] surfaceNodes(Topology t, VolumeBody body, double band, TriangleTree near, double reach) {
        TriangleMesh m = body.surface();
        TriangleTree tree = new TriangleTree(m.coordinates(), m.triangles(), 3);
        int[] stack = tree.newStack();
        int[] stack2 = near == null ? null : near.newStack();
        List<Integer> out = new ArrayList<>();
        for (int id = body.firstNode(), e = body.firstNode() + body.nodeCount(); id < e; id++) {
            Vec3 p = t.node(id).position();
            if (tree.distance(p.x(), p.y(), p.z(), stack) <= band
                    && (near == null || near.distance(p.x(), p.y(), p.z(), stack2) <= reach)) {
                out.add(id);
            }
        }
        return out.stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * Zero-length springs from the liver's bare-area nodes (posterior fifth of its depth, +y posterior; upper half
     * of its height) to fixed anchors, of stiffness K h^2 each; returns the held nodes.
     */
    static int[] holdBareArea(Topology t, VolumeBody liver, double h, double paPerM) {
        double[] b = liver.surface().bounds();
        double yCut = b[4] - 0.2 * (b[4] - b[1]);
        double zCut = 0.5 * (b[2] + b[5]);
        List<Integer> held = new ArrayList<>();
        int end = liver.firstNode() + liver.nodeCount();
        for (int id = liver.firstNode(); id < end; id++) {
            Vec3 p = t.node(id).position();
            if (p.y() >= yCut && p.z() >= zCut) {
                held.add(id);
            }
        }
        return tie(t, held, h, paPerM);
    }

    /**
     * The abdomen under the liver, as an elastic foundation: zero-length springs of K h^2 each from the liver's
     * surface nodes (within {@code band} of its surface) in the lower half of its height that are neither
     * diaphragm followers nor held at the bare area, to fixed anchors; returns the supported nodes. Without it
     * nothing but the soft bare-area hold stands against the diaphragm's push, so the liver goes down as far as the
     * most-descending part of the muscle above it and leaves the rest (one-sided contact); the viscera below keep it
     * pressed on the whole of its diaphragmatic surface.
     */
    static int[] supportBelow(Topology t, VolumeBody liver, double h, double paPerM, double band, int[] followers,
            int[] held) {
        double[] b = liver.surface().bounds();
        double zCut = 0.5 * (b[2] + b[5]);
        java.util.Set<Integer> skip = new java.util.HashSet<>();
        for (int id : followers) {
            skip.add(id);
        }
        for (int id : held) {
            skip.add(id);
        }
        List<Integer> below = new ArrayList<>();
        for (int id : surfaceNodes(t, liver, band, null, 0)) {
            if (t.node(id).position().z() < zCut && !skip.contains(id)) {
                below.add(id);
            }
        }
        return tie(t, below, h, paPerM);
    }

    /** Zero-length springs of K h^2 from each node to a fixed anchor at its rest point; returns the nodes. */
    private static int[] tie(Topology t, List<Integer> nodes, double h, double paPerM) {
        for (int id : nodes) {
            int a = t.addNode(t.node(id).position(), PleuraCarriers.FRAME_MASS_KG).fix().id();
            t.addSpring(id, a, paPerM * h * h, 0, 0);
        }
        return nodes.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The diaphragm's lower-surface triangles (mesh triangles none of whose corners is upper), as node ids. */
    static int[] lowerTriangles(DiaphragmScene scene) {
        TriangleMesh m = scene.surfaces().mesh();
        List<Integer> out = new ArrayList<>();
        for (int tr = 0; tr < m.triangleCount(); tr++) {
            boolean lower = true;
            for (int k = 0; k < 3; k++) {
                lower &= !scene.surfaces().isUpper(m.corner(tr, k));
            }
            if (lower) {
                for (int k = 0; k < 3; k++) {
                    out.add(m.corner(tr, k));
                }
            }
        }
        return out.stream().mapToInt(Integer::intValue).toArray();
    }

    static int lungHolding(List<TriangleMesh> surfaces, double[] p) {
        for (int i = 0; i < surfaces.size(); i++) {
            TriangleMesh m = surfaces.get(i);
            TriangleTree tree = new TriangleTree(m.coordinates(), m.triangles(), 3);
            if (Math.abs(tree.winding(p[0], p[1], p[2], tree.newStack())) > 0.5) {
                return i;
            }
        }
        return -1;
    }

    static double[] restPositions(Topology t, int n) {
        double[] x = new double[3 * n];
        for (int i = 0; i < n; i++) {
            Vec3 p = t.node(i).position();
            x[3 * i] = p.x();
            x[3 * i + 1] = p.y();
            x[3 * i + 2] = p.z();
        }
        return x;
    }

    static double[] filled(int n, double v) {
        double[] a = new double[n];
        java.util.Arrays.fill(a, v);
        return a;
    }

    /** Points 0 .. n-1 on nodes 0 .. n-1, weight 1, for a state of {@code nodeCount} nodes. */
    static LinearMapping identity(int n, int nodeCount) {
        return nodes(java.util.stream.IntStream.range(0, n).toArray(), nodeCount);
    }

    /** Points 0 .. ids.length-1 on the nodes ids, weight 1, for a state of {@code nodeCount} nodes. */
    static LinearMapping nodes(int[] ids, int nodeCount) {
        LinearMapping.Builder b = new LinearMapping.Builder(nodeCount);
        for (int id : ids) {
            b.add(new int[] {id}, new double[] {1});
        }
        return b.build();
    }

    /** The same rows on a state of more nodes. */
    static LinearMapping rebase(LinearMapping m, int nodeCount) {
        return rows(m, java.util.stream.IntStream.range(0, m.pointCount()).toArray(), nodeCount);
    }

    /** Rows {@code rows} of m, in that order, on a state of {@code nodeCount} nodes (at least m's). */
    static LinearMapping rows(LinearMapping m, int[] rows, int nodeCount) {
        LinearMapping.Builder b = new LinearMapping.Builder(nodeCount);
        for (int i : rows) {
            int e = m.entries(i);
            int[] nodes = new int[e];
            double[] w = new double[e];
            for (int k = 0; k < e; k++) {
                nodes[k] = m.node(i, k);
                w[k] = m.weight(i, k);
            }
            b.add(nodes, w);
        }
        return b.build();
    }

    /** Signed distance of x[o..o+2] to the plane of triangle tri (corners in p), + on the winding's outward side. */
    static double planeDistance(double[] p, int[] tris, int tri, double[] x, int o) {
        int a = 3 * tris[3 * tri];
        int b = 3 * tris[3 * tri + 1];
        int c = 3 * tris[3 * tri + 2];
        double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
        double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        return (nx * (x[o] - p[a]) + ny * (x[o + 1] - p[a + 1]) + nz * (x[o + 2] - p[a + 2])) / len;
    }

    /**
     * The scene's global viscous damping is c N s/m on every node (c = alpha times the diaphragm's mean node mass):
     * on an organ node of mass m it is the rate c / m, which an explicit step of dt keeps stable for c dt / m below
     * about 1. The lattices' clipped corner nodes are light (down to rho h^3 / 512), so a coarse diaphragm (heavy
     * nodes, a large c) with fine organs is refused here, naming the values, rather than left to diverge.
     */
    static void refuseOverdamped(Topology t, int first, double dt) {
        double c = t.viscousDamping();
        for (int id = first; id < t.nodeCount(); id++) {
            double m = t.node(id).mass();
            if (!t.node(id).isFixed() && c * dt / m > 0.5) {
                throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "organ node %d of mass %.3g"
                        + " kg under the scene's viscous damping %.3g N s/m at the step %.3g s: c dt / m = %.2f,"
                        + " expected at most 0.5 (coarser organ cells, a finer diaphragm or less viscous damping)", id,
                        m, c, dt, c * dt / m));
            }
        }
    }
}
