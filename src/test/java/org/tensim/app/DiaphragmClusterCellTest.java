package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.Json;
import org.tensim.testsupport.Commands;

/** {@code diaphragm --cluster-cell}: the mesh given, simplified by vertex clustering, run as the scene itself. */
class DiaphragmClusterCellTest {
    @TempDir
    Path dir;

    @Test
    void theClusteredMeshIsTheSceneAndIsMeasuredItself() throws Exception {
        Path mesh = dir.resolve("dome-14.obj");
        assertEquals("0", Commands.run("diaphragm-mesh", "--rings", "14", "--out", mesh.toString())[0]);
        Path full = dir.resolve("full");
        Path clustered = dir.resolve("clustered");
        String[] common = {"--mesh", mesh.toString(), "--integrator", "bdf2", "--dt", "0.025", "--seconds", "0.1",
            "--vtk-per-cycle", "0"};
        assertEquals("0", Commands.run(concat(new String[] {"diaphragm"}, common, "--out", full.toString()))[0]);
        String[] r = Commands.run(concat(new String[] {"diaphragm"}, common, "--cluster-cell", "20", "--out",
                clustered.toString()));
        assertEquals("0", r[0], r[2]);
        Map<String, Object> f = Json.readMap(full.resolve("summary.json"));
        Map<String, Object> c = Json.readMap(clustered.resolve("summary.json"));
        int fullNodes = ((Number) f.get("diaphragm_nodes")).intValue();
        int clusteredNodes = ((Number) c.get("diaphragm_nodes")).intValue();
        assertTrue(clusteredNodes < fullNodes / 2, clusteredNodes + " clustered nodes against " + fullNodes);
        assertEquals(20.0, ((Number) c.get("cluster_cell_mm")).doubleValue());
        assertTrue(!c.containsKey("drawn_nodes"), "no mapping back to the mesh given");
        assertTrue(String.valueOf(c.get("source")).contains("clustered in 20.0 mm cubes"),
                "source: " + c.get("source"));
    }

    @Test
    void aClusterCellWithoutAMeshWithACoarseEdgeOrNotPositiveIsRefused() {
        String[] r = Commands.run("diaphragm", "--cluster-cell", "8", "--out", "unused");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--cluster-cell 8.0: expected a positive cube size in mm with --mesh"), r[2]);
        r = Commands.run("diaphragm", "--mesh", "x.obj", "--cluster-cell", "8", "--coarse-edge", "8", "--out",
                "unused");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("without --coarse-edge"), r[2]);
        r = Commands.run("diaphragm", "--mesh", "x.obj", "--cluster-cell", "0", "--out", "unused");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--cluster-cell 0.0"), r[2]);
    }

    private static String[] concat(String[] a, String[] b, String... c) {
        String[] r = new String[a.length + b.length + c.length];
        System.arraycopy(a, 0, r, 0, a.length);
        System.arraycopy(b, 0, r, a.length, b.length);
        System.arraycopy(c, 0, r, a.length + b.length, c.length);
        return r;
    }
}
