package org.tensim.scene.diaphragm;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.PriorityQueue;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;

/**
 * The paper's attachment rule on bone surfaces, at the diaphragm's origins only (package-private,
 * called by the scene builder when the cage is a thorax of bone surfaces).
 *
 * <p>The paper attaches the diaphragm where its distance to ribs, sternum and cartilage is under a
 * threshold W. Applied to every node, that rule glues the whole zone of apposition to the chest wall,
 * where the muscle lies on the ribs and must slide, and the glued area grows with W. Here it picks
 * only the origin line: the vertices of the diaphragm's free rim (where its two faces meet, or an open
 * boundary) whose distance to an origin bone ({@link Bones#origin}: xiphoid, cartilages and ribs 7-12,
 * right L1-L3 and left L1-L2) is under W. The attached region is that line widened by a fixed
 * insertion width {@link #INSERTION_WIDTH_M} along the surface (geodesic distance over the mesh's
 * edges), so that its area is the rim's length times a width: it converges with the mesh, and a larger
 * threshold adds only rim that lies near a bone. A label file replaces the rule: its origin labels are
 * the seeds.
 *
 * <p>Each attached node is tied, as by the attachment band, with {@code k_b A_i / 2} (Pa/m times its
 * share of its face's area) to an anchor at its rest point carried by its nearest origin bone's motion
 * (a rib's helical axis, the sternum's, fixed for a vertebra).
 */
final class OriginAttachment {
    /** Width of the insertion along the surface from the origin line, m (a tendinous insertion: about 1 cm). */
    static final double INSERTION_WIDTH_M = 0.010;

    private OriginAttachment() {
    }

    /**
     * Attaches the builder's diaphragm at its origins; returns the attached area and nodes per bone.
     *
     * @param seeds per vertex, a label file's origin (null: by the rule on the rim)
     */
    static Map<String, double[]> attach(DiaphragmSceneBuilder b, Bones bones, RigidMotion[] motions,
            boolean[] seeds, double bandPaPerM) {
        TriangleMesh m = b.mesh;
        double w = b.p.attachThresholdM();
        double midX = midline(bones);
        int[] nearestBone = new int[b.nv];
        double[] distance = new double[b.nv];
        double[] g = new double[3];
        for (int v = 0; v < b.nv; v++) {
            nearestBone[v] = -1;
            distance[v] = Double.POSITIVE_INFINITY;
            double x = m.coord(v, 0);
            double y = m.coord(v, 1);
            double z = m.coord(v, 2);
            for (int i = 0; i < bones.all().size(); i++) {
                Bones.Bone bone = bones.all().get(i);
                if (!bone.origin() || !crusSide(bone, x, midX) || !near(bone.mesh().bounds(), x, y, z, 2 * w)) {
                    continue;
                }
                SignedDistance f = bones.field(i);
                double d = Math.max(0, f.distance(x, y, z, g, 0));
                if (d < distance[v]) {
                    distance[v] = d;
                    nearestBone[v] = i;
                }
            }
        }
        boolean[] seed = seeds;
        if (seed == null) {
            boolean[] rim = FibreInsertion.rim(m, b.surfaces);
            seed = new boolean[b.nv];
            for (int v = 0; v < b.nv; v++) {
                seed[v] = rim[v] && distance[v] < w;
            }
        }
        double[] geodesic = geodesic(m, seed);
        Map<String, double[]> perPart = new LinkedHashMap<>();
        b.markFirstAnchor();
        for (int v = 0; v < b.nv; v++) {
            if (!(geodesic[v] <= INSERTION_WIDTH_M) || nearestBone[v] < 0 && !nearestAny(bones, m, v, midX,
                    nearestBone)) {
                continue;
            }
            Bones.Bone bone = bones.all().get(nearestBone[v]);
            b.attached[v] = true;
            Node n = b.t.node(v);
            double k = bandPaPerM * b.area[v] / 2;
            RigidMotion motion = motions[nearestBone[v]];
            Node anchor = b.t.addNode(n.position(), n.mass());
            if (motion == RigidMotion.FIXED) {
                anchor.fix();
            } else {
                anchor.drive(motion);
            }
            b.tie(v, anchor.id(), k);
            switch (bone.kind()) {
                case VERTEBRA -> b.attachedSpine++;
                case RIB -> b.attachedRibs++;
                default -> b.attachedCartilage++;
            }
            double[] e = perPart.computeIfAbsent(bone.name(), key -> new double[2]);
            e[0] += b.area[v] / 2;
            e[1]++;
        }
        b.originDistance = geodesic;
        return perPart;
    }

    /** For a seed from a label file far from every origin bone's threshold: its nearest origin bone at all. */
    private static boolean nearestAny(Bones bones, TriangleMesh m, int v, double midX, int[] nearestBone) {
        double[] g = new double[3];
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < bones.all().size(); i++) {
            Bones.Bone bone = bones.all().get(i);
            if (!bone.origin() || !crusSide(bone, m.coord(v, 0), midX)) {
                continue;
            }
            double d = bones.field(i).distance(m.coord(v, 0), m.coord(v, 1), m.coord(v, 2), g, 0);
            if (d < best) {
                best = d;
                nearestBone[v] = i;
            }
        }
        return nearestBone[v] >= 0;
    }

    /** The right crus arises from L1-L3, the left from L1-L2 (+X is the patient's left). */
    private static boolean crusSide(Bones.Bone bone, double x, double midX) {
        return bone.kind() != Bones.Kind.VERTEBRA || bone.index() <= 14 || x < midX;
    }

    /** The body's midline x, m: the vertebrae's centre (0 without vertebrae). */
    static double midline(Bones bones) {
        double s = 0;
        int n = 0;
        for (Bones.Bone b : bones.of(Bones.Kind.VERTEBRA)) {
            double[] bb = b.mesh().bounds();
            s += 0.5 * (bb[0] + bb[3]);
            n++;
        }
        return n == 0 ? 0 : s / n;
    }

    static boolean near(double[] bounds, double x, double y, double z, double margin) {
        return x > bounds[0] - margin && x < bounds[3] + margin && y > bounds[1] - margin && y < bounds[4] + margin
                && z > bounds[2] - margin && z < bounds[5] + margin;
    }

    /** Per vertex, the distance along the mesh's edges to the nearest seed, m (Dijkstra; infinite if none). */
    static double[] geodesic(TriangleMesh m, boolean[] seed) {
        int nv = m.vertexCount();
        int[][] adjacency = adjacency(m);
        double[] d = new double[nv];
        Arrays.fill(d, Double.POSITIVE_INFINITY);
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, c) -> Double.compare(a[0], c[0]));
        for (int v = 0; v < nv; v++) {
            if (seed[v]) {
                d[v] = 0;
                queue.add(new double[] {0, v});
            }
        }
        while (!queue.isEmpty()) {
            double[] top = queue.poll();
            int v = (int) top[1];
            if (top[0] > d[v]) {
                continue;
            }
            for (int u : adjacency[v]) {
                double dx = m.coord(u, 0) - m.coord(v, 0);
                double dy = m.coord(u, 1) - m.coord(v, 1);
                double dz = m.coord(u, 2) - m.coord(v, 2);
                double nd = d[v] + Math.sqrt(dx * dx + dy * dy + dz * dz);
                if (nd < d[u]) {
                    d[u] = nd;
                    queue.add(new double[] {nd, u});
                }
            }
        }
        return d;
    }

    private static int[][] adjacency(TriangleMesh m) {
        int nv = m.vertexCount();
        java.util.List<java.util.Set<Integer>> sets = new java.util.ArrayList<>(nv);
        for (int v = 0; v < nv; v++) {
            sets.add(new java.util.HashSet<>());
        }
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                int a = m.corner(t, k);
                int c = m.corner(t, (k + 1) % 3);
                sets.get(a).add(c);
                sets.get(c).add(a);
            }
        }
        int[][] out = new int[nv][];
        for (int v = 0; v < nv; v++) {
            out[v] = sets.get(v).stream().mapToInt(Integer::intValue).toArray();
        }
        return out;
    }
}
