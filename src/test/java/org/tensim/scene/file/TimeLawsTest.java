package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.conditions.TimeLaw;

/** Each law's values as a scene file writes them: sine, ramp, table (both extensions) and CSV file. */
class TimeLawsTest {
    @TempDir
    Path dir;

    TimeLaw law(String laws, String name) {
        Scene s = SceneFiles.load(dir, "l.yaml", "version: 1\nbodies: {c: {type: cube}}\n"
                + "run: {dt: 1 ms, duration: 1 s}\nlaws:\n" + laws);
        return s.laws().get(name);
    }

    @Test
    void sine() {
        TimeLaw l = law("  w: {type: sine, amplitude: 2, frequency: 0.5 Hz, phase: 0.25 rad}\n", "w");
        for (double t : new double[] {0, 0.3, 1, 2.7}) {
            assertEquals(2 * Math.sin(Math.PI * t + 0.25), l.value(t), 1e-15);
        }
        TimeLaw ms = law("  w: {type: sine, frequency: 250 mHz}\n", "w");
        assertEquals(1, ms.value(1), 1e-15, "a quarter period of 0.25 Hz is 1 s");
    }

    @Test
    void ramp() {
        TimeLaw l = law("  r: {type: ramp, start: 100 ms, duration: 0.4 s, from: 1, to: 3}\n", "r");
        assertEquals(1, l.value(0), 0);
        assertEquals(1, l.value(0.1), 0);
        assertEquals(2, l.value(0.3), 1e-12);
        assertEquals(3, l.value(0.5), 0);
        assertEquals(3, l.value(9), 0);
    }

    @Test
    void tablesInterpolateAndExtend() {
        String pts = "points: [[0 s, 0], [1 s, 2], [3 s, 1]]";
        TimeLaw c = law("  t: {type: table, " + pts + "}\n", "t");
        assertEquals(1, c.value(0.5), 1e-15);
        assertEquals(2, c.value(1), 0);
        assertEquals(1.5, c.value(2), 1e-15);
        assertEquals(0, c.value(-1), 0, "constant before the first point");
        assertEquals(1, c.value(10), 0, "constant after the last point");
        TimeLaw e = law("  t: {type: table, " + pts + ", extend: extrapolate}\n", "t");
        assertEquals(-2, e.value(-1), 1e-15, "the first segment's line");
        assertEquals(0.5, e.value(4), 1e-15, "the last segment's line");
        assertEquals(1.5, e.value(2), 1e-15);
        assertThrows(IllegalArgumentException.class,
                () -> TimeLaw.table(new double[] {0, 1, 1}, new double[] {0, 1, 2}, TimeLaw.Extension.CONSTANT));
    }

    @Test
    void csvFiles() {
        SceneFiles.write(dir, "trace.csv", "t_s,factor\n0,0\n0.5,1\n2 s,0\n");
        TimeLaw l = law("  f: {type: csv, file: trace.csv}\n", "f");
        assertEquals(0.5, l.value(0.25), 1e-15);
        assertEquals(0.5, l.value(1.25), 1e-15);
        assertEquals(0, l.value(5), 0);
        SceneFiles.write(dir, "trace-ms.csv", "t,v\n0 ms,0\n500 ms,1\n");
        assertEquals(0.5, law("  f: {type: csv, file: trace-ms.csv}\n", "f").value(0.25), 1e-15);
        // A refusal names the file's line, also after a blank line and without a final line break.
        SceneFiles.write(dir, "back.csv", "t,v\n0,0\n\n1,1\n0.5,2");
        SceneException e = org.junit.jupiter.api.Assertions.assertThrows(SceneException.class,
                () -> law("  f: {type: csv, file: back.csv}\n", "f"));
        org.junit.jupiter.api.Assertions.assertTrue(e.getMessage().startsWith(
                "back.csv:5:1: laws.f.file (back.csv): the times must increase"), e.getMessage());
    }
}
