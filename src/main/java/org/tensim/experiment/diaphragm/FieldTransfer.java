package org.tensim.experiment.diaphragm;

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
        double num = 0;
        double den = 0;
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
                double d = closest(coarseRest, coarseTriangles, t, p, w);
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
                double uf = fineEnd[3 * i + a] - fineRest[3 * i + a];
                num += (uc - uf) * (uc - uf);
                den += uf * uf;
            }
        }
        return Math.sqrt(num / den);
    }

    /**
     * Squared distance from p to triangle t, and in {@code w} the barycentric weights of the closest
     * point (Ericson, Real-Time Collision Detection, 5.1.5).
     */
    static double closest(double[] x, int[] tri, int t, double[] p, double[] w) {
        int ia = 3 * tri[3 * t];
        int ib = 3 * tri[3 * t + 1];
        int ic = 3 * tri[3 * t + 2];
        double abx = x[ib] - x[ia], aby = x[ib + 1] - x[ia + 1], abz = x[ib + 2] - x[ia + 2];
        double acx = x[ic] - x[ia], acy = x[ic + 1] - x[ia + 1], acz = x[ic + 2] - x[ia + 2];
        double apx = p[0] - x[ia], apy = p[1] - x[ia + 1], apz = p[2] - x[ia + 2];
        double d1 = abx * apx + aby * apy + abz * apz;
        double d2 = acx * apx + acy * apy + acz * apz;
        if (d1 <= 0 && d2 <= 0) {
            return set(w, 1, 0, 0, x, ia, ib, ic, p);
        }
        double bpx = p[0] - x[ib], bpy = p[1] - x[ib + 1], bpz = p[2] - x[ib + 2];
        double d3 = abx * bpx + aby * bpy + abz * bpz;
        double d4 = acx * bpx + acy * bpy + acz * bpz;
        if (d3 >= 0 && d4 <= d3) {
            return set(w, 0, 1, 0, x, ia, ib, ic, p);
        }
        double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            double v = d1 / (d1 - d3);
            return set(w, 1 - v, v, 0, x, ia, ib, ic, p);
        }
        double cpx = p[0] - x[ic], cpy = p[1] - x[ic + 1], cpz = p[2] - x[ic + 2];
        double d5 = abx * cpx + aby * cpy + abz * cpz;
        double d6 = acx * cpx + acy * cpy + acz * cpz;
        if (d6 >= 0 && d5 <= d6) {
            return set(w, 0, 0, 1, x, ia, ib, ic, p);
        }
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            double v = d2 / (d2 - d6);
            return set(w, 1 - v, 0, v, x, ia, ib, ic, p);
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
            double v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            return set(w, 0, 1 - v, v, x, ia, ib, ic, p);
        }
        double denom = 1 / (va + vb + vc);
        double v = vb * denom;
        double u = vc * denom;
        return set(w, 1 - v - u, v, u, x, ia, ib, ic, p);
    }

    private static double set(double[] w, double a, double b, double c, double[] x, int ia, int ib, int ic,
            double[] p) {
        w[0] = a;
        w[1] = b;
        w[2] = c;
        double d = 0;
        for (int k = 0; k < 3; k++) {
            double q = a * x[ia + k] + b * x[ib + k] + c * x[ic + k] - p[k];
            d += q * q;
        }
        return d;
    }
}
