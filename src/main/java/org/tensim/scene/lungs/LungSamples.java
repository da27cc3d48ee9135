package org.tensim.scene.lungs;

import java.util.List;
import java.util.Random;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.thorax.TriangleTree;

/**
 * Points drawn in the lungs' volumes to follow: uniform in the volume (rejection in each lung's bounding box by
 * the generalised winding number of its surface, inside where |w| &gt; 1/2, as the lattice is filled), each lung
 * given a share of the points in proportion to its volume, with a fixed seed. Uniform in the volume, they spread
 * over the whole height, apex to base (the counts per fifth of the height are reported in docs/lungs.md).
 *
 * @param positions 3 per point, m, in the surfaces' frame
 * @param lung      each point's lung, an index into the list of surfaces given
 */
public record LungSamples(double[] positions, int[] lung) {
    /** The points' default seed. */
    public static final long SEED = 20080415L;

    /** Number of points. */
    public int count() {
        return lung.length;
    }

    /**
     * Draws {@code n} points in the closed surfaces {@code lungs} (m), in proportion to their enclosed volumes
     * (divergence theorem), with the given seed.
     *
     * @throws IllegalArgumentException when n &lt; 1 or no surface encloses a volume
     */
    public static LungSamples draw(List<TriangleMesh> lungs, int n, long seed) {
        if (n < 1) {
            throw new IllegalArgumentException("the number of lung sample points must be at least 1, got " + n);
        }
        double[] vol = new double[lungs.size()];
        double total = 0;
        for (int i = 0; i < vol.length; i++) {
            vol[i] = Math.abs(lungs.get(i).signedVolume());
            total += vol[i];
        }
        if (!(total > 0)) {
            throw new IllegalArgumentException("the lung surfaces enclose no volume: no point can be drawn in them");
        }
        int[] share = new int[vol.length];
        int given = 0;
        for (int i = 0; i < vol.length; i++) {
            share[i] = i == vol.length - 1 ? n - given : (int) Math.round(n * vol[i] / total);
            given += share[i];
        }
        Random r = new Random(seed);
        double[] pos = new double[3 * n];
        int[] which = new int[n];
        int k = 0;
        for (int i = 0; i < vol.length; i++) {
            TriangleMesh m = lungs.get(i);
            TriangleTree tree = new TriangleTree(m.coordinates(), m.triangles(), 3);
            int[] stack = tree.newStack();
            double[] b = m.bounds();
            int tries = 0;
            for (int got = 0; got < share[i]; tries++) {
                if (tries > 1000 * share[i] + 1000) {
                    throw new IllegalArgumentException("surface " + i + " of the lungs: no point found inside after "
                            + tries + " draws in its bounds");
                }
                double x = b[0] + r.nextDouble() * (b[3] - b[0]);
                double y = b[1] + r.nextDouble() * (b[4] - b[1]);
                double z = b[2] + r.nextDouble() * (b[5] - b[2]);
                if (Math.abs(tree.winding(x, y, z, stack)) > 0.5) {
                    pos[3 * k] = x;
                    pos[3 * k + 1] = y;
                    pos[3 * k + 2] = z;
                    which[k++] = i;
                    got++;
                }
            }
        }
        return new LungSamples(pos, which);
    }
}
