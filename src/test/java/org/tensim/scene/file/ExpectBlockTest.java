package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The expect: block's checks as read: ranges in the column's unit from any unit of its dimension, or from %. */
class ExpectBlockTest {
    @TempDir
    Path dir;

    static String scene(String units, String expect) {
        return String.join("\n", "version: 1", units,
                "bodies: {c: {type: cube}}",
                "regions: {bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}}",
                "conditions: [{type: fixed, region: bottom}]",
                "probes: {p: {node: 13}}",
                "run: {dt: 1 ms, duration: 0.01 s}",
                "expect:", expect, "");
    }

    @Test
    void rangesAreInTheColumnsUnitWhateverUnitTheFileGives() {
        Scene s = SceneFiles.load(dir, "a.yaml", scene("", String.join("\n",
                "  - {column: p_dy_m, stat: min, value: -8 m, tolerance: 2 %}",
                "  - {column: p_dx_m, stat: final, value: 5 mm, tolerance: 0.5 mm}",
                "  - {column: p_dz_m, stat: mean, between: [-3 cm, 20 mm]}",
                "  - {column: t_s, stat: max, value: 10 ms, tolerance: 0.001 ms}",
                "  - {summary: steps, value: 10, tolerance: 0}",
                "  - {summary: dt_s, between: [0.5 ms, 2 ms]}",
                "  - {summary: columns.p_dy_m.min, stat: value, value: -8, tolerance: 10 %}")));
        List<SceneExpectation> e = s.expect();
        assertEquals(7, e.size());
        check(e.get(0), "column", "p_dy_m", "min", "m", -8.16, -7.84);
        check(e.get(1), "column", "p_dx_m", "final", "m", 0.0045, 0.0055);
        check(e.get(2), "column", "p_dz_m", "mean", "m", -0.03, 0.02);
        check(e.get(3), "column", "t_s", "max", "s", 0.01 - 1e-6, 0.01 + 1e-6);
        check(e.get(4), "summary", "steps", "value", "", 10, 10);
        check(e.get(5), "summary", "dt_s", "value", "s", 0.0005, 0.002);
        check(e.get(6), "summary", "columns.p_dy_m.min", "value", "m", -8.8, -7.2);
        assertTrue(e.get(0).where().startsWith("a.yaml:9:5: expect[0]"), e.get(0).where());
        assertEquals("-8 m ± 2 %", e.get(0).stated());
    }

    @Test
    void bareNumbersTakeTheFilesUnits() {
        Scene s = SceneFiles.load(dir, "mm.yaml", scene("units: {length: mm, time: ms}", String.join("\n",
                "  - {column: p_dy_m, stat: min, between: [-3, 2]}",
                "  - {column: t_s, stat: final, value: 10, tolerance: 0.5}")));
        check(s.expect().get(0), "column", "p_dy_m", "min", "m", -0.003, 0.002);
        check(s.expect().get(1), "column", "t_s", "final", "s", 0.0095, 0.0105);
    }

    @Test
    void holdsWithinTheRangeBoundsIncludedAndNeverForNaN() {
        SceneExpectation e = new SceneExpectation("column", "p_dy_m", "min", "m", -2, -1, "", "");
        assertTrue(e.holds(-2));
        assertTrue(e.holds(-1));
        assertTrue(e.holds(-1.5));
        assertFalse(e.holds(-2.0000001));
        assertFalse(e.holds(-0.9999999));
        assertFalse(e.holds(Double.NaN));
    }

    @Test
    void summaryKeysAreTheRunnersNumbersWithTheirUnits() {
        Scene s = SceneFiles.load(dir, "k.yaml", scene("", "  - {summary: body_nodes.c, value: 20, tolerance: 0}"));
        assertEquals(List.of("t_s", "p_dx_m", "p_dy_m", "p_dz_m"), SceneExpectation.columns(s.probes()));
        var keys = SceneExpectation.summaryKeys(s.bodies().keySet(), SceneExpectation.columns(s.probes()));
        assertEquals(List.of("dt_s", "duration_s", "steps", "body_nodes.c", "columns.p_dx_m.min", "columns.p_dx_m.max",
                "columns.p_dy_m.min", "columns.p_dy_m.max", "columns.p_dz_m.min", "columns.p_dz_m.max"),
                List.copyOf(keys.keySet()));
        assertEquals("m", keys.get("columns.p_dy_m.max"));
        assertEquals("s", keys.get("dt_s"));
        assertEquals("", keys.get("body_nodes.c"));
    }

    @Test
    void aRelativeToleranceIsRelativeToTheValuesMagnitudeAndACountRefusesAUnit() {
        Scene s = SceneFiles.load(dir, "r.yaml", scene("", "  - {column: p_dy_m, stat: max, value: -0.5 m,"
                + " tolerance: 10%}"));
        check(s.expect().get(0), "column", "p_dy_m", "max", "m", -0.55, -0.45);
        SceneException x = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "c.yaml", scene("",
                "  - {summary: steps, value: 10 m, tolerance: 0}")));
        assertTrue(x.getMessage().startsWith("c.yaml:9:29: expect[0].value: \"10 m\" is not a number"),
                x.getMessage());
    }

    private static void check(SceneExpectation e, String source, String key, String stat, String unit, double low,
            double high) {
        assertEquals(source, e.source());
        assertEquals(key, e.key());
        assertEquals(stat, e.stat());
        assertEquals(unit, e.unit());
        assertEquals(low, e.low(), 1e-12 * Math.max(1, Math.abs(low)), e.label() + " low");
        assertEquals(high, e.high(), 1e-12 * Math.max(1, Math.abs(high)), e.label() + " high");
    }
}
