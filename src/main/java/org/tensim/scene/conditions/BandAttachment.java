package org.tensim.scene.conditions;

import java.util.BitSet;
import java.util.List;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * The paper's attachment by a distance threshold W as a band of ties with a stiffness per unit area, on any
 * topology and any targets: node i, of area share A_i (m^2) and rest distance d_i to its nearest target, is tied
 * with
 * <pre>
 *   k_i = k_b A_i taper(d_i),   taper(d) = 1 for d &lt;= W - T,  cos^2(pi (d - W + T) / (2 T)) up to W,  0 beyond
 * </pre>
 * (k_b in Pa/m, T the taper's width, 0 for a sharp edge), shared among the targets within W in proportion to their
 * own tapers, {@code taper(d_is) / sum_s taper(d_is)}: a node between two targets follows both, so that the
 * displacement the band imposes varies continuously where the nearest target changes. Unlike a tie per node within
 * W ({@link DistanceAttachment}), whose total stiffness grows with the number of nodes, the band's total stiffness
 * is k_b times its area and converges as the mesh is refined; the taper keeps nodes entering the band from adding
 * stiffness in steps. A node's tie frequency {@code sqrt(k_b A_i / m_i)} does not depend on the element size when
 * its mass is its area's.
 *
 * <p>The diaphragm's default attachment ({@code scene.diaphragm.AttachmentBand}: its ribs, cartilages, sternum
 * and spine as targets) and a scene file's {@code attachment} with {@code mode: band} (one rigid body) are this.
 * It runs in two phases, {@link #weigh} then {@link #tie}, so that a caller may change a node's weight between
 * them (the diaphragm's crura, where no node lies near its spine segment).
 */
public final class BandAttachment {
    private BandAttachment() {
    }

    /** What a target does with its share k (N/m, &gt; 0) of a node's band stiffness: a tie, or several. */
    @FunctionalInterface
    public interface Tie {
        void attach(Topology t, int node, double stiffnessNPerM);
    }

    /**
     * Something a band ties nodes to.
     *
     * @param name     for messages
     * @param distance its distance from a node's rest point, m
     * @param tie      what tying a node to it with a stiffness does
     */
    public record Target(String name, DistanceAttachment.Distance distance, Tie tie) {
        public Target {
            if (name == null || distance == null || tie == null) {
                throw new IllegalArgumentException("a band target needs a name, a distance and a tie, got " + name
                        + ", " + distance + ", " + tie);
            }
        }
    }

    /**
     * Per node of the topology (at the time of {@link #weigh}): its weight {@code taper(d)} to its nearest target,
     * the index of that target (-1 for none; a caller may set it so to take the node out of the targets' ties),
     * that distance (m; infinite for a node that is not a candidate) and its shares among the targets (null
     * where no target is within W). The arrays are the caller's to change before {@link #tie}.
     */
    public record Weights(double[] weight, int[] nearest, double[] distance, double[][] share) {
    }

    /** 1 inside the band, falling as cos^2 over the last {@code taperM} metres to 0 at {@code thresholdM}. */
    public static double taper(double d, double thresholdM, double taperM) {
        if (d >= thresholdM) {
            return 0;
        }
        if (d <= thresholdM - taperM) {
            return 1;
        }
        double c = Math.cos(0.5 * Math.PI * (d - (thresholdM - taperM)) / taperM);
        return c * c;
    }

    /**
     * Each candidate's weight, nearest target and shares, at its rest position.
     *
     * @param thresholdM W, m (finite, &gt;= 0)
     * @param taperM     T, m (0 &lt;= T &lt;= W)
     */
    public static Weights weigh(Topology t, BitSet candidates, List<Target> targets, double thresholdM,
            double taperM) {
        if (!(thresholdM >= 0) || Double.isInfinite(thresholdM)) {
            throw new IllegalArgumentException("band attachment threshold must be >= 0 and finite (m), got "
                    + thresholdM);
        }
        if (!(taperM >= 0 && taperM <= thresholdM)) {
            throw new IllegalArgumentException("attachment band taper (" + taperM * 1e3 + " mm) must be between 0"
                    + " and the attachment threshold (" + thresholdM * 1e3 + " mm)");
        }
        int n = t.nodeCount();
        double[] weight = new double[n];
        int[] nearest = new int[n];
        double[] distance = new double[n];
        double[][] share = new double[n][];
        java.util.Arrays.fill(nearest, -1);
        java.util.Arrays.fill(distance, Double.POSITIVE_INFINITY);
        for (int v = candidates.nextSetBit(0); v >= 0 && v < n; v = candidates.nextSetBit(v + 1)) {
            Vec3 q = t.node(v).position();
            double bestD = Double.POSITIVE_INFINITY;
            double[] own = new double[targets.size()];
            double sum = 0;
            for (int i = 0; i < targets.size(); i++) {
                double d = targets.get(i).distance().at(q);
                own[i] = taper(d, thresholdM, taperM);
                sum += own[i];
                if (d < bestD) {
                    bestD = d;
                    nearest[v] = i;
                }
            }
            weight[v] = taper(bestD, thresholdM, taperM);
            distance[v] = bestD;
            if (sum > 0) {
                for (int i = 0; i < own.length; i++) {
                    own[i] /= sum;
                }
                share[v] = own;
            }
        }
        return new Weights(weight, nearest, distance, share);
    }

    /**
     * Ties node v with stiffness k (N/m, its {@code k_b A_v weight}) to the targets by its shares, in target
     * order; nothing where it has no share.
     */
    public static void tie(Topology t, Weights w, int v, double stiffnessNPerM, List<Target> targets) {
        double[] sh = w.share()[v];
        if (sh == null) {
            return;
        }
        for (int i = 0; i < sh.length; i++) {
            if (sh[i] > 0) {
                targets.get(i).tie().attach(t, v, stiffnessNPerM * sh[i]);
            }
        }
    }
}
