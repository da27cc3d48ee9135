package org.tensim.experiment.diaphragm;

import org.tensim.io.mesh.SurfaceDistance;

/**
 * The error of a coarse model's displacement field against a fine one's, with the coarse
 * field interpolated where each fine node lies (package-private, used by
 * {@link ResolutionStudy#error}).
 *
 * <p>Each upper-surface node of the fine model (rest position p) is projected on the closest
 * point of the coarse model's upper surface at rest (its triangles); the coarse displacement
 * there is the linear interpolation of its corners' (barycentric weights: the shape functions
 * of a linear triangle). Then {@code e = sqrt(sum |u_coarse(p) - u_fine|^2 / sum |u_fine|^2)}.
 * Linear interpolation adds an error of second order in the coarse element size, where taking
 * the nearest coarse node would add one of first order (the displacement gradient times half an
 * edge, which at 13 mm elements on a dome of 18 mm excursion is itself several per cent).
 */
final class FieldTransfer {
    private FieldTransfer() {
    }

    /**
     * @param coarseTriangles the coarse upper surface's triangles, as node ids (3 each)
     */
    static double relativeRms(double[] fineRest, double[] fineEnd, boolean[] fineUpper, double[] coarseRest,
            double[] coarseEnd, int[] coarseTriangles) {
        return relativeRms(fineRest, fineEnd, fineUpper,
                differences(fineRest, fineEnd, fineUpper, coarseRest, coarseEnd, coarseTriangles));
    }

    /** As above, from the differences {@link #differences} gave (3 per fine node, m). */
    static double relativeRms(double[] fineRest, double[] fineEnd, boolean[] fineUpper, double[] diff) {
        double num = 0;
        double den = 0;
        for (int i = 0; i < fineUpper.length; i++) {
            if (!fineUpper[i]) {
                continue;
            }
            for (int a = 0; a < 3; a++) {
                double uf = fineEnd[3 * i + a] - fineRest[3 * i + a];
                num += diff[3 * i + a] * diff[3 * i + a];
                den += uf * uf;
            }
        }
        return Math.sqrt(num / den);
    }

    /**
     * Per fine node (3 each, m): the coarse displacement interpolated where the node lies minus the fine one,
     * on the upper nodes; 0 elsewhere. What {@link #relativeRms} sums, for finding where the error sits.
     */
    static double[] differences(double[] fineRest, double[] fineEnd, boolean[] fineUpper, double[] coarseRest,
            double[] coarseEnd, int[] coarseTriangles) {
        double[] diff = new double[fineRest.length];
        int nt = coarseTriangles.length / 3;
        double[] box = new double[6 * nt];
        for (int t = 0; t < nt; t++) {
            for (int a = 0; a < 3; a++) {
                double lo = Double.POSITIVE_INFINITY;
                double hi = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < 3; k++) {
                    double c = coarseRest[3 * coarseTriangles[3 * t + k] + a];
                    lo = Math.min(lo, c);
                    hi = Math.max(hi, c);
                }
                box[6 * t + a] = lo;
                box[6 * t + 3 + a] = hi;
            }
        }
        double[] p = new double[3];
        double[] w = new double[3];
        double[] best = new double[3];
        for (int i = 0; i < fineUpper.length; i++) {
            if (!fineUpper[i]) {
                continue;
            }
            for (int a = 0; a < 3; a++) {
                p[a] = fineRest[3 * i + a];
            }
            double bd = Double.POSITIVE_INFINITY;
            int bt = -1;
            for (int t = 0; t < nt; t++) {
                double gap = 0; // distance from p to the triangle's box: a lower bound of its distance
                for (int a = 0; a < 3; a++) {
                    double g = Math.max(box[6 * t + a] - p[a], p[a] - box[6 * t + 3 + a]);
                    gap += g > 0 ? g * g : 0;
                }
                if (gap >= bd) {
                    continue;
                }
                double d = SurfaceDistance.closest(coarseRest, coarseTriangles, t, p[0], p[1], p[2], w);
                if (d < bd) {
                    bd = d;
                    bt = t;
                    System.arraycopy(w, 0, best, 0, 3);
                }
            }
            for (int a = 0; a < 3; a++) {
                double uc = 0;
                for (int k = 0; k < 3; k++) {
                    int v = coarseTriangles[3 * bt + k];
                    uc += best[k] * (coarseEnd[3 * v + a] - coarseRest[3 * v + a]);
                }
                diff[3 * i + a] = uc - (fineEnd[3 * i + a] - fineRest[3 * i + a]);
            }
        }
        return diff;
    }
}
