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
 *
 * <p><b>Driven frames, not a node per vertex.</b> A rigid motion is affine, {@code x -> R x + c}, so the motion of
 * any point equals the affine combination {@code sum_k lambda_k X_k(t)} of four driven nodes X_k of that rib placed
 * at {@code o, o + L e_x, o + L e_y, o + L e_z} (o the rib's centroid, L = {@link #FRAME_M}), with the point's
 * fixed affine coordinates {@code lambda = (1 - sum a_i, a_x, a_y, a_z)}, {@code a = (p - o) / L}: exact, to
 * rounding, for every vertex of the rib. So each rib adds four driven nodes (its {@link RigidMotion}, a tiny mass
 * that is never integrated) instead of one per vertex, and the fixed parts four fixed nodes; the diaphragmatic
 * offset p - q is carried by the fixed frame with weights summing to 0. Rows hold 3 + 4, 4 or 8 entries.
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
     */
    public record Rules(double diaphragmM, double ribM, double wallM) {
        public Rules {
            Check.positive("pleura's diaphragm distance", "m", diaphragmM);
            Check.positive("pleura's rib distance", "m", ribM);
            Check.positive("pleura's chest-wall distance", "m", wallM);
            if (wallM < ribM) {
                throw new IllegalArgumentException(String.format(Locale.ROOT, "the pleura's chest-wall distance %.4g"
                        + " m is below its rib distance %.4g m: expected wallM >= ribM", wallM, ribM));
            }
        }

        /** 15 mm to the diaphragm, 12 mm to a rib alone, 40 mm to the chest wall. */
        public static Rules defaults() {
            return new Rules(0.015, 0.012, 0.040);
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
     * @param firstNode the first frame node added ({@code 4 (ribs + 1)} nodes from there: ribs' frames, then the
     *                  fixed frame)
     */
    public record Built(TriangleMesh surface, LinearMapping mapping, Carrier[] carrier, int firstNode) {
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
            double[] p = {px, py, pz};
            if (dD <= rules.diaphragmM() && dD <= d1) {
                carrier[v] = Carrier.DIAPHRAGM;
                int[] nodes = new int[7];
                double[] weights = new double[7];
                double[] q = new double[3];
                for (int k = 0; k < 3; k++) {
                    nodes[k] = upperTriangles[3 * tri + k];
                    weights[k] = w[k];
                    for (int a = 0; a < 3; a++) {
                        q[a] += w[k] * xyz[3 * nodes[k] + a];
                    }
                }
                // The rest offset p - q on the fixed frame: affine weights of (origin + p - q) minus those of origin.
                double[] lam = frameWeights(origin[fixedFrame], new double[] {origin[fixedFrame][0] + px - q[0],
                        origin[fixedFrame][1] + py - q[1], origin[fixedFrame][2] + pz - q[2]});
                for (int k = 0; k < 4; k++) {
                    nodes[3 + k] = first + 4 * fixedFrame + k;
                    weights[3 + k] = lam[k] - (k == 0 ? 1 : 0);
                }
                b.add(nodes, weights);
            } else if (r1 >= 0 && (d1 <= rules.ribM() || d1 <= rules.wallM() && d2 > rules.wallM())) {
                carrier[v] = Carrier.RIB;
                b.add(frameNodes(first, r1), frameWeights(origin[r1], p));
            } else if (r1 >= 0 && d1 <= rules.wallM()) {
                carrier[v] = Carrier.INTERCOSTAL;
                double a1 = d2 / (d1 + d2);
                double[] l1 = frameWeights(origin[r1], p);
                double[] l2 = frameWeights(origin[r2], p);
                int[] nodes = new int[8];
                double[] weights = new double[8];
                int[] f1 = frameNodes(first, r1);
                int[] f2 = frameNodes(first, r2);
                for (int k = 0; k < 4; k++) {
                    nodes[k] = f1[k];
                    weights[k] = a1 * l1[k];
                    nodes[4 + k] = f2[k];
                    weights[4 + k] = (1 - a1) * l2[k];
                }
                b.add(nodes, weights);
            } else {
                carrier[v] = Carrier.FIXED;
                b.add(frameNodes(first, fixedFrame), frameWeights(origin[fixedFrame], p));
            }
        }
        return new Built(pleura, b.build(), carrier, first);
    }

    private static int[] frameNodes(int first, int frame) {
        int o = first + 4 * frame;
        return new int[] {o, o + 1, o + 2, o + 3};
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
