package org.tensim.io.mesh;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

/**
 * Checks of a mesh's geometry before it becomes a scene: no stray vertex far from
 * the rest (a vertex kilometres away, or at 1e300, is a broken file, not anatomy),
 * and a size that fits the declared {@code --units} and the organ's plausible size.
 * Each refusal names the file, what was measured and what to do.
 */
public final class MeshExtent {
    /**
     * A vertex farther from the median centre than this many times the radius that
     * holds 90 % of the vertices is an outlier. A closed organ surface has every vertex
     * within about 1.5 times that radius; 20 leaves room for long, thin shapes.
     */
    static final double OUTLIER_FACTOR = 20;

    private MeshExtent() {
    }

    /** Refuses a mesh with a vertex far away from all the others (see {@link #OUTLIER_FACTOR}). */
    public static void refuseOutliers(TriangleMesh m, Path file) throws MeshFormatException {
        int n = m.vertexCount();
        if (n < 4) {
            return;
        }
        double[] c = new double[3];
        double[] tmp = new double[n];
        for (int a = 0; a < 3; a++) {
            for (int i = 0; i < n; i++) {
                tmp[i] = m.coord(i, a);
            }
            Arrays.sort(tmp);
            c[a] = tmp[n / 2];
        }
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            r[i] = distance(m, i, c);
        }
        double[] sorted = r.clone();
        Arrays.sort(sorted);
        double r90 = sorted[(int) Math.floor(0.9 * (n - 1))];
        if (!(r90 > 0)) {
            return; // (nearly) all vertices at one point: the cleaner reports the degenerate triangles
        }
        int worst = 0;
        int count = 0;
        for (int i = 0; i < n; i++) {
            if (!(r[i] <= OUTLIER_FACTOR * r90)) {
                count++;
                if (!(r[i] <= r[worst]) || r[worst] <= OUTLIER_FACTOR * r90) {
                    worst = i;
                }
            }
        }
        if (count > 0) {
            throw new MeshFormatException(file, "vertex " + (worst + 1), String.format(Locale.ROOT,
                    "%d vertex(es) lie far from the rest: vertex %d (1-based, as in OBJ) is at (%.6g, %.6g, %.6g) m,"
                            + " %.4g m from the mesh's median centre, where 90 %% of the vertices lie within %.4g m"
                            + " (limit %.0f times that); remove the stray vertices or fix their coordinates",
                    count, worst + 1, m.coord(worst, 0), m.coord(worst, 1), m.coord(worst, 2), r[worst], r90,
                    OUTLIER_FACTOR));
        }
    }

    /**
     * Refuses a mesh whose largest bounding-box side, read in {@code units}, is outside
     * [{@code minM}, {@code maxM}] metres, the plausible size of {@code organ}; the
     * message names the measured size and the units that would fit, if one does.
     */
    public static void refuseImplausibleSize(TriangleMesh m, Path file, MeshUnits units, String organ, double minM,
            double maxM) throws MeshFormatException {
        refuseImplausibleSize(m, file, units, organ, minM, maxM, "--units ");
    }

    /**
     * As {@link #refuseImplausibleSize(TriangleMesh, Path, MeshUnits, String, double, double)}, the units being
     * given as {@code unitsSetting} followed by the unit (e.g. "--units " on the command line, "units: " in a
     * scene file).
     */
    public static void refuseImplausibleSize(TriangleMesh m, Path file, MeshUnits units, String organ, double minM,
            double maxM, String unitsSetting) throws MeshFormatException {
        double[] b = m.bounds();
        double size = Math.max(b[3] - b[0], Math.max(b[4] - b[1], b[5] - b[2]));
        if (size >= minM && size <= maxM) {
            return;
        }
        double fileUnits = size / units.metresPerUnit();
        String fits = null;
        for (MeshUnits u : MeshUnits.values()) {
            double asU = fileUnits * u.metresPerUnit();
            if (u != units && asU >= minM && asU <= maxM) {
                fits = u.name().toLowerCase(Locale.ROOT);
            }
        }
        String advice = fits != null
                ? "the file is probably in " + (fits.equals("m") ? "metres" : "millimetres") + ": use "
                        + unitsSetting + fits
                : "no " + unitsSetting.strip() + " (mm or m) gives a plausible size: check the file's scale";
        throw new MeshFormatException(file, "extent", String.format(Locale.ROOT,
                "the mesh measures %.4g %s across (largest side of its bounding box) = %.4g m with %s%s;"
                        + " a %s measures %.3g to %.3g m: %s",
                fileUnits, units.name().toLowerCase(Locale.ROOT), size, unitsSetting,
                units.name().toLowerCase(Locale.ROOT), organ, minM, maxM, advice));
    }

    private static double distance(TriangleMesh m, int i, double[] c) {
        double dx = m.coord(i, 0) - c[0];
        double dy = m.coord(i, 1) - c[1];
        double dz = m.coord(i, 2) - c[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
