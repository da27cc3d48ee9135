package org.tensim.io.landmarks;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.testsupport.SharedData;

class DirLabLandmarksTest {
    /**
     * Mean 3D displacement, its SD and its maximum (mm) over each case's 300 landmarks from end-exhale to
     * end-inhale, as published (Castillo et al. 2009; Vandemeulebroucke et al. 2012, Table I) and quoted in the
     * shared folder's ATTRIBUTION.md.
     */
    private static final double[][] PUBLISHED = {
        {3.89, 2.78, 10.9}, {4.34, 3.90, 17.7}, {6.94, 4.05, 16.6}, {9.83, 4.86, 20.3}, {7.48, 5.51, 24.8}};

    @TempDir
    Path tmp;

    private static Path shared(int n) {
        Path f = SharedData.LUNG_LANDMARKS.resolve("case" + n + "-300-ee-ei.csv");
        Assumptions.assumeTrue(Files.isRegularFile(f), f.toAbsolutePath() + " not found");
        Path g = SharedData.LUNG_LANDMARKS.resolve("case" + n + "-75-six-phases.csv");
        Assumptions.assumeTrue(Files.isRegularFile(g), g.toAbsolutePath() + " not found");
        return SharedData.LUNG_LANDMARKS;
    }

    @Test
    void theSharedPairsGiveThePublishedMeanDisplacements() throws Exception {
        for (int n = 1; n <= 5; n++) {
            LandmarkSet s = DirLabLandmarks.readPairs(shared(n), n);
            assertEquals(300, s.count(), "case " + n + " landmarks");
            assertEquals(List.of("ee", "ei"), s.phases());
            assertEquals(1, s.ids()[0]);
            assertEquals(300, s.ids()[299]);
            double[] p = PUBLISHED[n - 1];
            // Published to two decimals: the figure rounds to it, within 0.01 mm.
            assertEquals(p[0], s.meanDisplacement("ee", "ei") * 1e3, 0.005 + 1e-9, "case " + n + " mean, mm");
            assertEquals(p[1], s.displacementSd("ee", "ei") * 1e3, 0.005 + 1e-9, "case " + n + " SD, mm");
            assertEquals(p[2], s.maxDisplacement("ee", "ei") * 1e3, 0.05 + 1e-9, "case " + n + " max, mm");
        }
    }

    @Test
    void theSharedPairsAreInMetresWithTheHeadAlongMinusZ() throws Exception {
        LandmarkSet s = DirLabLandmarks.readPairs(shared(1), 1);
        // Line 2 of case1-300-ee-ei.csv: 1,203.70,135.80,155.00,203.70,133.86,162.50 (mm).
        assertArrayEquals(new double[] {0.2037, 0.1358, 0.155}, java.util.Arrays.copyOf(s.at("ee"), 3), 1e-12);
        assertArrayEquals(new double[] {0.2037, 0.13386, 0.1625}, java.util.Arrays.copyOf(s.at("ei"), 3), 1e-12);
        assertArrayEquals(new double[] {0, 0, -1}, s.superior());
        // Inhaling moves the lowest landmarks to the feet: along +z, against the superior direction.
        double[] x = s.at("ee");
        double[] d = s.displacement("ee", "ei");
        double zMax = 0;
        for (int i = 0; i < s.count(); i++) {
            zMax = Math.max(zMax, x[3 * i + 2]);
        }
        double sum = 0;
        int n = 0;
        for (int i = 0; i < s.count(); i++) {
            if (x[3 * i + 2] > zMax - 0.03) {
                sum += d[3 * i + 2];
                n++;
            }
        }
        assertTrue(n > 10 && sum / n > 0.004, "the basal landmarks move to larger z: " + sum / n + " m over " + n);
    }

    @Test
    void theSharedSixPhaseSetsHave75LandmarksAtSixPhases() throws Exception {
        for (int n = 1; n <= 5; n++) {
            LandmarkSet s = DirLabLandmarks.readSixPhases(shared(n), n);
            assertEquals(75, s.count(), "case " + n);
            assertEquals(DirLabLandmarks.SIX_PHASES, s.phases());
            // End-inhale (t00) to end-exhale (t50) is a real breath: a mean motion of over 1 mm.
            assertTrue(s.meanDisplacement("t50", "t00") > 1e-3, "case " + n + ": "
                    + s.meanDisplacement("t50", "t00"));
        }
    }

    private Path file(String name, String... lines) throws IOException {
        Path f = tmp.resolve(name);
        Files.write(f, List.of(lines));
        return f;
    }

    private static final String HEADER = "landmark,ee_x_mm,ee_y_mm,ee_z_mm,ei_x_mm,ei_y_mm,ei_z_mm";

    @Test
    void aMalformedLineIsRefusedNamingTheFileAndLine() throws Exception {
        Path f = file("case9-300-ee-ei.csv", HEADER, "1,1,2,3,1,2,4", "2,1,2,3,1,2,4", "3,1,2,abc,1,2,4",
                "4,1,2,3,1,2,4");
        LandmarkFormatException e = assertThrows(LandmarkFormatException.class,
                () -> DirLabLandmarks.read(f, DirLabLandmarks.EE_EI));
        assertEquals(4, e.line());
        assertEquals("case9-300-ee-ei.csv, line 4: ee_z_mm is 'abc', not a number; expected a coordinate in mm",
                e.getMessage());
    }

    @Test
    void aShortRowARepeatedLandmarkAWrongHeaderAndAnEmptyFileAreRefused() throws Exception {
        Path shortRow = file("short.csv", HEADER, "1,1,2,3,1,2,4", "2,1,2,3,1,2");
        LandmarkFormatException e = assertThrows(LandmarkFormatException.class,
                () -> DirLabLandmarks.read(shortRow, DirLabLandmarks.EE_EI));
        assertEquals("short.csv, line 3: a row of 6 fields; expected 7 (landmark, then x, y, z in mm at each of"
                + " [ee, ei])", e.getMessage());
        Path twice = file("twice.csv", HEADER, "1,1,2,3,1,2,4", "1,1,2,3,1,2,4");
        e = assertThrows(LandmarkFormatException.class, () -> DirLabLandmarks.read(twice, DirLabLandmarks.EE_EI));
        assertEquals("twice.csv, line 3: landmark 1 appears a second time; expected each landmark once",
                e.getMessage());
        Path header = file("header.csv", "landmark,x,y,z,x,y,z", "1,1,2,3,1,2,4");
        e = assertThrows(LandmarkFormatException.class, () -> DirLabLandmarks.read(header, DirLabLandmarks.EE_EI));
        assertEquals("header.csv, line 1: the header is landmark,x,y,z,x,y,z; expected " + HEADER, e.getMessage());
        Path id = file("id.csv", HEADER, "1.5,1,2,3,1,2,4");
        e = assertThrows(LandmarkFormatException.class, () -> DirLabLandmarks.read(id, DirLabLandmarks.EE_EI));
        assertEquals(2, e.line());
        assertTrue(e.getMessage().contains("landmark '1.5' is not a whole number"), e.getMessage());
        Path empty = file("empty.csv", HEADER);
        e = assertThrows(LandmarkFormatException.class, () -> DirLabLandmarks.read(empty, DirLabLandmarks.EE_EI));
        assertTrue(e.getMessage().startsWith("empty.csv: no landmark row after the header"), e.getMessage());
    }

    @Test
    void aWellFormedFileIsReadInMetres() throws Exception {
        Path f = file("ok.csv", HEADER, "7,10,20,30,11,22,33", "", "8,0,0,0,0,0,2.5");
        LandmarkSet s = DirLabLandmarks.read(f, DirLabLandmarks.EE_EI);
        assertArrayEquals(new int[] {7, 8}, s.ids());
        assertArrayEquals(new double[] {0.001, 0.002, 0.003, 0, 0, 0.0025}, s.displacement("ee", "ei"), 1e-15);
        assertEquals((Math.sqrt(14) + 2.5) / 2 * 1e-3, s.meanDisplacement("ee", "ei"), 1e-15);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> s.at("t00"));
        assertEquals("ok has no phase 't00': its phases are [ee, ei]", e.getMessage());
    }
}
