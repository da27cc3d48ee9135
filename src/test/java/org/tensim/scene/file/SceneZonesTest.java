package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Topology;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/** A tensegrity zone over a mass-spring cube's element makes the tensegrity cube, to the bit. */
class SceneZonesTest {
    @TempDir
    Path dir;

    static final String CUBE = "version: 1\nbodies: {c: {type: cube, element: mass-spring}}\n"
            + "run: {dt: 1 ms, duration: 1 ms}\nregions:\n"
            + "  bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}\n"
            + "  corners: {indices: [0, 1, 2, 3, 4, 5, 6, 7]}\n"
            + "  all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}\n"
            + "  element: {difference: [all, corners]}\n"
            + "  vertical: {indices: [12, 13, 14, 15]}\n"
            + "conditions: [{type: fixed, region: bottom}]\n";

    @Test
    void aTensegrityZoneOverTheElementIsTheTensegrityCube() {
        Scene s = SceneFiles.load(dir, "z.yaml", CUBE + "zones: {struts: {region: element, model: tensegrity}}\n");
        Topology zoned = s.bodies().get("c").topology();
        Topology ts = CubeScene.tensegrity(CubeParameters.paper()).topology;
        assertEquals(6, zoned.rigidLinks().size());
        assertEquals(ts.rigidLinks(), zoned.rigidLinks());
        assertEquals(ts.springs(), zoned.springs());
        // Fixed and loaded alike, the zoned cube and the tensegrity cube move alike to the last bit.
        zoned.applyForce(zoned.node(13), org.tensim.model.ForceLaw.constant(new org.tensim.model.Vec3(0, -400, 0)));
        zoned.applyForce(zoned.node(15), org.tensim.model.ForceLaw.constant(new org.tensim.model.Vec3(0, -400, 0)));
        Topology plain = new Topology();
        CubeScene.addStructure(plain, 10, 1, 100, 2, true, true);
        for (int i = 0; i < plain.nodeCount(); i++) {
            if (Math.abs(plain.node(i).position().y()) < 1e-9) {
                plain.node(i).fix();
            }
        }
        plain.applyForce(plain.node(13), org.tensim.model.ForceLaw.constant(new org.tensim.model.Vec3(0, -400, 0)));
        plain.applyForce(plain.node(15), org.tensim.model.ForceLaw.constant(new org.tensim.model.Vec3(0, -400, 0)));
        Simulation x = new Simulation(SystemState.compile(zoned), Integrators.create("rk2"));
        Simulation y = new Simulation(SystemState.compile(plain), Integrators.create("rk2"));
        double[] dx = new double[3];
        double[] dy = new double[3];
        for (int i = 0; i < 500; i++) {
            x.step(1e-3);
            y.step(1e-3);
            x.state().displacement(13, dx);
            y.state().displacement(13, dy);
            assertArrayEquals(dy, dx, 0, "step " + i);
        }
        assertTrue(dx[1] < 0 && dx[1] > -1, "the rigid struts hold P up: " + dx[1]);
    }

    @Test
    void aPartialZoneMakesItsOwnStrutsRigidAndBadZonesAreRefused() {
        Scene s = SceneFiles.load(dir, "z.yaml", CUBE + "zones: {up: {region: vertical, model: tensegrity}}\n");
        assertEquals(2, s.bodies().get("c").topology().rigidLinks().size(), "the two vertical struts");
        SceneException none = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "z.yaml",
                CUBE + "zones: {up: {region: corners, model: tensegrity}}\n"));
        assertTrue(none.getMessage().contains("both ends of none of the element's struts"), none.getMessage());
        SceneException rigid = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "z.yaml",
                CUBE.replace("element: mass-spring", "element: tensegrity") + "zones: {up: {model: tensegrity}}\n"));
        assertTrue(rigid.getMessage().contains("needs element: mass-spring"), rigid.getMessage());
        SceneException model = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "z.yaml",
                CUBE + "zones: {up: {model: tensegrty}}\n"));
        assertTrue(model.getMessage().contains("z.yaml:11:21: zones.up.model: \"tensegrty\" is not one of tensegrity"),
                model.getMessage());
    }
}
