package org.tensim.scene.file;

import java.util.BitSet;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;

/**
 * The faces of a body's surface that a region covers, and the nodal forces of a pressure on them. A surface vertex
 * belongs to a region when the node carrying it (its largest weight, {@link #carriers}) does; a face when its three
 * vertices do.
 *
 * <p>A pressure p on a face of rest area A and outward unit normal n is the force {@code -p A n} (N; p &gt; 0 pushes
 * into the body, as the abdomen's pressure on the diaphragm; p &lt; 0 pulls out, as the pleural pressure on the
 * lung), a third on each corner vertex, and each vertex's force goes to the nodes carrying it by their weights
 * ({@link LinearMapping#addTranspose}: the same virtual work). It is a dead load: the rest normals. The forces
 * sum to {@code -p sum A n}: p times the projected area of the faces on each axis, and zero over a closed surface.
 * The outward side is the one the surface's triangles turn to when its signed volume is positive (a surface given
 * inside out is turned round).
 */
public final class SurfaceFaces {
    private SurfaceFaces() {
    }

    /** For each surface vertex, the node carrying it with the largest weight (the first of equals). */
    public static int[] carriers(LinearMapping map) {
        int[] out = new int[map.pointCount()];
        for (int i = 0; i < out.length; i++) {
            int best = 0;
            for (int k = 1; k < map.entries(i); k++) {
                if (map.weight(i, k) > map.weight(i, best)) {
                    best = k;
                }
            }
            out[i] = map.node(i, best);
        }
        return out;
    }

    /** The faces of {@code s} whose three vertices' carriers are in {@code nodes}. */
    public static BitSet faces(EmbeddedSurface s, BitSet nodes) {
        int[] c = carriers(s.mapping());
        TriangleMesh m = s.mesh();
        BitSet f = new BitSet();
        for (int t = 0; t < m.triangleCount(); t++) {
            if (nodes.get(c[m.corner(t, 0)]) && nodes.get(c[m.corner(t, 1)]) && nodes.get(c[m.corner(t, 2)])) {
                f.set(t);
            }
        }
        return f;
    }

    /** The vector area {@code sum A n} of some faces, outward, m^2. */
    public static double[] vectorArea(EmbeddedSurface s, BitSet faces) {
        TriangleMesh m = s.mesh();
        double sign = orientation(m);
        double[] a = new double[3];
        double[] an = new double[3];
        faces.stream().forEach(t -> {
            areaNormal(m, t, an);
            for (int k = 0; k < 3; k++) {
                a[k] += sign * an[k];
            }
        });
        return a;
    }

    /** The area of some faces, m^2. */
    public static double area(EmbeddedSurface s, BitSet faces) {
        double[] an = new double[3];
        double sum = 0;
        for (int t = faces.nextSetBit(0); t >= 0; t = faces.nextSetBit(t + 1)) {
            areaNormal(s.mesh(), t, an);
            sum += Math.sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        }
        return sum;
    }

    /**
     * Each node's share of the surface's area, m^2: a third of each face's area to each of its corner vertices, and
     * each vertex's share to the nodes carrying it by their weights (the mapping's transpose, as a pressure's
     * forces); the shares sum to the surface's area. A node that carries no surface vertex has none.
     */
    public static double[] nodeAreas(EmbeddedSurface s) {
        TriangleMesh m = s.mesh();
        double[] vertex = new double[3 * m.vertexCount()];
        for (int t = 0; t < m.triangleCount(); t++) {
            double a = m.area(t) / 3;
            for (int c = 0; c < 3; c++) {
                vertex[3 * m.corner(t, c)] += a;
            }
        }
        double[] node = new double[3 * s.mapping().nodeCount()];
        s.mapping().addTranspose(vertex, node);
        double[] out = new double[s.mapping().nodeCount()];
        for (int i = 0; i < out.length; i++) {
            out[i] = node[3 * i];
        }
        return out;
    }

    /**
     * The nodal forces of a unit pressure (1 Pa) on some faces: {@code 3 * nodeCount} values, N per Pa.
     */
    public static double[] unitPressureForces(EmbeddedSurface s, BitSet faces) {
        TriangleMesh m = s.mesh();
        double sign = orientation(m);
        double[] vertexForce = new double[3 * m.vertexCount()];
        double[] an = new double[3];
        faces.stream().forEach(t -> {
            areaNormal(m, t, an);
            for (int c = 0; c < 3; c++) {
                int v = m.corner(t, c);
                for (int k = 0; k < 3; k++) {
                    vertexForce[3 * v + k] -= sign * an[k] / 3;
                }
            }
        });
        double[] nodeForce = new double[3 * s.mapping().nodeCount()];
        s.mapping().addTranspose(vertexForce, nodeForce);
        return nodeForce;
    }

    /** {@code (b - a) x (c - a) / 2} of triangle t: its area times its normal (counter-clockwise). */
    private static void areaNormal(TriangleMesh m, int t, double[] out) {
        int a = m.corner(t, 0);
        int b = m.corner(t, 1);
        int c = m.corner(t, 2);
        double ux = m.coord(b, 0) - m.coord(a, 0);
        double uy = m.coord(b, 1) - m.coord(a, 1);
        double uz = m.coord(b, 2) - m.coord(a, 2);
        double vx = m.coord(c, 0) - m.coord(a, 0);
        double vy = m.coord(c, 1) - m.coord(a, 1);
        double vz = m.coord(c, 2) - m.coord(a, 2);
        out[0] = 0.5 * (uy * vz - uz * vy);
        out[1] = 0.5 * (uz * vx - ux * vz);
        out[2] = 0.5 * (ux * vy - uy * vx);
    }

    /** +1 when the surface's signed volume is &gt;= 0 (its triangles face out), else -1. */
    private static double orientation(TriangleMesh m) {
        double vol = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            int a = m.corner(t, 0);
            int b = m.corner(t, 1);
            int c = m.corner(t, 2);
            vol += m.coord(a, 0) * (m.coord(b, 1) * m.coord(c, 2) - m.coord(b, 2) * m.coord(c, 1))
                    - m.coord(a, 1) * (m.coord(b, 0) * m.coord(c, 2) - m.coord(b, 2) * m.coord(c, 0))
                    + m.coord(a, 2) * (m.coord(b, 0) * m.coord(c, 1) - m.coord(b, 1) * m.coord(c, 0));
        }
        return vol >= 0 ? 1 : -1;
    }
}
