package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class VtkSeriesWriterTest {
    @TempDir
    Path dir;

    @Test
    void framesCarryPointsTrianglesDisplacementsAndLabelsAndThePvdListsThem() throws Exception {
        VtkSeriesWriter w = new VtkSeriesWriter(dir, "d", new int[] {0, 1, 2}, new int[] {0, 1, 0}, "tissue");
        double[] rest = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        double[] now = {0, 0, 0.5, 1, 0, 0, 0, 1, -0.25};
        w.frame(0, rest, rest);
        Path f = w.frame(0.5, now, rest);
        List<String> lines = Files.readAllLines(f);
        assertEquals("# vtk DataFile Version 3.0", lines.get(0));
        assertTrue(lines.contains("POINTS 3 double"));
        assertTrue(lines.contains("POLYGONS 1 4"));
        assertTrue(lines.contains("3 0 1 2"));
        int v = lines.indexOf("VECTORS displacement double");
        assertEquals("0.000000 0.000000 0.5000000", lines.get(v + 1));
        assertEquals("0.000000 0.000000 -0.2500000", lines.get(v + 3));
        int s = lines.indexOf("SCALARS tissue int 1");
        assertEquals("1", lines.get(s + 3), "label of point 1 (after the LOOKUP_TABLE line)");
        String pvd = Files.readString(w.collection());
        assertTrue(pvd.contains("timestep=\"0.000000\"") && pvd.contains("file=\"d_0001.vtk\"")
                && pvd.contains("timestep=\"0.500000\""), pvd);
        assertEquals(2, w.frameCount());
    }
}
