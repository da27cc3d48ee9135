package org.tensim.experiment;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.scene.file.CubeSceneFile;
import org.tensim.scene.file.Scene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The cube experiment's scene file, with any parameters set over it, builds the cubes {@link CubeScene} builds:
 * the same nodes, springs, links, fixed nodes and point P, and the same trajectory of P to the bit.
 */
class CubeSceneFileTest {
    static final CubeParameters OTHER = new CubeParameters(8, 2, 150, 1.5, 300, 0.4, 10, 2e-3, 1);

    @Test
    void theSceneFileBuildsTheCubeScenesCubes() {
        for (CubeParameters p : new CubeParameters[] {CubeParameters.paper(), OTHER}) {
            Scene s = CubeSceneFile.load(p);
            for (boolean rigid : new boolean[] {false, true}) {
                CubeScene c = CubeScene.build(p, rigid);
                String name = rigid ? CubeSceneFile.TENSEGRITY : CubeSceneFile.MASS_SPRING;
                Topology t = s.bodies().get(name).topology();
                assertSameStructure(c.topology, t);
                assertEquals(c.probe.id(), CubeSceneFile.probe(s, name));
                double[] a = trajectory(c.topology, c.probe.id(), p);
                double[] b = trajectory(t, CubeSceneFile.probe(s, name), p);
                assertArrayEquals(a, b, 0, "P's trajectory, " + name + ", " + p);
            }
        }
    }

    static void assertSameStructure(Topology a, Topology b) {
        assertEquals(a.nodeCount(), b.nodeCount());
        for (int i = 0; i < a.nodeCount(); i++) {
            Node x = a.node(i);
            Node y = b.node(i);
            assertEquals(x.position(), y.position());
            assertEquals(x.mass(), y.mass(), 0);
            assertEquals(x.isFixed(), y.isFixed(), "node " + i + " fixed");
        }
        assertEquals(a.springs().size(), b.springs().size());
        for (int i = 0; i < a.springs().size(); i++) {
            Spring x = a.springs().get(i);
            Spring y = b.springs().get(i);
            assertEquals(x, y, "spring " + i);
        }
        assertEquals(a.rigidLinks().size(), b.rigidLinks().size());
        assertEquals(a.forces().size(), b.forces().size());
        for (int i = 0; i < a.forces().size(); i++) {
            assertEquals(a.forces().get(i).node(), b.forces().get(i).node());
        }
    }

    /** P's displacement after each of 300 steps of the paper's RK2, flattened. */
    static double[] trajectory(Topology t, int probe, CubeParameters p) {
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create("rk2"));
        double[] out = new double[900];
        double[] d = new double[3];
        for (int i = 0; i < 300; i++) {
            sim.step(p.dtS());
            sim.state().displacement(probe, d);
            System.arraycopy(d, 0, out, 3 * i, 3);
        }
        return out;
    }

    /** The jar's copy of the file (for machines without the checkout) is the file, and loads to the same cubes. */
    @Test
    void theBuildsCopyIsTheFile() throws Exception {
        assertArrayEquals(java.nio.file.Files.readAllBytes(CubeSceneFile.FILE), CubeSceneFile.builtIn());
        Scene copy = org.tensim.scene.file.SceneLoader.load("cube.yaml", CubeSceneFile.builtIn(),
                java.nio.file.Path.of("."), CubeSceneFile.overrides(OTHER));
        Scene file = CubeSceneFile.load(OTHER);
        for (String body : java.util.List.of(CubeSceneFile.MASS_SPRING, CubeSceneFile.TENSEGRITY)) {
            assertSameStructure(file.bodies().get(body).topology(), copy.bodies().get(body).topology());
        }
    }
}
