package org.tensim.scene.lungs;

import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;

/**
 * The pleura's vertex motions blended over a neighbourhood, so that the carried surface stays a surface.
 *
 * <p><b>Why.</b> Each vertex's own carrier ({@link PleuraCarriers}) is chosen by distance thresholds, so neighbours on
 * either side of a threshold move by different rules: a diaphragmatic vertex descends with the dome while its costal
 * or fixed neighbour a few mm away stays with the rib or the frame. The lungs' rest surface has edges of a few mm, and
 * the diaphragm moves some 10 mm, so the triangles across such a boundary turn over during inspiration (their
 * normals reverse): the pleura folds, a follower paired with a turned triangle is held to the wrong side of it, and
 * the lung is driven through its wall. The parietal pleura is one continuous membrane that stretches between its
 * attachments; here that stretch is spread over a length R instead of one triangle.
 *
 * <p><b>The blend.</b> Vertex v's row is the average, by the weights {@code K_u = (1 - (r_uv / R)^2)^2} (r_uv the
 * distance at rest, u within R, v itself included), of its neighbours' carrier <i>rules evaluated at v's own rest
 * position</i> p_v: a rib's rigid motion of p_v (its frame's affine coordinates of p_v), an intercostal vertex's two
 * ribs at p_v with its own blend, the fixed frame at p_v, a diaphragmatic vertex's closest diaphragm point q_u (its
 * triangle's barycentric weights) plus the constant offset p_v - q_u on the fixed frame. Every rule reproduces p_v at
 * rest, so the blend does, exactly, and the surface starts where it is; a vertex whose neighbours within R are all
 * carried by one rib moves exactly with that rib. The motion's gradient along the surface is then about the
 * difference of neighbouring rules over R (a 10 mm relative motion over R = 25 mm: a shear of about 0.4, far from
 * turning a triangle over) instead of that difference over one edge.
 */
final class PleuraBlend {
    /**
     * One vertex's own carrier rule.
     *
     * @param kind   its carrier
     * @param frameA the rib (frame index) of a RIB or the first of an INTERCOSTAL vertex; the fixed frame for FIXED and
     *               DIAPHRAGM
     * @param frameB the second rib of an INTERCOSTAL vertex, else -1
     * @param a      the weight of frameA for INTERCOSTAL (1 otherwise)
     * @param nodes  a DIAPHRAGM vertex's three diaphragm nodes, else null
     * @param w      their barycentric weights
     * @param q      the closest diaphragm point at rest, m
     */
    record Rule(PleuraCarriers.Carrier kind, int frameA, int frameB, double a, int[] nodes, double[] w, double[] q) {
    }

    private PleuraBlend() {
    }

    /**
     * The blended mapping.
     *
     * @param pleura     the pleura's rest surface, m
     * @param rules      per vertex, its own rule
     * @param origin     per frame (ribs, then the fixed frame), its origin, m
     * @param firstFrame the first frame node (frame f's nodes are {@code firstFrame + 4 f ..+3})
     * @param fixedFrame the fixed frame's index
     * @param radiusM    R, m; 0 for each vertex by its own rule alone
     * @param builder    receives one row per vertex
     * @param uniform    out: per vertex, true when every neighbour within R has exactly its own rule's carrier
     */
    static void rows(TriangleMesh pleura, Rule[] rules, double[][] origin, int firstFrame, int fixedFrame,
            double radiusM, LinearMapping.Builder builder, boolean[] uniform) {
        int n = pleura.vertexCount();
        double[] xyz = pleura.coordinates();
        Map<Integer, Double> own = new LinkedHashMap<>();
        if (radiusM == 0) {
            for (int v = 0; v < n; v++) {
                own.clear();
                add(own, rules[v], new double[] {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}, 1, origin, firstFrame,
                        fixedFrame);
                put(builder, own, 1);
                uniform[v] = rules[v].kind() != PleuraCarriers.Carrier.DIAPHRAGM;
            }
            return;
        }
        Grid grid = new Grid(xyz, radiusM);
        double r2 = radiusM * radiusM;
        Map<Integer, Double> row = new LinkedHashMap<>();
        for (int v = 0; v < n; v++) {
            row.clear();
            double[] p = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
            double[] sum = {0};
            boolean[] same = {true};
            final int vv = v;
            grid.forEachNear(p, u -> {
                double dx = xyz[3 * u] - p[0], dy = xyz[3 * u + 1] - p[1], dz = xyz[3 * u + 2] - p[2];
                double d2 = dx * dx + dy * dy + dz * dz;
                if (d2 >= r2) {
                    return;
                }
                double s = 1 - d2 / r2;
                double k = s * s;
                sum[0] += k;
                add(row, rules[u], p, k, origin, firstFrame, fixedFrame);
                same[0] &= sameCarrier(rules[u], rules[vv]);
            });
            uniform[v] = same[0];
            put(builder, row, sum[0]);
        }
    }

    private static void put(LinearMapping.Builder builder, Map<Integer, Double> row, double sum) {
        int[] nodes = new int[row.size()];
        double[] weights = new double[row.size()];
        int i = 0;
        for (Map.Entry<Integer, Double> e : row.entrySet()) {
            nodes[i] = e.getKey();
            weights[i++] = e.getValue() / sum;
        }
        builder.add(nodes, weights);
    }

    private static boolean sameCarrier(Rule a, Rule b) {
        return a.kind() == b.kind() && a.kind() != PleuraCarriers.Carrier.DIAPHRAGM && a.frameA() == b.frameA()
                && a.frameB() == b.frameB() && a.a() == b.a();
    }

    /** Adds k times rule u evaluated at p to the row. */
    private static void add(Map<Integer, Double> row, Rule u, double[] p, double k, double[][] origin, int firstFrame,
            int fixedFrame) {
        switch (u.kind()) {
            case RIB, FIXED -> frame(row, u.frameA(), p, k, origin, firstFrame);
            case INTERCOSTAL -> {
                frame(row, u.frameA(), p, k * u.a(), origin, firstFrame);
                frame(row, u.frameB(), p, k * (1 - u.a()), origin, firstFrame);
            }
            case DIAPHRAGM -> {
                for (int c = 0; c < 3; c++) {
                    row.merge(u.nodes()[c], k * u.w()[c], Double::sum);
                }
                // p - q_u on the fixed frame: the affine weights of (origin + p - q) less those of the origin.
                double[] o = origin[fixedFrame];
                double[] lam = PleuraCarriers.frameWeights(o, new double[] {o[0] + p[0] - u.q()[0],
                        o[1] + p[1] - u.q()[1], o[2] + p[2] - u.q()[2]});
                for (int c = 0; c < 4; c++) {
                    row.merge(firstFrame + 4 * fixedFrame + c, k * (lam[c] - (c == 0 ? 1 : 0)), Double::sum);
                }
            }
            default -> throw new IllegalStateException("carrier " + u.kind());
        }
    }

    private static void frame(Map<Integer, Double> row, int f, double[] p, double k, double[][] origin,
            int firstFrame) {
        double[] lam = PleuraCarriers.frameWeights(origin[f], p);
        for (int c = 0; c < 4; c++) {
            row.merge(firstFrame + 4 * f + c, k * lam[c], Double::sum);
        }
    }

    /** A uniform grid of cell R over the points, for the neighbours within R. */
    private static final class Grid {
        private final Map<Long, int[]> cells = new java.util.HashMap<>();
        private final double cell;

        Grid(double[] xyz, double cellM) {
            this.cell = cellM;
            Map<Long, java.util.List<Integer>> lists = new java.util.HashMap<>();
            for (int i = 0; 3 * i < xyz.length; i++) {
                lists.computeIfAbsent(key(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], 0, 0, 0),
                        k -> new java.util.ArrayList<>()).add(i);
            }
            lists.forEach((k, l) -> cells.put(k, l.stream().mapToInt(Integer::intValue).toArray()));
        }

        private long key(double x, double y, double z, int dx, int dy, int dz) {
            long i = (long) Math.floor(x / cell) + dx + (1 << 20);
            long j = (long) Math.floor(y / cell) + dy + (1 << 20);
            long k = (long) Math.floor(z / cell) + dz + (1 << 20);
            return (i << 42) | (j << 21) | k;
        }

        void forEachNear(double[] p, java.util.function.IntConsumer f) {
            for (int dx = -1; dx <= 1; dx++) {
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dz = -1; dz <= 1; dz++) {
                        int[] c = cells.get(key(p[0], p[1], p[2], dx, dy, dz));
                        if (c != null) {
                            for (int u : c) {
                                f.accept(u);
                            }
                        }
                    }
                }
            }
        }
    }
}
