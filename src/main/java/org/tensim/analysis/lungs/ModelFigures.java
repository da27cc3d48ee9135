package org.tensim.analysis.lungs;

import org.tensim.io.landmarks.DirLabLandmarks;

/**
 * A model's lung motion in the measured cases' terms ({@link MeasuredCase}): the SI profile from end-exhale to
 * end-inhale of both lungs and of each, and the time course at DIR-Lab's six phases.
 *
 * <p><b>Phase to time.</b> DIR-Lab's phase {@code tNN} is NN % of the cycle after end-inhale (its ATTRIBUTION.md:
 * {@code t00} end-inhale to {@code t50} end-exhale in steps of a tenth of the cycle), so the model's phase NN is
 * taken at {@code t = endInhaleS + NN / 100 * periodS} (brought into the sampled span by whole periods,
 * {@link ModelMotion#positionsAt}). The shares are those of {@link PhaseShares}: the least-squares factor of the
 * model's own points' field at each phase time on the field from end-exhale ({@code endExhaleS}) to end-inhale.
 * {@code t50}'s share is then 0 only when the model's end-exhale is half a cycle after its end-inhale; it is
 * reported as measured. The breathing law is sampled at the same times and normalised the same way,
 * {@code (L(t) - L(ee)) / (L(ei) - L(ee))}.
 *
 * @param both         the profile of all the points
 * @param right        of the right lung's points (null when it has fewer than 2)
 * @param left         of the left lung's
 * @param phaseTimesS  the time taken for each of the six phases, {@code t00} first, s
 * @param shares       each phase's share, all the points
 * @param sharesRight  the right lung's (null as {@code right})
 * @param sharesLeft   the left lung's
 * @param lawShares    the breathing law at the phases, normalised; null when the motion has no law
 */
public record ModelFigures(SiProfile both, SiProfile right, SiProfile left, double[] phaseTimesS, double[] shares,
        double[] sharesRight, double[] sharesLeft, double[] lawShares) {

    /** The figures of {@code m}. */
    public static ModelFigures of(ModelMotion m) {
        double[] x = m.positionsAt(m.endExhaleS());
        double[] xi = m.positionsAt(m.endInhaleS());
        double[] d = new double[x.length];
        for (int j = 0; j < x.length; j++) {
            d[j] = xi[j] - x[j];
        }
        int[] r = m.pointsOf("right");
        int[] l = m.pointsOf("left");
        int phases = DirLabLandmarks.SIX_PHASES.size();
        double[] times = new double[phases];
        // One more row than the phases: end-exhale itself, the reference of every share.
        double[][] pos = new double[phases + 1][];
        for (int p = 0; p < phases; p++) {
            times[p] = m.endInhaleS() + phasePercent(p) / 100.0 * m.periodS();
            pos[p] = m.positionsAt(times[p]);
        }
        pos[phases] = x;
        pos[0] = xi; // t00 is end-inhale itself
        times[0] = m.endInhaleS();
        double[] law = null;
        if (m.law() != null) {
            double l0 = m.lawAt(m.endExhaleS());
            double l1 = m.lawAt(m.endInhaleS());
            if (!(l1 != l0)) {
                throw new IllegalArgumentException("the breathing law is " + l0 + " at both end-exhale and"
                        + " end-inhale: no share of it can be taken");
            }
            law = new double[phases];
            for (int p = 0; p < phases; p++) {
                law[p] = (m.lawAt(times[p]) - l0) / (l1 - l0);
            }
        }
        return new ModelFigures(SiProfile.of(x, d, m.superior(), null), profile(x, d, m.superior(), r),
                profile(x, d, m.superior(), l), times, sixOf(PhaseShares.of(pos, phases, 0)),
                r.length >= 2 ? sixOf(PhaseShares.of(subset(pos, r), phases, 0)) : null,
                l.length >= 2 ? sixOf(PhaseShares.of(subset(pos, l), phases, 0)) : null, law);
    }

    /** The percentage of the cycle after end-inhale of phase {@code p} of {@link DirLabLandmarks#SIX_PHASES}. */
    public static int phasePercent(int p) {
        return Integer.parseInt(DirLabLandmarks.SIX_PHASES.get(p).substring(1));
    }

    private static SiProfile profile(double[] x, double[] d, double[] up, int[] idx) {
        return idx.length >= 2 ? SiProfile.of(x, d, up, idx) : null;
    }

    private static double[] sixOf(double[] sharesWithExhale) {
        return java.util.Arrays.copyOf(sharesWithExhale, sharesWithExhale.length - 1);
    }

    private static double[][] subset(double[][] pos, int[] idx) {
        double[][] out = new double[pos.length][3 * idx.length];
        for (int p = 0; p < pos.length; p++) {
            for (int k = 0; k < idx.length; k++) {
                System.arraycopy(pos[p], 3 * idx[k], out[p], 3 * k, 3);
            }
        }
        return out;
    }
}
