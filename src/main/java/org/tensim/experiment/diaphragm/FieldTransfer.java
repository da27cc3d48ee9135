package org.tensim.experiment.diaphragm;

import org.tensim.model.LinearMapping;
import org.tensim.scene.diaphragm.ShellMapping;

/**
 * The error of a coarse model's displacement field against a fine one's, the coarse field carried to each
 * fine node by the mapping that carries a fine mesh on a coarse model's shell ({@link ShellMapping}; package-private,
 * used by {@link ResolutionStudy#error}).
 *
 * <p>Each upper-surface node of the fine model (rest position p) is given its coordinates in the coarse shell at rest:
 * the nearest triangle of the coarse upper surface, the barycentric weights along it (the shape functions of a
 * linear triangle) and the depth through the thickness towards the corners' partners on the lower face, which
 * reproduce p exactly ({@link ShellMapping}); the coarse displacement there is the same weighted sum of its nodes'.
 * Then {@code e = sqrt(sum |u_coarse(p) - u_fine|^2 / sum |u_fine|^2)}.
 * Linear interpolation adds an error of second order in the coarse element size, where taking
 * the nearest coarse node would add one of first order (the displacement gradient times half an
 * edge, which at 13 mm elements on a dome of 18 mm excursion is itself several per cent).
 */
final class FieldTransfer {
    private FieldTransfer() {
    }

    /** Relative RMS of the differences {@link #differences} gave (3 per fine node, m) over the fine upper nodes. */
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

    /** The fine model's upper nodes (in their order) carried by the coarse model's shell at rest. */
    static ShellMapping mapping(ResolutionStudy.Run fine, ResolutionStudy.Run coarse) {
        boolean[] fu = fine.upper();
        int n = 0;
        for (boolean b : fu) {
            n += b ? 1 : 0;
        }
        double[] points = new double[3 * n];
        for (int i = 0, k = 0; i < fu.length; i++) {
            if (fu[i]) {
                System.arraycopy(fine.rest(), 3 * i, points, 3 * k++, 3);
            }
        }
        boolean[] pointUpper = new boolean[n];
        java.util.Arrays.fill(pointUpper, true);
        int nc = coarse.rest().length / 3;
        int[] partners = coarse.partners();
        if (partners == null) {
            partners = new int[nc];
            java.util.Arrays.fill(partners, -1);
        }
        return ShellMapping.of(coarse.rest(), coarse.upperTriangles(), coarse.upper(), partners, points, pointUpper);
    }

    /**
     * Per fine node (3 each, m): the coarse displacement carried where the node lies ({@link #mapping}) minus the
     * fine one, on the upper nodes; 0 elsewhere. What {@link #relativeRms} sums, for finding where the error sits.
     */
    static double[] differences(ResolutionStudy.Run fine, ResolutionStudy.Run coarse) {
        LinearMapping m = mapping(fine, coarse).mapping();
        double[] uc = new double[coarse.rest().length];
        for (int k = 0; k < uc.length; k++) {
            uc[k] = coarse.end()[k] - coarse.rest()[k];
        }
        double[] carried = new double[3 * m.pointCount()];
        m.apply(uc, carried);
        double[] diff = new double[fine.rest().length];
        boolean[] fu = fine.upper();
        for (int i = 0, k = 0; i < fu.length; i++) {
            if (!fu[i]) {
                continue;
            }
            for (int a = 0; a < 3; a++) {
                diff[3 * i + a] = carried[3 * k + a] - (fine.end()[3 * i + a] - fine.rest()[3 * i + a]);
            }
            k++;
        }
        return diff;
    }
}
