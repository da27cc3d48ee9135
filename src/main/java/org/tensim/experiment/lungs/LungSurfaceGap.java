package org.tensim.experiment.lungs;

import org.tensim.model.LinearMapping;
import org.tensim.scene.thorax.TriangleTree;

/**
 * How far a lung's own surface lies from its pleura: the lung's outer surface vertices (carried by its lattice)
 * against the pleura's triangles (carried by the diaphragm, the ribs and the fixed frame), both at the state given. At
 * rest the two coincide (the pleura is the lung's outer rest surface), so each vertex's signed distance to the pleura
 * is its departure: positive outside the pleura (the lung pressed into the wall: penetration), negative inside it (the
 * lung come away from the wall: separation). The same vertices are the sliding term's followers
 * ({@code SurfaceSliding}); its own departures are to the planes of the triangles each is paired with, walked from
 * step to step, where this reads the distance to the nearest point of the whole pleura, searched anew.
 *
 * <p>The sign is the side of the nearest triangle's plane (outward by winding); the distance the closest point's. The
 * pleura's tree is rebuilt at each read (a read-out, not a solver stage).
 */
final class LungSurfaceGap {
    private final LinearMapping lungSurface;
    private final LinearMapping pleura;
    private final int[] triangles;
    private final double[] lungXyz;
    private final double[] pleuraXyz;
    private final double[] out = new double[4];
    private double worstPen;
    private double worstSep;
    private double worstPenT = Double.NaN;
    private double worstSepT = Double.NaN;
    private final double[] worstPenAt = new double[3];
    private final double[] worstSepAt = new double[3];

    /**
     * @param lungSurface the lung's surface vertices on the state's nodes
     * @param pleura      the pleura's vertices on the state's nodes
     * @param triangles   the pleura's triangles, 3 vertex ids each, outward by winding
     */
    LungSurfaceGap(LinearMapping lungSurface, LinearMapping pleura, int[] triangles) {
        this.lungSurface = lungSurface;
        this.pleura = pleura;
        this.triangles = triangles;
        this.lungXyz = new double[3 * lungSurface.pointCount()];
        this.pleuraXyz = new double[3 * pleura.pointCount()];
    }

    /** Reads the departures at state {@code x} (m) at time t (s), keeping the largest of each sign. */
    void read(double[] x, double t) {
        lungSurface.apply(x, lungXyz);
        pleura.apply(x, pleuraXyz);
        TriangleTree tree = new TriangleTree(pleuraXyz, triangles, 3);
        int[] stack = tree.newStack();
        for (int v = 0; 3 * v < lungXyz.length; v++) {
            double px = lungXyz[3 * v];
            double py = lungXyz[3 * v + 1];
            double pz = lungXyz[3 * v + 2];
            double d = signedDistance(tree, stack, px, py, pz);
            if (d > worstPen) {
                worstPen = d;
                worstPenT = t;
                worstPenAt[0] = px;
                worstPenAt[1] = py;
                worstPenAt[2] = pz;
            } else if (-d > worstSep) {
                worstSep = -d;
                worstSepT = t;
                worstSepAt[0] = px;
                worstSepAt[1] = py;
                worstSepAt[2] = pz;
            }
        }
    }

    /**
     * The signed distance of a point to the pleura at its last read, m (+ outside): the closest point's distance, with
     * the side of the nearest triangle's plane, which holds the closest point, so any corner of it gives the side.
     */
    private double signedDistance(TriangleTree tree, int[] stack, double px, double py, double pz) {
        int t = tree.nearest(px, py, pz, stack, out);
        int a = 3 * triangles[3 * t];
        int b = 3 * triangles[3 * t + 1];
        int c = 3 * triangles[3 * t + 2];
        double[] p = pleuraXyz;
        double ux = p[b] - p[a];
        double uy = p[b + 1] - p[a + 1];
        double uz = p[b + 2] - p[a + 2];
        double wx = p[c] - p[a];
        double wy = p[c + 1] - p[a + 1];
        double wz = p[c + 2] - p[a + 2];
        double side = (px - p[a]) * (uy * wz - uz * wy) + (py - p[a + 1]) * (uz * wx - ux * wz)
                + (pz - p[a + 2]) * (ux * wy - uy * wx);
        double dist = Math.sqrt(out[3]);
        return side >= 0 ? dist : -dist;
    }

    /** The largest penetration read, m (0 when none). */
    double maxPenetrationM() {
        return worstPen;
    }

    /** The largest separation read, m (0 when none). */
    double maxSeparationM() {
        return worstSep;
    }

    /** When the largest penetration was read, s (NaN when none). */
    double penetrationTimeS() {
        return worstPenT;
    }

    /** When the largest separation was read, s (NaN when none). */
    double separationTimeS() {
        return worstSepT;
    }

    /** Where the largest penetration was read (the lung's vertex), m. */
    double[] penetrationAtM() {
        return worstPenAt.clone();
    }

    /** Where the largest separation was read (the lung's vertex), m. */
    double[] separationAtM() {
        return worstSepAt.clone();
    }
}
