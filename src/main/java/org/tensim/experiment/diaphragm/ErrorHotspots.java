package org.tensim.experiment.diaphragm;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Where a coarse model's error sits: the fine model's upper nodes binned by their rest position's x and y into
 * square cells, and the cells that carry the largest shares of the summed squared difference {@code sum_i |d_i|^2}
 * (the numerator of the study's relative RMS error, {@link ResolutionStudy#error}). A share of 0.4 in one cell
 * means that cell alone makes 0.4 of the error's square; the rest is spread over the others.
 */
final class ErrorHotspots {
    /** Cell size, m: a few elements of the coarse models wide, a region's size on an adult diaphragm. */
    static final double CELL_M = 0.030;

    /** How many cells are reported. */
    static final int TOP = 3;

    private ErrorHotspots() {
    }

    /**
     * @param rest  rest positions of the fine model, 3 per node, m
     * @param upper per node, whether it is on the upper surface (only those count)
     * @param diff  per node, the difference vector, 3 per node (any length unit)
     * @param cellM the cells' side, m (&gt; 0)
     * @param top   how many cells (&gt;= 1)
     * @return the {@code top} cells with the largest shares, largest first, each with {@code x_mm} and
     *         {@code y_mm} (the cell's bounds, mm) and {@code share} (0-1); empty when the difference is 0
     */
    static List<Map<String, Object>> of(double[] rest, boolean[] upper, double[] diff, double cellM, int top) {
        if (!(cellM > 0) || top < 1) {
            throw new IllegalArgumentException("error hotspots need a cell size > 0 m and at least one cell, got "
                    + cellM + " m and " + top);
        }
        Map<List<Long>, Double> sums = new HashMap<>();
        double total = 0;
        for (int i = 0; i < upper.length; i++) {
            if (!upper[i]) {
                continue;
            }
            double d2 = diff[3 * i] * diff[3 * i] + diff[3 * i + 1] * diff[3 * i + 1] + diff[3 * i + 2] * diff[3 * i + 2];
            long cx = (long) Math.floor(rest[3 * i] / cellM);
            long cy = (long) Math.floor(rest[3 * i + 1] / cellM);
            sums.merge(List.of(cx, cy), d2, Double::sum);
            total += d2;
        }
        List<Map<String, Object>> out = new ArrayList<>();
        if (!(total > 0)) {
            return out;
        }
        List<Map.Entry<List<Long>, Double>> cells = new ArrayList<>(sums.entrySet());
        cells.sort((a, b) -> Double.compare(b.getValue(), a.getValue()));
        for (Map.Entry<List<Long>, Double> c : cells.subList(0, Math.min(top, cells.size()))) {
            long cx = c.getKey().get(0);
            long cy = c.getKey().get(1);
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("x_mm", List.of(mm(cx * cellM), mm((cx + 1) * cellM)));
            m.put("y_mm", List.of(mm(cy * cellM), mm((cy + 1) * cellM)));
            m.put("share", DiaphragmReport.round(c.getValue() / total, 3));
            out.add(m);
        }
        return out;
    }

    private static double mm(double m) {
        return DiaphragmReport.round(1e3 * m, 1);
    }
}
