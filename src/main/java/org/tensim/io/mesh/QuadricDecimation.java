package org.tensim.io.mesh;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.PriorityQueue;

/**
 * Mesh simplification by edge collapse ordered by quadric error (Garland and Heckbert 1997): each vertex carries
 * the planes of its triangles (weighted by their areas), an edge's cost is the summed quadric's error at the
 * merged vertex's place plus a small term in the edge's length (so that on a plane, where every error is zero,
 * short edges go first and the triangles stay even), and the cheapest edge is collapsed until the mesh has the
 * target number of triangles.
 *
 * <p>Unlike vertex clustering, the result stays what the input was: a 2-manifold stays one (the link condition),
 * a closed surface stays closed, no triangle folds over (its normal may turn by at most 60 degrees in a
 * collapse), and the triangles keep a quality floor ({@link CollapseMesh}). Groups keep apart what must not
 * merge (the two faces of a thin shell): an edge joins two vertices of one group only, and a vertex where its
 * group's surface ends (an open rim, or a triangle with corners in two groups) stays where it is or slides
 * along that border onto its neighbour on it; planes across the border edges, weighted {@link #BORDER_WEIGHT}
 * times, keep the border's course.
 */
public final class QuadricDecimation {
    /** A simplified mesh and the group of each of its vertices. */
    public record Result(TriangleMesh mesh, int[] groups) {
    }

    /** Weight of a border edge's plane, per squared edge length, against a triangle's plane per its area. */
    static final double BORDER_WEIGHT = 100;
    /** Weight of the edge length's fourth power in an edge's cost, against the quadric's error (m^4). */
    static final double LENGTH_WEIGHT = 1e-3;

    private record Candidate(double cost, int remove, int keep, double x, double y, double z, int removeVersion,
            int keepVersion) {
    }

    private QuadricDecimation() {
    }

    /**
     * @param groups          one group number per vertex (vertices of different groups never merge)
     * @param targetTriangles triangles to stop at (at least 4); fewer collapses happen when the guards allow
     *                        no more, so the result may have more
     */
    public static Result simplify(TriangleMesh m, int[] groups, int targetTriangles) {
        if (groups.length != m.vertexCount()) {
            throw new IllegalArgumentException("decimation needs one group per vertex: got " + groups.length
                    + " groups for " + m.vertexCount() + " vertices");
        }
        if (targetTriangles < 4) {
            throw new IllegalArgumentException("target triangle count " + targetTriangles + ": expected 4 or more");
        }
        CollapseMesh cm = new CollapseMesh(m, groups);
        double[] q = quadrics(cm);
        int nv = m.vertexCount();
        int[] version = new int[nv];
        boolean[] alive = new boolean[nv];
        Arrays.fill(alive, true);
        PriorityQueue<Candidate> heap = new PriorityQueue<>((c, d) -> Double.compare(c.cost, d.cost));
        for (int v = 0; v < nv; v++) {
            for (int w : neighbours(cm, v)) {
                if (w > v) {
                    push(heap, cm, q, version, v, w);
                }
            }
        }
        while (cm.aliveTriangles > targetTriangles && !heap.isEmpty()) {
            Candidate c = heap.poll();
            if (!alive[c.remove] || !alive[c.keep] || version[c.remove] != c.removeVersion
                    || version[c.keep] != c.keepVersion || !cm.canCollapse(c.remove, c.keep, c.x, c.y, c.z)) {
                continue;
            }
            cm.collapse(c.remove, c.keep, c.x, c.y, c.z);
            alive[c.remove] = false;
            Quadrics.add(q, c.keep, c.remove);
            // every edge whose cost or guards the collapse may have changed: those of the kept vertex's ring
            int[] ring = neighbours(cm, c.keep);
            int[] changed = Arrays.copyOf(ring, ring.length + 1);
            changed[ring.length] = c.keep;
            for (int u : changed) {
                version[u]++;
            }
            Arrays.sort(changed);
            for (int u : changed) {
                for (int w : neighbours(cm, u)) {
                    if (w > u || Arrays.binarySearch(changed, w) < 0) {
                        push(heap, cm, q, version, u, w);
                    }
                }
            }
        }
        return compact(cm, alive);
    }

    /** Area-weighted planes of the pure triangles, and the border edges' planes, per vertex. */
    private static double[] quadrics(CollapseMesh cm) {
        double[] q = new double[Quadrics.SIZE * cm.group.length];
        double[] x = cm.xyz;
        for (int t = 0; t < cm.triangleAlive.length; t++) {
            if (!cm.pure(t)) {
                continue;
            }
            int[] c = {cm.tri[3 * t], cm.tri[3 * t + 1], cm.tri[3 * t + 2]};
            double[] n = cross(x, c[0], c[1], c[2]);
            double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (len == 0) {
                continue;
            }
            for (int k = 0; k < 3; k++) {
                Quadrics.addPlane(q, c[k], n[0] / len, n[1] / len, n[2] / len, x[3 * c[0]], x[3 * c[0] + 1],
                        x[3 * c[0] + 2], 0.5 * len);
            }
            for (int k = 0; k < 3; k++) {
                int a = c[k];
                int b = c[(k + 1) % 3];
                if (!cm.border(a, b)) {
                    continue;
                }
                double ex = x[3 * b] - x[3 * a];
                double ey = x[3 * b + 1] - x[3 * a + 1];
                double ez = x[3 * b + 2] - x[3 * a + 2];
                double[] p = {ey * n[2] - ez * n[1], ez * n[0] - ex * n[2], ex * n[1] - ey * n[0]};
                double pl = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                double w = BORDER_WEIGHT * (ex * ex + ey * ey + ez * ez);
                for (int v : new int[] {a, b}) {
                    Quadrics.addPlane(q, v, p[0] / pl, p[1] / pl, p[2] / pl, x[3 * a], x[3 * a + 1], x[3 * a + 2],
                            w);
                }
            }
        }
        return q;
    }

    private static double[] cross(double[] x, int i, int j, int k) {
        double ux = x[3 * j] - x[3 * i];
        double uy = x[3 * j + 1] - x[3 * i + 1];
        double uz = x[3 * j + 2] - x[3 * i + 2];
        double vx = x[3 * k] - x[3 * i];
        double vy = x[3 * k + 1] - x[3 * i + 1];
        double vz = x[3 * k + 2] - x[3 * i + 2];
        return new double[] {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    }

    private static int[] neighbours(CollapseMesh cm, int v) {
        int[] out = new int[3 * cm.triangleCount(v)];
        int n = 0;
        for (int i = 0; i < cm.triangleCount(v); i++) {
            int t = cm.triangle(v, i);
            for (int c = 0; c < 3; c++) {
                out[n++] = cm.tri[3 * t + c];
            }
        }
        return Arrays.stream(out, 0, n).filter(w -> w != v).distinct().toArray();
    }

    /** Queues the cheapest admissible collapse of edge (a, b), if there is one. */
    private static void push(PriorityQueue<Candidate> heap, CollapseMesh cm, double[] q, int[] version, int a,
            int b) {
        if (cm.group[a] != cm.group[b]) {
            return;
        }
        byte ka = cm.kind[a];
        byte kb = cm.kind[b];
        double[] x = cm.xyz;
        List<double[]> options = new ArrayList<>(); // {remove, keep, x, y, z}
        if (ka == CollapseMesh.FREE && kb == CollapseMesh.FREE) {
            double[] p = new double[3];
            double l2 = 0;
            double m2 = 0;
            if (Quadrics.minimum(q, a, b, p)) {
                for (int k = 0; k < 3; k++) {
                    double e = x[3 * b + k] - x[3 * a + k];
                    double d = p[k] - 0.5 * (x[3 * a + k] + x[3 * b + k]);
                    l2 += e * e;
                    m2 += d * d;
                }
            }
            if (l2 > 0 && m2 <= l2) { // an optimum beyond the edge's length is an ill-conditioned one
                options.add(new double[] {a, b, p[0], p[1], p[2]});
            } else {
                options.add(new double[] {a, b, x[3 * b], x[3 * b + 1], x[3 * b + 2]});
                options.add(new double[] {b, a, x[3 * a], x[3 * a + 1], x[3 * a + 2]});
                options.add(new double[] {a, b, 0.5 * (x[3 * a] + x[3 * b]), 0.5 * (x[3 * a + 1] + x[3 * b + 1]),
                    0.5 * (x[3 * a + 2] + x[3 * b + 2])});
            }
        } else if (ka == CollapseMesh.FREE || kb == CollapseMesh.FREE) {
            int keep = ka == CollapseMesh.FREE ? b : a;
            int remove = keep == a ? b : a;
            options.add(new double[] {remove, keep, x[3 * keep], x[3 * keep + 1], x[3 * keep + 2]});
        } else if (ka == CollapseMesh.BORDER && kb == CollapseMesh.BORDER && cm.border(a, b)) {
            options.add(new double[] {a, b, x[3 * b], x[3 * b + 1], x[3 * b + 2]});
            options.add(new double[] {b, a, x[3 * a], x[3 * a + 1], x[3 * a + 2]});
        }
        double l2 = 0;
        for (int k = 0; k < 3; k++) {
            double e = x[3 * b + k] - x[3 * a + k];
            l2 += e * e;
        }
        Candidate best = null;
        for (double[] o : options) {
            double cost = Quadrics.error(q, a, b, o[2], o[3], o[4]) + LENGTH_WEIGHT * l2 * l2;
            int remove = (int) o[0];
            int keep = (int) o[1];
            if ((best == null || cost < best.cost) && cm.canCollapse(remove, keep, o[2], o[3], o[4])) {
                best = new Candidate(cost, remove, keep, o[2], o[3], o[4], version[remove], version[keep]);
            }
        }
        if (best != null) {
            heap.add(best);
        }
    }

    /** The living vertices and triangles, renumbered. */
    private static Result compact(CollapseMesh cm, boolean[] alive) {
        int nv = alive.length;
        int[] index = new int[nv];
        Arrays.fill(index, -1);
        int n = 0;
        for (int v = 0; v < nv; v++) {
            if (alive[v] && cm.triangleCount(v) > 0) {
                index[v] = n++;
            }
        }
        double[] xyz = new double[3 * n];
        int[] groups = new int[n];
        for (int v = 0; v < nv; v++) {
            if (index[v] >= 0) {
                System.arraycopy(cm.xyz, 3 * v, xyz, 3 * index[v], 3);
                groups[index[v]] = cm.group[v];
            }
        }
        int[] tri = new int[3 * cm.aliveTriangles];
        int k = 0;
        for (int t = 0; t < cm.triangleAlive.length; t++) {
            if (cm.triangleAlive[t]) {
                for (int c = 0; c < 3; c++) {
                    tri[k++] = index[cm.tri[3 * t + c]];
                }
            }
        }
        return new Result(new TriangleMesh(xyz, tri), groups);
    }
}
