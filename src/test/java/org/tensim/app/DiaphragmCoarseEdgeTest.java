package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;

/** {@code diaphragm --coarse-edge}: the mechanics on a decimation of the mesh given, carrying it. */
class DiaphragmCoarseEdgeTest {
    @TempDir
    Path dir;

    private static String[] run(String... args) {
        return Commands.run(args);
    }

    @Test
    void theMechanicsRunOnTheDecimationAndTheGivenMeshIsMeasured() throws Exception {
        Path mesh = dir.resolve("dome-14.obj");
        assertEquals("0", run("diaphragm-mesh", "--rings", "14", "--out", mesh.toString())[0]);
        Path out = dir.resolve("run");
        String[] r = run("diaphragm", "--mesh", mesh.toString(), "--coarse-edge", "25", "--integrator", "bdf2",
                "--dt", "0.025", "--seconds", "0.1", "--vtk-per-cycle", "0", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        Map<String, Object> s = Json.readMap(out.resolve("summary.json"));
        int drawn = ((Number) s.get("drawn_nodes")).intValue();
        int mechanical = ((Number) s.get("mechanical_nodes")).intValue();
        assertEquals(((Number) s.get("diaphragm_nodes")).intValue(), drawn, "the given mesh is what is measured");
        assertTrue(mechanical < drawn / 2, mechanical + " mechanical nodes carry " + drawn);
        assertEquals(25.0, ((Number) s.get("coarse_edge_mm")).doubleValue());
    }

    @Test
    void aCoarseEdgeWithoutAMeshOrNotPositiveIsRefusedNamingTheValue() {
        String[] r = run("diaphragm", "--coarse-edge", "8", "--out", "unused");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--coarse-edge 8.0: expected a positive edge length in mm with --mesh"), r[2]);
        r = run("diaphragm", "--mesh", "x.obj", "--coarse-edge", "-3", "--out", "unused");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--coarse-edge -3.0"), r[2]);
    }
}
