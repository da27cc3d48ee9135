package org.tensim.scene.diaphragm;

import org.tensim.scene.shell.TwoSurfaces;

/**
 * Where a diaphragm scene is measured (by the run's summary and the GUI's readouts alike): each hemidiaphragm's top
 * ({@link DomeHeights}), and the 3rd-5th costal cartilages' markers.
 */
public final class MeasuringSites {
    /** Horizontal radius about each dome's top at rest within which its top is sought at every moment, m. */
    public static final double DOME_TOP_RADIUS_M = 0.025;

    /**
     * Least distance of a half's top at rest from the midline, as a fraction of the half's width, for it to count
     * as that hemidiaphragm's own dome top ({@link #domeHeights}).
     */
    public static final double OWN_TOP_FROM_MIDLINE = 0.2;
    /**
     * How each half's top is read in a state ({@link DomeHeights}): where a half has a dome top of its own
     * ({@link DiaphragmScene#domeTops()}, at rest, clear of the midline by {@link #OWN_TOP_FROM_MIDLINE} of the half's
     * width), the highest of the free (not attached) upper-surface nodes within {@code radiusM} horizontally of it:
     * the local highest point. A half whose highest point lies on the midline, rising towards the other, higher dome
     * (the BodyParts3D diaphragm's left, the double dome's left), has no top of its own; it is read on its
     * midclavicular line (half-way from the midline to its lateral edge): the highest point of the free upper surface
     * in that sagittal plane, the coronal silhouette a frontal radiograph shows there, lateral to the heart, where the
     * hemidiaphragm's excursion is read (Hida et al.).
     */
    public static DomeHeights domeHeights(DiaphragmScene s, double radiusM) {
        double[][] tops = s.domeTops();
        int n = s.diaphragmNodes();
        TwoSurfaces surfaces = s.surfaces();
        boolean[] attached = new boolean[n];
        for (int v = 0; v < n; v++) {
            attached[v] = s.isAttached(v);
        }
        int[][] candidates = new int[2][];
        int[][] line = new int[2][];
        double[] lineX = {Double.NaN, Double.NaN};
        for (int d = 0; d < 2; d++) {
            if (tops[d] == null) {
                candidates[d] = new int[0];
            } else if (ownTop(surfaces, tops, d)) {
                final int half = d;
                candidates[d] = java.util.stream.IntStream.range(0, n)
                        .filter(v -> surfaces.isUpper(v) && !attached[v] && Math.hypot(surfaces.mesh().coord(v, 0)
                                - tops[half][0], surfaces.mesh().coord(v, 1) - tops[half][1]) < radiusM)
                        .toArray();
            } else {
                lineX[d] = midclavicularX(surfaces, d);
                line[d] = DomeHeights.lineTriangles(surfaces, attached, lineX[d]);
            }
        }
        return new DomeHeights(candidates, line, lineX);
    }

    /** Where each half's top is sought ({@link #domeHeights}), in words: {right, left}; null for no half. */
    public static String[] domeTopSites(DiaphragmScene s, double radiusM) {
        double[][] tops = s.domeTops();
        String[] site = new String[2];
        for (int d = 0; d < 2; d++) {
            if (tops[d] != null) {
                site[d] = ownTop(s.surfaces(), tops, d)
                        ? String.format(java.util.Locale.ROOT, "local top, within %.0f mm of (%.1f, %.1f) mm",
                                1e3 * radiusM, 1e3 * tops[d][0], 1e3 * tops[d][1])
                        : String.format(java.util.Locale.ROOT,
                                "midclavicular line, the upper surface's highest point in the plane x = %.1f mm",
                                1e3 * midclavicularX(s.surfaces(), d));
            }
        }
        return site;
    }

    private static boolean ownTop(TwoSurfaces surfaces, double[][] tops, int d) {
        double[] b = surfaces.mesh().bounds();
        return Math.abs(tops[d][0] - 0.5 * (b[0] + b[3])) >= OWN_TOP_FROM_MIDLINE * 0.5 * (b[3] - b[0]);
    }

    /** The x of half d's midclavicular line (0 right, below the centre; 1 left), m. */
    private static double midclavicularX(TwoSurfaces surfaces, int d) {
        double[] b = surfaces.mesh().bounds();
        return 0.5 * (b[0] + b[3]) + (d == 0 ? -0.25 : 0.25) * (b[3] - b[0]);
    }

    /** The nodes of the 3rd-5th costal cartilages (their mean is the cartilage marker), empty when the cage has none. */
    public static int[] cartilageMarkerNodes(DiaphragmScene s) {
        java.util.Set<Integer> markers = new java.util.TreeSet<>();
        for (RibCage.Segment sg : s.cage().segments()) {
            if (sg.kind() == RibCage.Kind.CARTILAGE && sg.name().matches(".*[^0-9][345]")) {
                markers.add(sg.a());
                markers.add(sg.b());
            }
        }
        return markers.stream().mapToInt(Integer::intValue).toArray();
    }

    private MeasuringSites() {
    }
}
