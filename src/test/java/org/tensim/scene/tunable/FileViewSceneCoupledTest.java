package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.experiment.SceneRunner;
import org.tensim.scene.file.CoupledBodies;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneLoader;
import org.tensim.solver.Simulation;
import org.tensim.solver.SurfaceSliding;
import org.tensim.testsupport.Commands;

/**
 * The GUI runs a file whose bodies touch each other as {@code tensim run} does: one simulation holding the slab and
 * the block with the contact's term, each body's surface (the block's here) carried from its own nodes in it; after the same steps every
 * probe reads what the headless run's CSV holds, to the bit. A live change reaches the shared state, a rebuild makes
 * the whole coupled scene anew.
 */
class FileViewSceneCoupledTest {
    private static final Path EXAMPLE = Path.of("docs/examples/block-on-slab.yaml");
    private static final double DT = 2e-4; // the file's step
    private static final int STEPS = 500; // 0.1 s: the block has pressed into the slab

    @TempDir
    Path dir;

    @Test
    void theBlockOnTheSlabStepsAsTheHeadlessRunToTheBit() throws IOException {
        String[] r = Commands.run("run", EXAMPLE.toString(), "--set", "run.duration=0.1 s", "--set",
                "run.every=" + STEPS, "--out", dir.toString());
        assertEquals("0", r[0], r[2]);
        List<String> csv = Files.readAllLines(dir.resolve("block-on-slab.csv"));
        assertEquals(3, csv.size(), "the header, t = 0 and t = 0.1 s: " + csv);
        String[] header = csv.get(0).split(",");
        String[] last = csv.get(2).split(",");

        ViewScene gui = FileViewScene.factory(EXAMPLE).create(true);
        List<Body> bodies = gui.bodies();
        assertEquals(List.of("slab+block (coupled)", "slab surface (vertex 0)", "block surface (vertex 0)"),
                bodies.stream().map(Body::name).toList(), "one lattice for both, then each body's surface");
        Simulation both = bodies.get(0).simulation();
        assertEquals(1, both.forces().terms().stream().filter(t -> t instanceof SurfaceSliding).count(),
                "the contact's term");
        for (int i = 0; i < STEPS; i++) {
            for (Body b : bodies) { // as the window's runner steps them
                b.simulation().step(DT);
            }
        }
        Scene merged = CoupledBodies.merge(SceneLoader.load(EXAMPLE));
        Map<String, Simulation> sims = Map.of("slab+block", both);
        double[] row = new double[header.length];
        SceneRunner.sample(merged, sims, SceneRunner.energySprings(merged, sims), both.time(), row);
        for (int c = 0; c < header.length; c++) {
            assertEquals(Double.parseDouble(last[c]), row[c], 0, header[c]);
        }
        int dy = List.of(header).indexOf("bottom_mean_dy_m");
        int pen = List.of(header).indexOf("press_penetration_m");
        assertTrue(row[dy] < -1e-5 && row[pen] > 1e-5, "the block moved down into the slab: dy " + row[dy]
                + " m, penetration " + row[pen] + " m");

        // The block's surface is its own mapping applied to its nodes, which follow the slab's in the shared state.
        Scene loaded = SceneLoader.load(EXAMPLE);
        int slab = loaded.bodies().get("slab").topology().nodeCount();
        int block = loaded.bodies().get("block").topology().nodeCount();
        double[] own = java.util.Arrays.copyOfRange(both.state().x, 3 * slab, 3 * (slab + block));
        double[] expected = new double[3 * bodies.get(2).nodeCount()];
        loaded.bodies().get("block").surface().mapping().apply(own, expected);
        double[] shown = bodies.get(2).simulation().state().x;
        for (int k = 0; k < expected.length; k++) {
            assertEquals(expected[k], shown[k], 1e-15, "surface value " + k);
        }
    }

    /** The example with the block's E live and the contact's stiffness a rebuild. */
    private Path tunable() throws IOException {
        String text = Files.readString(EXAMPLE).replace("../../meshes/", Path.of("meshes").toAbsolutePath() + "/")
                .replaceFirst("(?m)^expect:", "parameters:\n"
                        + "  E: {path: bodies.block.material.E, unit: kPa, range: [0.5, 4], apply: live}\n"
                        + "  k: {path: \"conditions[2].stiffness\", unit: N/m, range: [5, 100], apply: rebuild}\n"
                        + "expect:");
        return Files.writeString(dir.resolve("tunable.yaml"), text);
    }

    @Test
    void aLiveChangeReachesTheSharedStateAndARebuildRebuildsBothBodies() throws IOException {
        Path file = tunable();
        SceneFactory f = FileViewScene.factory(file);
        ViewScene s = f.create(true);
        Simulation both = s.bodies().get(0).simulation();
        for (int i = 0; i < 10; i++) {
            s.bodies().forEach(b -> b.simulation().step(DT));
        }
        double[] k0 = both.state().springK.clone();
        s.prepare("E", 2).run();
        double[] fresh = org.tensim.solver.SystemState.compile(CoupledBodies.merge(SceneLoader.load(file,
                List.of("E=2"))).bodies().get("slab+block").topology()).springK;
        int slabSprings = 0;
        for (int i = 0; i < k0.length; i++) {
            assertEquals(fresh[i], both.state().springK[i], 0, "spring " + i);
            slabSprings += fresh[i] == k0[i] ? 1 : 0;
        }
        assertTrue(slabSprings > 0 && slabSprings < k0.length, "the slab's springs kept, the block's doubled");
        assertEquals(10 * DT, both.time(), 1e-15, "not restarted");

        // The rebuild: a new shared state whose contact runs at 40 N/m, stepping as the headless build of k = 40.
        ViewScene rebuilt = f.create(true, Map.of("k", 40.0));
        Simulation again = rebuilt.bodies().get(0).simulation();
        Simulation headless = CoupledBodies.simulations(CoupledBodies.merge(SceneLoader.load(file, List.of("k=40"))),
                "rk2").get("slab+block");
        Simulation before = f.create(true).bodies().get(0).simulation();
        for (int i = 0; i < 200; i++) {
            again.step(DT);
            headless.step(DT);
            before.step(DT);
        }
        for (int k = 0; k < headless.state().x.length; k++) {
            assertEquals(headless.state().x[k], again.state().x[k], 0, "position value " + k);
        }
        assertNotEquals(before.state().x[both.state().x.length - 2], again.state().x[both.state().x.length - 2],
                "the stiffer contact moves the block otherwise");
    }
}
