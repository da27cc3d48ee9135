package org.tensim.experiment.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class ErrorHotspotsTest {
    // Four nodes: two upper ones in the cell x 0-30, y 0-30 mm, one upper in x -30-0, y 30-60 mm, one lower.
    private static final double[] REST = {
        0.005, 0.010, 1.0,
        0.025, 0.029, 1.1,
        -0.001, 0.045, 0.9,
        0.005, 0.010, 0.99};
    private static final boolean[] UPPER = {true, true, true, false};

    @Test
    void cellsAreRankedByTheirShareOfTheSquaredDifferenceOverTheUpperNodes() {
        // |d| = 3, 3 in the first cell (18), 2 in the second (4); the lower node's 100 does not count.
        double[] diff = {3, 0, 0, 0, 0, -3, 0, 2, 0, 100, 0, 0};
        List<Map<String, Object>> cells = ErrorHotspots.of(REST, UPPER, diff, 0.030, 3);
        assertEquals(2, cells.size(), cells.toString());
        assertEquals(List.of(0.0, 30.0), cells.get(0).get("x_mm"));
        assertEquals(List.of(0.0, 30.0), cells.get(0).get("y_mm"));
        assertEquals(18.0 / 22, (double) cells.get(0).get("share"), 1e-3);
        assertEquals(List.of(-30.0, 0.0), cells.get(1).get("x_mm"));
        assertEquals(List.of(30.0, 60.0), cells.get(1).get("y_mm"));
        assertEquals(4.0 / 22, (double) cells.get(1).get("share"), 1e-3);
        assertEquals(1, ErrorHotspots.of(REST, UPPER, diff, 0.030, 1).size());
        // With 0.1 m cells the third node (x = -1 mm) still lies in a cell of its own, across x = 0: two cells,
        // the same shares.
        List<Map<String, Object>> wide = ErrorHotspots.of(REST, UPPER, diff, 0.1, 3);
        assertEquals(2, wide.size(), wide.toString());
        assertEquals(List.of(0.0, 100.0), wide.get(0).get("y_mm"));
        assertEquals(18.0 / 22, (double) wide.get(0).get("share"), 1e-3);
    }

    @Test
    void noDifferenceHasNoHotspotAndBadArgumentsAreRefused() {
        assertTrue(ErrorHotspots.of(REST, UPPER, new double[12], 0.030, 3).isEmpty());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ErrorHotspots.of(REST, UPPER, new double[12], 0, 3));
        assertTrue(e.getMessage().contains("cell size > 0 m"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ErrorHotspots.of(REST, UPPER, new double[12], 0.03, 0));
    }
}
