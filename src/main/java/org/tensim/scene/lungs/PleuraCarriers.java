package org.tensim.scene.lungs;

import java.util.List;
import java.util.Locale;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.model.LinearMapping;
import org.tensim.model.RigidMotion;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.thorax.TriangleTree;

/**
 * The parietal pleura as a surface carried by the nodes of one state: each of its vertices is a row of a
 * {@link LinearMapping}, by the rule below, so that the lungs can slide on it in the same force pass as the
 * diaphragm and the cage move (their reaction reaches the diaphragm's nodes through the mapping's transpose).
 *
 * <p><b>The rule</b> (distances at rest, {@link Rules}): for a vertex p, let d_D be its distance to the diaphragm's
 * upper surface, d_1 and d_2 its distances to the two nearest ribs' centrelines (each rib's polyline).
 * <ul>
 * <li><b>Diaphragmatic</b>, when d_D &lt;= {@link Rules#diaphragmM} and d_D &lt;= d_1: carried by the barycentric
 * weights of the closest point q on the nearest upper triangle (three diaphragm nodes), plus the constant rest
 * offset p - q (so the vertex starts where it is; a translation of the triangle moves it exactly, a turn of the
 * triangle by theta moves it by at most theta |p - q| less than a rigid offset would);</li>
 * <li><b>Costal</b>, when d_1 &lt;= {@link Rules#ribM}, or the second rib is farther than {@link Rules#wallM}:
 * moved rigidly with the nearest rib;</li>
 * <li><b>Intercostal</b>, when d_1 &lt;= {@link Rules#wallM} (and d_2 &lt;= wallM): the two nearest ribs' rigid
 * motions of p blended by distance, weights d_2 / (d_1 + d_2) and d_1 / (d_1 + d_2) (the nearer rib weighs more;
 * each rib's own motion at its own vertices);</li>
 * <li><b>Fixed</b> otherwise (mediastinal, spinal and apical parts, farther than wallM from any rib).</li>
 * </ul>
 * These are each vertex's own carrier; its row is their blend over the neighbours within {@link Rules#blendM}
 * ({@link PleuraBlend}, which says why: by its own carrier alone, the pleura folds where the kinds meet).
 *
 * <p><b>Driven frames, not a node per vertex.</b> A rigid motion is affine, {@code x -> R x + c}, so the motion of
 * any point equals the affine combination {@code sum_k lambda_k X_k(t)} of four driven nodes X_k of that rib placed
 * at {@code o, o + L e_x, o + L e_y, o + L e_z} (o the rib's centroid, L = {@link #FRAME_M}), with the point's
 * fixed affine coordinates {@code lambda = (1 - sum a_i, a_x, a_y, a_z)}, {@code a = (p - o) / L}: exact, to
 * rounding, for every vertex of the rib. So each rib adds four driven nodes (its {@link RigidMotion}, a tiny mass
 * that is never integrated) instead of one per vertex, and the fixed parts four fixed nodes; the diaphragmatic
 * offset p - q is carried by the fixed frame with weights summing to 0. Unblended rows hold 3 + 4, 4 or 8 entries;
 * blended ones the frames' and diaphragm nodes' of the neighbourhood.
 */
public final class PleuraCarriers {
    /** Edge of the carrier frames, m: about the ribs' size, so that the affine weights stay of order 1. */
    public static final double FRAME_M = 0.1;
    /** Mass given to the frame nodes, kg: they are driven or fixed, never integrated. */
    static final double FRAME_MASS_KG = 1e-6;

    /** How a vertex is carried. */
    public enum Carrier { DIAPHRAGM, RIB, INTERCOSTAL, FIXED }

    /**
     * The rule's distances, m.
     *
     * @param diaphragmM farthest a vertex may be from the diaphragm's upper surface to move with it (the lungs' base
     *                   lies on it; the meshes of different sources leave gaps of a few mm)
     * @param ribM       nearest-rib distance within which a vertex moves with that rib alone (a rib's half-height,
     *                   about 6 mm, plus the chest wall's soft tissue between rib and pleura)
     * @param wallM      nearest-rib distance within which a vertex is on the chest wall (intercostal spaces are
     *                   about 20-30 mm between rib centrelines); beyond it the vertex is fixed
     * @param blendM     radius over which the vertices' carriers are blended ({@link PleuraBlend}); 0 for each
     *                   vertex by its own carrier alone
     */
    public record Rules(double diaphragmM, double ribM, double wallM, double blendM) {
        public Rules {
            if (!(blendM >= 0) || Double.isInfinite(blendM)) {
                throw new IllegalArgumentException("the pleura's blend radius " + blendM
                        + " m: expected 0 (each vertex by its own carrier) or a positive length");
            }
            Check.positive("pleura's diaphragm distance", "m", diaphragmM);
            Check.positive("pleura's rib distance", "m", ribM);
            Check.positive("pleura's chest-wall distance", "m", wallM);
            if (wallM < ribM) {
                throw new IllegalArgumentException(String.format(Locale.ROOT, "the pleura's chest-wall distance %.4g"
                        + " m is below its rib distance %.4g m: expected wallM >= ribM", wallM, ribM));
            }
        }

        /**
         * 15 mm to the diaphragm, 12 mm to a rib alone, 40 mm to the chest wall, the carriers blended over 25 mm
         * ({@link PleuraBlend}: about 2.5 times the dome's descent, so that the pleura shears by about 0.4 where the
         * diaphragm's part meets the wall's, instead of folding over one edge).
         */
        public static Rules defaults() {
            return new Rules(0.015, 0.012, 0.040, 0.025);
        }

        /** The same with another blend radius, m (0: each vertex moved by its own carrier alone). */
        public Rules withBlend(double m) {
            return new Rules(diaphragmM, ribM, wallM, m);
        }
    }

    /**
     * A rib as the pleura sees it.
     *
     * @param name     its name (for reports)
     * @param motion   its rigid motion
     * @param polyline its centreline at rest, m, 3 per point (at least 2 points)
     */
    public record Rib(String name, RigidMotion motion, double[] polyline) {
    }

    /**
     * The carried pleura.
     *
     * @param surface   the pleura's rest surface, m (the mapping's point i is its vertex i)
     * @param mapping   the vertices on the state's nodes (nodeCount: the topology's when built)
     * @param carrier   per vertex, how it is carried
     * @param ownRule   per vertex, true when it moves exactly by its own carrier (every neighbour within the blend
     *                  radius carried the same way by the same ribs; never for a diaphragmatic vertex)
     * @param firstNode the first frame node added ({@code 4 (ribs + 1)} nodes from there: ribs' frames, then the
     *                  fixed frame)
     */
    public record Built(TriangleMesh surface, LinearMapping mapping, Carrier[] carrier, boolean[] ownRule,
            int firstNode) {
        /** Number of vertices carried a given way. */
        public int count(Carrier c) {
            int n = 0;
            for (Carrier k : carrier) {
                n += k == c ? 1 : 0;
            }
            return n;
        }
    }

    private PleuraCarriers() {
    }

    /**
     * Adds the frames to {@code t} and maps the pleura's vertices.
     *
     * @param pleura         the pleura's surface at rest, m
     * @param upperTriangles the diaphragm's upper-surface triangles as node ids of {@code t} (3 each)
     * @param ribs           the ribs (may be empty: then nothing is costal or intercostal)
     * @param nodeCount      the node count the mapping is built for (at least the topology's after the frames;
     *                       0 for exactly that)
     */
    public static Built build(Topology t, TriangleMesh pleura, int[] upperTriangles, List<Rib> ribs, Rules rules,
            int nodeCount) {
        int n = t.nodeCount();
        double[] xyz = new double[3 * n];
        for (int i = 0; i < n; i++) {
            Vec3 p = t.node(i).position();
            xyz[3 * i] = p.x();
            xyz[3 * i + 1] = p.y();
            xyz[3 * i + 2] = p.z();
        }
        TriangleTree upper = upperTriangles.length == 0 ? null : new TriangleTree(xyz, upperTriangles, 3);
        int[] stack = upper == null ? null : upper.newStack();
        int first = t.nodeCount();
        double[][] origin = new double[ribs.size() + 1][];
        for (int r = 0; r <= ribs.size(); r++) {
            origin[r] = r < ribs.size() ? centroid(ribs.get(r).polyline()) : centroid(pleura.coordinates());
            for (int k = 0; k < 4; k++) {
                double[] o = origin[r].clone();
                if (k > 0) {
                    o[k - 1] += FRAME_M;
                }
                var node = t.addNode(o[0], o[1], o[2], FRAME_MASS_KG);
                if (r < ribs.size()) {
                    node.drive(ribs.get(r).motion());
                } else {
                    node.fix();
                }
            }
        }
        int fixedFrame = ribs.size();
        LinearMapping.Builder b = new LinearMapping.Builder(nodeCount == 0 ? t.nodeCount()
                : Check.atLeast("pleura mapping's node count", nodeCount, t.nodeCount()));
        Carrier[] carrier = new Carrier[pleura.vertexCount()];
        PleuraBlend.Rule[] rule = new PleuraBlend.Rule[pleura.vertexCount()];
        double[] w = new double[4];
        for (int v = 0; v < pleura.vertexCount(); v++) {
            double px = pleura.coord(v, 0);
            double py = pleura.coord(v, 1);
            double pz = pleura.coord(v, 2);
            int r1 = -1;
            int r2 = -1;
            double d1 = Double.POSITIVE_INFINITY;
            double d2 = Double.POSITIVE_INFINITY;
            for (int r = 0; r < ribs.size(); r++) {
                double d = polylineDistance(ribs.get(r).polyline(), px, py, pz);
                if (d < d1) {
                    d2 = d1;
                    r2 = r1;
                    d1 = d;
                    r1 = r;
                } else if (d < d2) {
                    d2 = d;
                    r2 = r;
                }
            }
            int tri = upper == null ? -1 : upper.nearest(px, py, pz, stack, w);
            double dD = tri < 0 ? Double.POSITIVE_INFINITY : Math.sqrt(w[3]);
            if (dD <= rules.diaphragmM() && dD <= d1) {
                int[] nodes = new int[3];
                double[] q = new double[3];
                for (int k = 0; k < 3; k++) {
                    nodes[k] = upperTriangles[3 * tri + k];
                    for (int a = 0; a < 3; a++) {
                        q[a] += w[k] * xyz[3 * nodes[k] + a];
                    }
                }
                rule[v] = new PleuraBlend.Rule(Carrier.DIAPHRAGM, fixedFrame, -1, 1, nodes,
                        new double[] {w[0], w[1], w[2]}, q);
            } else if (r1 >= 0 && (d1 <= rules.ribM() || d1 <= rules.wallM() && d2 > rules.wallM())) {
                rule[v] = new PleuraBlend.Rule(Carrier.RIB, r1, -1, 1, null, null, null);
            } else if (r1 >= 0 && d1 <= rules.wallM()) {
                rule[v] = new PleuraBlend.Rule(Carrier.INTERCOSTAL, r1, r2, d2 / (d1 + d2), null, null, null);
            } else {
                rule[v] = new PleuraBlend.Rule(Carrier.FIXED, fixedFrame, -1, 1, null, null, null);
            }
            carrier[v] = rule[v].kind();
        }
        boolean[] own = new boolean[pleura.vertexCount()];
        PleuraBlend.rows(pleura, rule, origin, first, fixedFrame, rules.blendM(), b, own);
        return new Built(pleura, b.build(), carrier, own, first);
    }

    /** A point's affine coordinates on the frame at {@code o} (corners o, o + L e_x, o + L e_y, o + L e_z). */
    static double[] frameWeights(double[] o, double[] p) {
        double ax = (p[0] - o[0]) / FRAME_M;
        double ay = (p[1] - o[1]) / FRAME_M;
        double az = (p[2] - o[2]) / FRAME_M;
        return new double[] {1 - ax - ay - az, ax, ay, az};
    }

    private static double[] centroid(double[] xyz) {
        double[] c = new double[3];
        int n = xyz.length / 3;
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                c[a] += xyz[3 * i + a] / n;
            }
        }
        return c;
    }

    /** Distance from a point to a polyline (3 per point), m. */
    static double polylineDistance(double[] line, double px, double py, double pz) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i + 5 < line.length; i += 3) {
            double ax = line[i];
            double ay = line[i + 1];
            double az = line[i + 2];
            double ex = line[i + 3] - ax;
            double ey = line[i + 4] - ay;
            double ez = line[i + 5] - az;
            double len2 = ex * ex + ey * ey + ez * ez;
            double s = len2 > 0 ? ((px - ax) * ex + (py - ay) * ey + (pz - az) * ez) / len2 : 0;
            s = Math.max(0, Math.min(1, s));
            double dx = px - ax - s * ex;
            double dy = py - ay - s * ey;
            double dz = pz - az - s * ez;
            best = Math.min(best, dx * dx + dy * dy + dz * dz);
        }
        return Math.sqrt(best);
    }
}
