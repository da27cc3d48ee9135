package org.tensim.scene.lungs;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.volume.VolumeBody;

/**
 * Points embedded in a lattice volume's cells: each point carried by the eight corners of the cell it lies in, with
 * trilinear weights (as {@link VolumeBody} carries its surface), so that points drawn inside a lung move with it.
 */
final class LatticePoints {
    private LatticePoints() {
    }

    /**
     * Adds to {@code b} one row per point (3 per point, m), each on the corners of its cell of {@code body} (a
     * lattice of cell size h on the topology's nodes).
     *
     * @throws IllegalArgumentException naming the point when its cell is not part of the lattice (a point outside
     *                                  the volume)
     */
    static void embed(LinearMapping.Builder b, Topology t, VolumeBody body, double h, double[] points, String what) {
        double[] o = body.originM();
        Map<Long, Integer> nodeAt = new HashMap<>();
        for (int id = body.firstNode(), e = body.firstNode() + body.nodeCount(); id < e; id++) {
            Vec3 p = t.node(id).position();
            nodeAt.put(key((int) Math.round((p.x() - o[0]) / h), (int) Math.round((p.y() - o[1]) / h),
                    (int) Math.round((p.z() - o[2]) / h)), id);
        }
        int[] nodes = new int[8];
        double[] weights = new double[8];
        for (int i = 0; 3 * i < points.length; i++) {
            double[] f = new double[3];
            int[] c = new int[3];
            for (int a = 0; a < 3; a++) {
                double s = (points[3 * i + a] - o[a]) / h;
                c[a] = (int) Math.floor(s);
                f[a] = s - c[a];
            }
            for (int corner = 0; corner < 8; corner++) {
                Integer id = nodeAt.get(key(c[0] + (corner & 1), c[1] + (corner >> 1 & 1), c[2] + (corner >> 2 & 1)));
                if (id == null) {
                    throw new IllegalArgumentException(String.format(Locale.ROOT, "%s %d at (%.1f, %.1f, %.1f) mm"
                            + " lies in no cell of the volume: expected a point inside it", what, i,
                            1e3 * points[3 * i], 1e3 * points[3 * i + 1], 1e3 * points[3 * i + 2]));
                }
                double w = 1;
                for (int a = 0; a < 3; a++) {
                    w *= (corner >> a & 1) == 1 ? f[a] : 1 - f[a];
                }
                nodes[corner] = id;
                weights[corner] = w;
            }
            b.add(nodes.clone(), weights.clone());
        }
    }

    private static long key(int i, int j, int k) {
        return ((long) (i + 1_000_000) * 2_000_003L + (j + 1_000_000)) * 2_000_003L + (k + 1_000_000);
    }
}
