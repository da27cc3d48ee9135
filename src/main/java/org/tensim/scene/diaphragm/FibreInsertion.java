package org.tensim.scene.diaphragm;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * Where the muscle's active fibre tension enters the skeleton (package-private, used with
 * {@link MuscleFibres}): the active stress of a fibre rises from 0 at its ends to its full value
 * over an insertion length L,
 * <pre>
 *   a(d) = sin^2(pi d / (2 L))  for d &lt; L,   1 beyond,
 * </pre>
 * d the distance to the nearest end: the cage segments the attachment band ties the diaphragm to
 * (its origins) or the free rim of the shell (the edge where its two faces meet, or a boundary edge
 * of an open surface), whichever is nearer. A triangle's fibre takes the mean of its corners'.
 *
 * <p>Why: a fibre's tension is handed to the bone through its tendinous insertion, and at a free
 * end it has nothing to pull against (zero traction). With the full active stress up to the edge
 * of the sheet, the tension of every fibre ended in a line load {@code T = sigma_a t} (N/m) along
 * the rim: on the band's ties it was a boundary layer of width {@code sqrt(E t / k_b)}, about 2 mm,
 * which no mesh of 4-13 mm elements resolves (each mesh's rim nodes moved by their own
 * {@code ~ 4 T / (k_b h)}), and where the rim lies below the band (the lateral skirt of the double
 * dome) it pulled the free edge up by 16 mm. Ramped over a length that the coarse meshes resolve,
 * the load enters the band as a smooth body force {@code ~ T / L} per unit area and the free edge
 * carries none. The transmitted force is unchanged: the same tension reaches the band along each
 * fibre; only where it is handed over changes. On a real mesh the rim includes the boundaries of
 * its holes (foramina or meshing gaps): no fibre pulls across a hole. Measured (docs/diaphragm.md,
 * "Boundary conditions"; the runs in docs/history.md).
 */
final class FibreInsertion {
    /** Default insertion length L, m: one and a half times the band's 20 mm width (measured choice). */
    static final double DEFAULT_LENGTH_M = 0.030;

    private FibreInsertion() {
    }

    /** The activation a(d) at distance d (m) from the nearest fibre end, for insertion length L (m). */
    static double ramp(double d, double lengthM) {
        if (d >= lengthM) {
            return 1;
        }
        double s = Math.sin(0.5 * Math.PI * Math.max(0, d) / lengthM);
        return s * s;
    }

    /** Per vertex: on the shell's free rim ({@link TwoSurfaces#ownRim}). */
    static boolean[] rim(TriangleMesh m, TwoSurfaces s) {
        if (m != s.mesh()) {
            throw new IllegalArgumentException("the rim is sought on the surfaces' own mesh");
        }
        return s.ownRim();
    }

    /** Per vertex, the straight distance (m) to the nearest vertex of {@code set}; infinite when it is empty. */
    static double[] distanceTo(TriangleMesh m, boolean[] set) {
        int count = 0;
        for (boolean b : set) {
            count += b ? 1 : 0;
        }
        double[] xs = new double[3 * count];
        int n = 0;
        for (int v = 0; v < set.length; v++) {
            if (set[v]) {
                for (int a = 0; a < 3; a++) {
                    xs[3 * n + a] = m.coord(v, a);
                }
                n++;
            }
        }
        return distanceTo(m, xs);
    }

    /** Per vertex, the straight distance (m) to the nearest of the points {@code xs} (m, 3 each); infinite if none. */
    static double[] distanceTo(TriangleMesh m, double[] xs) {
        int count = xs.length / 3;
        double[] d = new double[m.vertexCount()];
        for (int v = 0; v < d.length; v++) {
            double best = Double.POSITIVE_INFINITY;
            for (int r = 0; r < count; r++) {
                double dx = m.coord(v, 0) - xs[3 * r];
                double dy = m.coord(v, 1) - xs[3 * r + 1];
                double dz = m.coord(v, 2) - xs[3 * r + 2];
                best = Math.min(best, dx * dx + dy * dy + dz * dz);
            }
            d[v] = Math.sqrt(best);
        }
        return d;
    }

    /**
     * Per vertex, the activation a(d) with d the smaller of its distance to the origins
     * ({@code originDistance}, m; null where the attachment gives none) and to the rim.
     *
     * @param lengthM insertion length L, m; 0 gives every vertex the full activation (no insertion)
     */
    static double[] activation(TriangleMesh m, TwoSurfaces s, double[] originDistance, double lengthM) {
        if (!(lengthM >= 0) || Double.isInfinite(lengthM)) {
            throw new IllegalArgumentException("fibre insertion length must be 0 or more metres (finite), got "
                    + lengthM + " m");
        }
        double[] a = new double[m.vertexCount()];
        if (lengthM == 0) {
            java.util.Arrays.fill(a, 1);
            return a;
        }
        double[] rimDistance = distanceTo(m, s.rimPoints());
        for (int v = 0; v < a.length; v++) {
            double d = originDistance == null ? rimDistance[v] : Math.min(originDistance[v], rimDistance[v]);
            a[v] = ramp(d, lengthM);
        }
        return a;
    }
}
