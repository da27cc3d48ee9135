package org.tensim.analysis.lungs;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.landmarks.LandmarkFormatException;

/** The run folder's form of a model motion: round trip, the VTK points series, malformed rows refused. */
class LungPointsFolderTest {
    @TempDir
    Path tmp;

    private static ModelMotion motion() {
        return motion(0.05);
    }

    private static ModelMotion motion(double stepS) {
        return new SyntheticMotion(0.002, 0.01, 0.006, 0.001).motion(SyntheticMotion.cosine(1, 4), stepS, 4, 3, 1);
    }

    @Test
    void theFolderReadsBackAsWrittenWithItsVtkSeries() throws Exception {
        ModelMotion m = motion();
        Path dir = SyntheticMotion.writeRun(tmp.resolve("run"), m);
        ModelMotion r = LungPointsFolder.read(dir);
        assertArrayEquals(m.timesS(), r.timesS(), 0);
        assertArrayEquals(m.lung(), r.lung());
        assertEquals(m.positionsM().length, r.positionsM().length);
        for (int k = 0; k < m.positionsM().length; k++) {
            assertArrayEquals(m.positionsM()[k], r.positionsM()[k], 1e-15);
        }
        assertArrayEquals(m.law(), r.law(), 0);
        assertArrayEquals(m.superior(), r.superior(), 0);
        assertEquals(m.endExhaleS(), r.endExhaleS(), 0);
        assertEquals(m.endInhaleS(), r.endInhaleS(), 0);
        assertEquals(m.periodS(), r.periodS(), 0);
        List<String> lines = Files.readAllLines(dir.resolve(LungPointsFolder.CSV));
        assertEquals("t_s,point,lung,x_mm,y_mm,z_mm", lines.get(0));
        assertEquals(1 + m.timesS().length * m.points(), lines.size());
        Path vtk = dir.resolve(LungPointsFolder.VTK);
        String pvd = Files.readString(vtk.resolve("lung-points.pvd"));
        assertEquals(m.timesS().length, pvd.split("<DataSet ", -1).length - 1);
        String frame = Files.readString(vtk.resolve("lung-points_0010.vtk"));
        assertTrue(frame.contains("POINTS " + m.points() + " double"), frame.substring(0, 200));
        assertTrue(frame.contains("VERTICES " + m.points() + " " + 2 * m.points()));
        assertTrue(!frame.contains("POLYGONS"));
        List<String> summaryFiles = new ArrayList<>();
        ((List<?>) org.tensim.io.Json.readMap(dir.resolve("summary.json")).get("files"))
                .forEach(f -> summaryFiles.add(f.toString()));
        assertTrue(summaryFiles.containsAll(List.of("lung-points.csv", "lung-points")), summaryFiles.toString());
    }

    @Test
    void aPositionBetweenTheLastInstantAndTheNextCycleIsInterpolatedAcrossTheGap() {
        ModelMotion m = motion(); // instants 0, 0.05, ..., 3.95 s of a 4 s period
        double[] last = m.positionsM()[m.timesS().length - 1];
        double[] first = m.positionsM()[0];
        double[] mid = m.positionsAt(3.975);
        double[] early = m.positionsAt(-0.025 - 4);
        for (int j = 0; j < mid.length; j++) {
            assertEquals((last[j] + first[j]) / 2, mid[j], 1e-15);
            assertEquals(mid[j], early[j], 1e-15);
        }
    }

    /** Writes a folder, replaces line {@code line} (from 1) of its CSV and returns the refusal's message. */
    private String refusal(String name, int line, String text) throws Exception {
        // A coarse sampling (10 instants) keeps the seven folders quick to write.
        Path dir = SyntheticMotion.writeRun(tmp.resolve(name), motion(0.4));
        Path csv = dir.resolve(LungPointsFolder.CSV);
        List<String> lines = new ArrayList<>(Files.readAllLines(csv));
        if (text == null) {
            lines.remove(line - 1);
        } else {
            lines.set(line - 1, text);
        }
        Files.write(csv, lines);
        return assertThrows(LandmarkFormatException.class, () -> LungPointsFolder.read(dir)).getMessage();
    }

    @Test
    void aMalformedRowIsRefusedWithTheFileAndLine() throws Exception {
        int n = motion().points();
        String m = refusal("number", 5, "0.0,3,right,1.0,abc,3.0");
        assertTrue(m.startsWith("lung-points.csv, line 5: y_mm is 'abc', not a number; expected a coordinate in mm"),
                m);
        m = refusal("lung", 4, "0.0,2,middle,1.0,2.0,3.0");
        assertTrue(m.startsWith("lung-points.csv, line 4: lung 'middle'; expected right or left"), m);
        m = refusal("order", 4, "0.0,7,right,1.0,2.0,3.0");
        assertTrue(m.startsWith("lung-points.csv, line 4: point 7; expected point 2"), m);
        m = refusal("short", 3, "0.0,1,right,1.0");
        assertTrue(m.startsWith("lung-points.csv, line 3: a row of 4 fields; expected 6"), m);
        m = refusal("header", 1, "t,point,lung,x,y,z");
        assertTrue(m.startsWith("lung-points.csv, line 1: the header is t,point,lung,x,y,z; expected t_s,"), m);
        // A point missing from the second instant: the next row is out of order.
        m = refusal("missing", 2 + n + 5, null);
        assertTrue(m.startsWith("lung-points.csv, line " + (2 + n + 5) + ": point 6; expected point 5"), m);
        // The last instant cut short.
        m = refusal("cut", 1 + motion(0.4).timesS().length * n, null);
        assertTrue(m.contains(": the last instant has " + (n - 1) + " points; expected " + n), m);
        m = refusal("time", 2 + n, "0.0,0,right,1.0,2.0,3.0");
        assertTrue(m.startsWith("lung-points.csv, line " + (2 + n) + ": t_s 0.0 starts an instant at or before"), m);
    }

    @Test
    void aFolderWithoutLungPointsOrItsSummaryKeyIsRefusedByName() throws Exception {
        Path empty = Files.createDirectories(tmp.resolve("empty"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> LungPointsFolder.read(empty));
        assertTrue(e.getMessage().contains("has no lung-points.csv"), e.getMessage());
        Path dir = SyntheticMotion.writeRun(tmp.resolve("nokey"), motion());
        Map<String, Object> s = org.tensim.io.Json.readMap(dir.resolve("summary.json"));
        s.remove(LungPointsFolder.KEY);
        org.tensim.io.Json.write(dir.resolve("summary.json"), s);
        e = assertThrows(IllegalArgumentException.class, () -> LungPointsFolder.read(dir));
        assertTrue(e.getMessage().contains("summary.json has no lung_points"), e.getMessage());
        s.put(LungPointsFolder.KEY, Map.of("end_exhale_s", 3, "end_inhale_s", 1, "period_s", "four",
                "superior", List.of(0, 0, 1)));
        org.tensim.io.Json.write(dir.resolve("summary.json"), s);
        String m = assertThrows(LandmarkFormatException.class, () -> LungPointsFolder.read(dir)).getMessage();
        assertTrue(m.startsWith("summary.json: lung_points.period_s is four; expected"), m);
    }
}
