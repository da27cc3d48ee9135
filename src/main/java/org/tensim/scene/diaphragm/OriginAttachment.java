package org.tensim.scene.diaphragm;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.PriorityQueue;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.scene.conditions.BandAttachment;

/**
 * The paper's attachment rule on bone surfaces, at the diaphragm's origins only (package-private,
 * called by the scene builder when the cage is a thorax of bone surfaces).
 *
 * <p>The paper attaches the diaphragm where its distance to ribs, sternum and cartilage is under a
 * threshold W. Applied to every node, that rule glues the whole zone of apposition to the chest wall,
 * where the muscle lies on the ribs and must slide, and the glued area grows with W. Here it picks
 * only the origin line: the diaphragm's inferior margin (its lowest edge all round, {@link #inferiorMargin}),
 * a strip {@link #INSERTION_WIDTH_M} high (its top {@link #TAPER_M} tapered), wherever its distance to an origin bone ({@link Bones#origin}:
 * xiphoid, cartilages and ribs 7-12, right L1-L3 and left L1-L2) is under W. Its area is the margin's
 * length near the bones times the strip's height: it converges with the mesh, and a larger threshold
 * adds only margin that lies near a bone, never the zone of apposition above it. The crura are attached
 * along the lumbar vertebrae too, wherever they lie within {@link #CRUS_DISTANCE_M} of them. A label file replaces
 * the rule: its origin labels, widened by the same width along the surface (geodesic distance over the
 * mesh's edges), are attached.
 *
 * <p>Each attached node is tied, as by the attachment band ({@link BandAttachment}: its taper, its zero-length
 * ties to carried anchors), with {@code k_b A_i / 2} (Pa/m times its
 * share of its face's area) to an anchor at its rest point carried by its nearest origin bone's motion
 * (a rib's helical axis, the sternum's, fixed for a vertebra).
 */
final class OriginAttachment {
    /** Width of the insertion along the surface from the origin line, m (a tendinous insertion: about 1 cm). */
    static final double INSERTION_WIDTH_M = 0.012;
    /**
     * Distance from an origin vertebra (right L1-L3, left L1-L2) within which the crura are attached, m: the
     * crura are tendons on the front of the vertebral bodies (about 1 cm from the bone in the shared thorax's
     * registration, and the muscle 3 mm thick).
     */
    static final double CRUS_DISTANCE_M = 0.008;
    /** Width of the smooth fall of the ties at the strip's edges, m (about the coarsest element). */
    static final double TAPER_M = 0.006;

    private OriginAttachment() {
    }

    /**
     * Attaches the builder's diaphragm at its origins; returns the attached area and nodes per bone.
     *
     * @param seeds per vertex, a label file's origin (null: by the rule on the inferior margin)
     */
    static Map<String, double[]> attach(DiaphragmSceneBuilder b, Bones bones, RigidMotion[] motions,
            boolean[] seeds, double bandPaPerM) {
        TriangleMesh m = b.mesh;
        double w = b.p.attachThresholdM();
        double midX = midline(bones);
        int[] nearestBone = new int[b.nv];
        double[] distance = new double[b.nv];
        // Per vertex: within the threshold of an origin vertebra (the crura's region, attached by their own rule).
        boolean[] crural = new boolean[b.nv];
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
                crural[v] |= bone.kind() == Bones.Kind.VERTEBRA && d < w;
                if (d < distance[v]) {
                    distance[v] = d;
                    nearestBone[v] = i;
                }
            }
        }
        // Per vertex, the share of its tie: 1 inside the strip, falling smoothly (cos^2 over TAPER_M) at its
        // top edge and at the threshold's, so that the attached area converges as a smooth integral rather
        // than counting whole vertices in or out.
        // Per vertex: its height above the origin line (above the inferior margin, or its distance along the
        // surface from a label file's origin) and its closeness to an origin bone (1 within the threshold less
        // the taper, falling to 0 at the threshold; 1 for a label file's).
        double[] height = seeds == null ? inferiorMargin(m, crural) : geodesic(m, seeds);
        double[] boneFactor = new double[b.nv];
        for (int v = 0; v < b.nv; v++) {
            if (seeds == null) {
                // The crura's region is left to their own rule below: it hangs below the costal margin.
                height[v] = crural[v] || Double.isInfinite(height[v]) ? Double.POSITIVE_INFINITY
                        : m.coord(v, 2) - height[v];
                boneFactor[v] = BandAttachment.taper(distance[v], w, Math.min(TAPER_M, w));
            } else {
                boneFactor[v] = 1;
            }
        }
        // The crura arise from the front of the lumbar vertebral bodies all along their length, not only at
        // the margin: every node within CRUS_DISTANCE_M of an origin vertebra is attached.
        double[] crus = new double[b.nv];
        for (int v = 0; v < b.nv && seeds == null; v++) {
            if (nearestBone[v] >= 0 && bones.all().get(nearestBone[v]).kind() == Bones.Kind.VERTEBRA) {
                crus[v] = BandAttachment.taper(distance[v], CRUS_DISTANCE_M, TAPER_M / 2);
            }
        }
        double[] weightedArea = consistentArea(m, height, boneFactor, crus);
        double[] weight = new double[b.nv];
        for (int v = 0; v < b.nv; v++) {
            weight[v] = b.area[v] > 0 ? weightedArea[v] / b.area[v] : 0;
        }
        boolean[] region = new boolean[b.nv];
        for (int v = 0; v < b.nv; v++) {
            region[v] = weight[v] > 0;
        }
        Map<String, double[]> perPart = new LinkedHashMap<>();
        b.markFirstAnchor();
        for (int v = 0; v < b.nv; v++) {
            if (weight[v] == 0 || nearestBone[v] < 0 && !nearestAny(bones, m, v, midX, nearestBone)) {
                continue;
            }
            Bones.Bone bone = bones.all().get(nearestBone[v]);
            b.attached[v] = true;
            Node n = b.t.node(v);
            double k = bandPaPerM * b.area[v] / 2 * weight[v];
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
            e[0] += b.area[v] / 2 * weight[v];
            e[1]++;
        }
        b.originDistance = geodesic(m, region);
        return perPart;
    }

    /**
     * Per vertex, {@code sum_T int_T w phi_v dA}, m^2: the strip's weight integrated over each triangle against
     * the vertex's linear shape function (the consistent weighting of a linear element), with w interpolated
     * linearly in each triangle from the corners', at each of 16 sub-triangles' centroids: the strip's edge cuts
     * through triangles, and a whole triangle's area is not lumped onto its lowest corner. The sum over
     * vertices is the strip's area, resolution-independent.
     */
    static double[] consistentArea(TriangleMesh m, double[] height, double[] boneFactor, double[] crus) {
        double[] out = new double[m.vertexCount()];
        final int n = 4;
        for (int t = 0; t < m.triangleCount(); t++) {
            int a = m.corner(t, 0);
            int b = m.corner(t, 1);
            int c = m.corner(t, 2);
            boolean noCrus = crus[a] + crus[b] + crus[c] == 0;
            if (noCrus && (Math.min(height[a], Math.min(height[b], height[c])) >= INSERTION_WIDTH_M
                    || boneFactor[a] + boneFactor[b] + boneFactor[c] == 0)) {
                continue;
            }
            double sub = m.area(t) / (n * n);
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n - i; j++) {
                    for (int up = 0; up < (i + j < n - 1 ? 2 : 1); up++) {
                        // Barycentric centroid of the sub-triangle (i, j), upright (up = 0) or inverted.
                        double l1 = up == 0 ? (i + 1.0 / 3) / n : (i + 2.0 / 3) / n;
                        double l2 = up == 0 ? (j + 1.0 / 3) / n : (j + 2.0 / 3) / n;
                        double l0 = 1 - l1 - l2;
                        double h = l0 * height[a] + l1 * height[b] + l2 * height[c];
                        double wq = Math.max(BandAttachment.taper(h, INSERTION_WIDTH_M, TAPER_M)
                                * (l0 * boneFactor[a] + l1 * boneFactor[b] + l2 * boneFactor[c]),
                                l0 * crus[a] + l1 * crus[b] + l2 * crus[c]);
                        out[a] += wq * l0 * sub;
                        out[b] += wq * l1 * sub;
                        out[c] += wq * l2 * sub;
                    }
                }
            }
        }
        return out;
    }

    /** Azimuthal sectors of the inferior margin (5 degrees each). */
    static final int SECTORS = 72;

    /**
     * Per vertex, the height of the diaphragm's inferior margin at its azimuth, m: the lowest point of the
     * surface in its 5-degree sector about the vertical axis through the mesh's centre (x, y of its bounding
     * box). The muscle arises from its origins along its lowest edge all round (the costal margin, the
     * xiphoid, the crura on the lumbar spine), so that edge is its origin line wherever a bone is near. The
     * lowest point is the surface's, not a vertex's: the lowest vertex in the sector, or where an edge
     * crosses into it (a linear height is lowest at a corner of the triangle clipped to the sector), so that
     * the same surface sampled finer gives the same margin.
     *
     * <p>The points of {@code skip} (the crura's region, within the threshold of an origin vertebra) do not
     * count: the right crus hangs down the lumbar spine to L3, 40 mm below the costal margin of ribs 11-12
     * in the same sectors, and taken as the margin there it left that costal origin unattached. The crura
     * are attached by their own rule.
     *
     * @param skip per vertex, left out of the search (null: none); a sector with no point left takes its
     *             neighbours' margin, and is infinite (no margin) when they have none either
     */
    static double[] inferiorMargin(TriangleMesh m, boolean[] skip) {
        double[] b = m.bounds();
        double cx = 0.5 * (b[0] + b[3]);
        double cy = 0.5 * (b[1] + b[4]);
        double[] low = new double[SECTORS];
        Arrays.fill(low, Double.POSITIVE_INFINITY);
        int nv = m.vertexCount();
        double[] angle = new double[nv];
        int[] sector = new int[nv];
        for (int v = 0; v < nv; v++) {
            angle[v] = Math.atan2(m.coord(v, 1) - cy, m.coord(v, 0) - cx) + Math.PI; // 0 .. 2 pi
            sector[v] = sectorOf(angle[v]);
            if (skip == null || !skip[v]) {
                low[sector[v]] = Math.min(low[sector[v]], m.coord(v, 2));
            }
        }
        double step = 2 * Math.PI / SECTORS;
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                int p = m.corner(t, k);
                int q = m.corner(t, (k + 1) % 3);
                if (sector[p] == sector[q] || skip != null && (skip[p] || skip[q])) {
                    continue;
                }
                // The boundaries between the two sectors, the short way round.
                double a0 = angle[p];
                double da = angle[q] - a0;
                da -= 2 * Math.PI * Math.round(da / (2 * Math.PI));
                int from = (int) Math.floor(Math.min(a0, a0 + da) / step) + 1;
                int to = (int) Math.floor(Math.max(a0, a0 + da) / step);
                for (int s = from; s <= to; s++) {
                    double theta = s * step - Math.PI; // the boundary's direction in atan2's range
                    double dx = Math.cos(theta);
                    double dy = Math.sin(theta);
                    double px = m.coord(p, 0) - cx;
                    double py = m.coord(p, 1) - cy;
                    double ex = m.coord(q, 0) - m.coord(p, 0);
                    double ey = m.coord(q, 1) - m.coord(p, 1);
                    double den = ex * dy - ey * dx;
                    if (den == 0) {
                        continue;
                    }
                    double f = Math.max(0, Math.min(1, -(px * dy - py * dx) / den));
                    double z = m.coord(p, 2) + f * (m.coord(q, 2) - m.coord(p, 2));
                    int below = Math.floorMod(s - 1, SECTORS);
                    int above = Math.floorMod(s, SECTORS);
                    low[below] = Math.min(low[below], z);
                    low[above] = Math.min(low[above], z);
                }
            }
        }
        // Linear in the angle between the sectors' middles: a margin that jumps from sector to sector would
        // cut the strip into steps that each mesh samples differently.
        double[] out = new double[nv];
        for (int v = 0; v < nv; v++) {
            double f = angle[v] / step - 0.5;
            int s0 = (int) Math.floor(f);
            double frac = f - s0;
            double l0 = low[Math.floorMod(s0, SECTORS)];
            double l1 = low[Math.floorMod(s0 + 1, SECTORS)];
            out[v] = Double.isInfinite(l0) ? l1 : Double.isInfinite(l1) ? l0 : (1 - frac) * l0 + frac * l1;
        }
        return out;
    }

    private static int sectorOf(double angle) {
        return (int) Math.min(SECTORS - 1, Math.floor(SECTORS * angle / (2 * Math.PI)));
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
