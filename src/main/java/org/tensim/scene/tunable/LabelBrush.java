package org.tensim.scene.tunable;

import org.tensim.io.mesh.VertexLabel;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * A brush that paints labels onto the diaphragm's mesh at rest: a ray (from the eye through the pointer) picks the
 * vertex it meets first, and every vertex within the brush's radius of it takes the brush's label. Positions are the
 * mesh's own (m), the frame the scene is drawn in at rest.
 */
public final class LabelBrush {
    private LabelBrush() {
    }

    /**
     * The vertex the ray meets first: of the vertices within {@code toleranceM} of the ray's line and in front of its
     * origin, the one nearest the origin along the ray.
     *
     * @param origin     the ray's origin, m (the eye)
     * @param direction  the ray's direction (any length but zero)
     * @param toleranceM how far from the line a vertex may lie and still be hit, m (&gt; 0)
     * @return the vertex, or -1 when the ray passes no vertex
     */
    public static int pick(TwoSurfaces mesh, double[] origin, double[] direction, double toleranceM) {
        double len = Math.sqrt(direction[0] * direction[0] + direction[1] * direction[1]
                + direction[2] * direction[2]);
        if (!(len > 0) || !(toleranceM > 0)) {
            throw new IllegalArgumentException("a pick needs a direction of non-zero length and a tolerance > 0 m,"
                    + " got |d| = " + len + " and " + toleranceM + " m");
        }
        double[] d = {direction[0] / len, direction[1] / len, direction[2] / len};
        int best = -1;
        double bestT = Double.POSITIVE_INFINITY;
        int n = mesh.mesh().vertexCount();
        for (int v = 0; v < n; v++) {
            double rx = mesh.mesh().coord(v, 0) - origin[0];
            double ry = mesh.mesh().coord(v, 1) - origin[1];
            double rz = mesh.mesh().coord(v, 2) - origin[2];
            double t = rx * d[0] + ry * d[1] + rz * d[2];
            if (t <= 0 || t >= bestT) {
                continue;
            }
            double px = rx - t * d[0];
            double py = ry - t * d[1];
            double pz = rz - t * d[2];
            if (px * px + py * py + pz * pz <= toleranceM * toleranceM) {
                best = v;
                bestT = t;
            }
        }
        return best;
    }

    /**
     * The labels with every vertex within {@code radiusM} of vertex {@code centre} (straight-line distance, on either
     * face of the shell) set to {@code label}; {@code labels} is not changed.
     */
    public static VertexLabel[] paint(TwoSurfaces mesh, VertexLabel[] labels, int centre, double radiusM,
            VertexLabel label) {
        int n = mesh.mesh().vertexCount();
        if (labels.length != n) {
            throw new IllegalArgumentException("labels for " + labels.length + " vertices, the mesh has " + n);
        }
        if (centre < 0 || centre >= n || !(radiusM >= 0) || label == null) {
            throw new IllegalArgumentException("a brush stroke needs a vertex of the mesh (0.." + (n - 1) + "), a"
                    + " radius >= 0 m and a label; got vertex " + centre + ", " + radiusM + " m, " + label);
        }
        VertexLabel[] out = labels.clone();
        double cx = mesh.mesh().coord(centre, 0);
        double cy = mesh.mesh().coord(centre, 1);
        double cz = mesh.mesh().coord(centre, 2);
        for (int v = 0; v < n; v++) {
            double dx = mesh.mesh().coord(v, 0) - cx;
            double dy = mesh.mesh().coord(v, 1) - cy;
            double dz = mesh.mesh().coord(v, 2) - cz;
            if (dx * dx + dy * dy + dz * dz <= radiusM * radiusM) {
                out[v] = label;
            }
        }
        return out;
    }
}
