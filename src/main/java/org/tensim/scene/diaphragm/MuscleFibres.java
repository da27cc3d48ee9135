package org.tensim.scene.diaphragm;

import java.util.function.DoubleUnaryOperator;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.conditions.FibreField;

/**
 * The muscle's action as active fibre tension ({@link BoundaryConditions.MuscleLoad#FIBRES};
 * package-private): every triangle of the shell's two faces on the muscle's side of the tendon plane
 * gets an {@link org.tensim.model.ActiveFibre} of thickness t/2 (half per face, as the pressure's
 * load) and active stress {@code sigma_a(t) = P s(t)}, P the live muscle amplitude of
 * {@link DiaphragmControls} read as an active stress (Pa) and s(t) the breathing level. The tension
 * {@code T = sigma_a t} (N/m) is the same on every muscle triangle: along one fibre the tension of a
 * contracting muscle does not vary, so no weighting by the action lines applies, except over the
 * insertion length at its ends, where it is handed to the origins ({@link FibreInsertion}). A triangle
 * cut by the tendon plane counts with its muscle area fraction (exact for a plane cutting a linear
 * triangle).
 *
 * <p>Fibre direction: the meridian towards the tendon. The diaphragm's costal, sternal and crural
 * fibres run from their origins on the ribs, the xiphoid and the spine up the zone of apposition
 * and over the domes, converging radially on the central tendon (Gray's Anatomy, 41st ed., ch. 63;
 * De Troyer and Boriek 2011, Compr. Physiol. 1:1273, "Mechanics of the respiratory muscles"). With
 * c the centre of the tendon (the area-weighted mean of its vertices) and r the horizontal direction
 * from c to the triangle's centroid, the circumferential direction is {@code e_z x r} and the fibre
 * {@code f = n x (e_z x r)} (n the triangle's unit normal): in the triangle's plane, perpendicular to
 * the circle around the tendon's centre, so horizontal and radial on flat parts and vertical on the
 * steep walls of the zone of apposition. Where the plane holds the circumferential direction (a
 * radial, vertical wall: |f| &lt; 0.05) the meridian is not defined and the triangle gets no fibre. The
 * directions and the fibres are the generic {@link FibreField}'s ({@link FibreField#towards} the tendon's centre
 * about the vertical), as a scene file's {@code fibres} condition's; the diaphragm supplies the centre, the
 * muscle's share of each triangle and the insertion.
 */
final class MuscleFibres {
    private MuscleFibres() {
    }

    /**
     * Adds the fibres to t (node ids = mesh vertex ids) and returns how many were added.
     *
     * @param tendonHeight per vertex, a signed height whose zero level is the tendon's edge, positive on the
     *                     tendon: the height above the tendon plane, m, the geodesic rule's signed distance to
     *                     the tendon's edge, m ({@link GeodesicTendon.Region#level}), or +1 / -1 for a tendon given
     *                     by labels (the edge then at mid-edge)
     * @param tendon  per vertex: tendon (true) or muscle
     * @param area    vertex area shares, m^2 (weights of the tendon's centre)
     * @param thicknessM the diaphragm's thickness t, m
     * @param activation per vertex, the share of the active stress in [0, 1] ({@link FibreInsertion}); a
     *                   triangle takes its corners' mean; null: 1 everywhere
     */
    static int add(Topology t, TriangleMesh m, double[] tendonHeight, boolean[] tendon, double[] area,
            double thicknessM, ActionLines lines, double[] activation) {
        double cx = 0;
        double cy = 0;
        double w = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            if (tendon[v]) {
                cx += area[v] * m.coord(v, 0);
                cy += area[v] * m.coord(v, 1);
                w += area[v];
            }
        }
        if (!(w > 0)) {
            throw new IllegalArgumentException("muscle load 'fibres' needs a central tendon to direct the fibres to,"
                    + " and the tendon plane leaves none; expected a tendon fraction above 0");
        }
        cx /= w;
        cy /= w;
        int added = 0;
        double[] h = new double[3];
        // The meridians about the vertical through the tendon's centre (its height does not enter).
        FibreField.Direction meridian = FibreField.towards(new Vec3(cx, cy, 0), new Vec3(0, 0, 1));
        // One law shared by every fibre, so that the force pass evaluates it once.
        DoubleUnaryOperator stress = lines::pressurePa;
        for (int tr = 0; tr < m.triangleCount(); tr++) {
            int[] c = {m.corner(tr, 0), m.corner(tr, 1), m.corner(tr, 2)};
            Vec3[] y = new Vec3[3];
            for (int k = 0; k < 3; k++) {
                y[k] = new Vec3(m.coord(c[k], 0), m.coord(c[k], 1), m.coord(c[k], 2));
                h[k] = tendonHeight[c[k]];
            }
            double fraction = muscleFraction(h);
            double share = activation == null ? 1 : (activation[c[0]] + activation[c[1]] + activation[c[2]]) / 3;
            if (fraction == 0 || share == 0) {
                continue;
            }
            if (FibreField.add(t, c, c, y, meridian, 0.5 * thicknessM * fraction * share, stress)) {
                added++;
            }
        }
        return added;
    }

    /**
     * The share of a linear triangle's area on the muscle side (h &lt; 0) of a plane, from its corners'
     * signed heights h: 1 or 0 when all are on one side, else the corner triangle cut off by the
     * plane, {@code h_k^2 / ((h_k - h_l) (h_k - h_m))} for the corner k alone on its side.
     */
    static double muscleFraction(double[] h) {
        int below = 0;
        for (double v : h) {
            below += v < 0 ? 1 : 0;
        }
        if (below == 0 || below == 3) {
            return below == 3 ? 1 : 0;
        }
        for (int k = 0; k < 3; k++) {
            boolean alone = (h[k] < 0) == (below == 1);
            if (alone) {
                double hk = h[k];
                double hl = h[(k + 1) % 3];
                double hm = h[(k + 2) % 3];
                double corner = hk * hk / ((hk - hl) * (hk - hm));
                return below == 1 ? corner : 1 - corner;
            }
        }
        throw new IllegalStateException("unreachable: a cut triangle has a corner alone on its side");
    }
}
