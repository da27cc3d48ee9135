package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.solver.Simulation;
import org.tensim.solver.SurfaceSliding;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * Deformable bodies coupled in a scene file share one state: the merge keeps an uncoupled body as it is, offsets
 * the coupled ones' nodes, probes and regions, and the block of docs/examples/block-on-slab.yaml, at rest, is held by
 * the contact with exactly its weight, the slab taking the opposite.
 */
class CoupledBodiesTest {
    private static final Path EXAMPLE = Path.of("docs/examples/block-on-slab.yaml");

    @TempDir
    Path dir;

    @Test
    void aSceneWithoutCouplingsIsRunAsItIs() {
        Scene s = SceneLoader.load(Path.of("docs/examples/plate.yaml"), List.of());
        assertSame(s, CoupledBodies.merge(s));
    }

    @Test
    void theCoupledBodiesAreMergedWithOffsetsAndAnUncoupledOneIsKept() throws IOException {
        String text = Files.readString(EXAMPLE).replace("../../meshes/", Path.of("meshes").toAbsolutePath() + "/")
                .replace("bodies:\n", "bodies:\n  other: {type: cube, side: 10 mm, node_mass: 1 g}\n");
        Path file = dir.resolve("three.yaml");
        Files.writeString(file, text);
        Scene loaded = SceneLoader.load(file, List.of());
        Scene merged = CoupledBodies.merge(loaded);
        assertEquals(List.of("other", "slab+block"), List.copyOf(merged.bodies().keySet()));
        assertSame(loaded.bodies().get("other"), merged.bodies().get("other"), "the uncoupled body is untouched");
        SceneBody both = merged.bodies().get("slab+block");
        int slab = loaded.bodies().get("slab").topology().nodeCount();
        assertEquals(slab + loaded.bodies().get("block").topology().nodeCount(), both.topology().nodeCount());
        SceneProbe before = loaded.probes().stream().filter(p -> p.name().equals("bottom")).findFirst().orElseThrow();
        SceneProbe after = merged.probes().stream().filter(p -> p.name().equals("bottom")).findFirst().orElseThrow();
        assertEquals("slab+block", after.body());
        for (int i = 0; i < before.nodes().length; i++) {
            assertEquals(before.nodes()[i] + slab, after.nodes()[i]);
            assertEquals(loaded.bodies().get("block").topology().node(before.nodes()[i]).position(),
                    both.topology().node(after.nodes()[i]).position());
        }
        assertEquals(merged.regions().get("bottom").in("slab+block").stream().boxed().toList(),
                java.util.Arrays.stream(after.nodes()).boxed().toList());
        // Gravity on the block only: the merged state has none, the block's nodes carry m g as nodal forces.
        assertEquals(0, both.topology().gravity().norm(), 0);
        assertEquals(loaded.bodies().get("block").topology().nodeCount(), both.topology().forces().size());
    }

    @Test
    void theBlockAtRestIsHeldByItsWeightAndTheSlabTakesTheOpposite() {
        Scene s = CoupledBodies.merge(SceneLoader.load(EXAMPLE, List.of()));
        SceneBody b = s.bodies().get("slab+block");
        Simulation sim = new Simulation(SystemState.compile(b.topology()), Integrators.create("rk2"));
        CoupledBodies.addTerms(b, sim);
        assertEquals(1, sim.forces().terms().size());
        SurfaceSliding term = (SurfaceSliding) sim.forces().terms().get(0);
        assertEquals(9, term.pairCount(), "the block's 9 bottom nodes");
        sim.runUntil(0.3, 2e-4);
        double[] x = sim.state().x;
        double[] f = new double[x.length];
        term.addForces(sim.time(), x, sim.state().v, f);
        int slab = 243;
        double[] onSlab = new double[3];
        double[] onBlock = new double[3];
        double mass = 0;
        for (int j = 0; j < sim.state().nodeCount; j++) {
            for (int a = 0; a < 3; a++) {
                (j < slab ? onSlab : onBlock)[a] += f[3 * j + a];
            }
            mass += j < slab ? 0 : sim.state().mass[j];
        }
        double mg = mass * 9.81;
        assertEquals(0.001, mass, 1e-12, "the block's 1 cm^3 of 1000 kg/m^3");
        for (int a = 0; a < 3; a++) {
            assertEquals(-onBlock[a], onSlab[a], 1e-15, "the slab takes the opposite of the block's force");
        }
        assertEquals(mg, onBlock[1], 1e-4 * mg, "the contact holds the block's weight");
        // Frictionless, the block still sways slowly in the dish the slab sags into (no global damping): a lateral
        // force of a few thousandths of its weight at 0.3 s.
        assertEquals(0, onBlock[0], 1e-2 * mg);
        assertEquals(0, onBlock[2], 1e-2 * mg);
        double[] d = new double[9];
        term.distancesM(x, d);
        double mean = java.util.Arrays.stream(d).average().orElseThrow();
        assertEquals(-mg / (9 * 20), mean, 1e-3 * mg / (9 * 20), "mean penetration m g / (9 k)");
    }

    @Test
    void withABodyOfNoSurfaceOrOnItselfIsRefusedAtTheKey() throws IOException {
        String text = Files.readString(EXAMPLE).replace("../../meshes/", Path.of("meshes").toAbsolutePath() + "/");
        Path file = dir.resolve("self.yaml");
        Files.writeString(file, text.replace("region: bottom, with: slab", "region: under, with: slab"));
        String m = assertThrows(SceneException.class, () -> SceneLoader.load(file, List.of())).getMessage();
        assertTrue(m.contains("self.yaml:") && m.contains("conditions[2].region") && m.contains("has nodes on body"
                + " 'slab' itself"), m);
        Files.writeString(file, text.replace("stiffness: 20 N/m}", "stiffness: 20 N/m, hard: true}"));
        m = assertThrows(SceneException.class, () -> SceneLoader.load(file, List.of())).getMessage();
        assertTrue(m.contains("conditions[2].hard") && m.contains("leave it out"), m);
    }
}
