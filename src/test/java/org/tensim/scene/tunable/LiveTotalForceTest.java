package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.solver.SystemState;

/**
 * A force's {@code total} as a live parameter: the running simulation's loaded nodes take the new total's equal
 * shares at once (the paper cube's top face, 6 nodes: 30 N is 5 N a node, 60 N is 10 N), their positions kept.
 */
class LiveTotalForceTest {
    @TempDir
    Path dir;

    private static double nodeForceY(SystemState s, int i) {
        double[] f = new double[3];
        s.forceLaw[i].addTo(0, f, 0);
        return f[1];
    }

    @Test
    void aLiveTotalIsSharedAnewOverTheRegionsNodes() throws IOException {
        Path file = Files.writeString(dir.resolve("c.yaml"), "version: 1\n"
                + "bodies:\n  c: {type: cube, element: mass-spring}\n"
                + "regions:\n  bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}\n"
                + "  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}\n"
                + "conditions:\n  - {type: fixed, region: bottom}\n"
                + "  - {type: force, region: top, direction: [0, -1, 0], total: 30 N}\n"
                + "run: {dt: 1 ms, duration: 1 s}\n"
                + "parameters:\n  total: {path: \"conditions[1].total\", unit: N, range: [0, 100], apply: live}\n");
        ViewScene v = FileViewScene.factory(file).create(true);
        SystemState s = v.bodies().get(0).simulation().state();
        assertEquals(6, s.forceNode.length, "the top face's nodes");
        for (int i = 0; i < s.forceNode.length; i++) {
            assertEquals(-5, nodeForceY(s, i), 1e-12, "30 N over 6 nodes");
        }
        v.bodies().get(0).simulation().step(1e-3);
        double[] x = s.x.clone();
        v.apply("total", 60);
        assertEquals(60, ((FileViewScene) v).value("total"));
        for (int i = 0; i < s.forceNode.length; i++) {
            assertEquals(-10, nodeForceY(s, i), 1e-12, "60 N over 6 nodes");
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(x, s.x, 0, "positions kept");
    }
}
