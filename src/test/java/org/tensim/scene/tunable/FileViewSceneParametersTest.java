package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * A scene file's named parameters in the GUI's scene: one control each (name, unit, range, live or restarting), a
 * live change seen by the running simulation's very next step, a rebuild one making a new scene from the file.
 */
public class FileViewSceneParametersTest {
    static final Path CUBE = Path.of("docs/examples/cube.yaml");
    /** A coarse volume with a stiffer zone: E, the zone's E and gravity live, the cell size a rebuild. */
    public static final String VOLUME = String.join("\n",
            "version: 1",
            "units: {length: mm}",
            "bodies:",
            "  v: {type: volume, box: [40, 10, 10], cell: 5, material: {E: 3 kPa, density: 1000 kg/m^3}}",
            "regions:",
            "  end: {box: {min: [0, 0, 0], max: [0, 1, 1], frame: relative}}",
            "  near: {box: {min: [0, 0, 0], max: [0.3, 1, 1], frame: relative}}",
            "zones:",
            "  stiff: {region: near, model: tensegrity, material: {E: 10 kPa}}",
            "conditions:",
            "  - {type: fixed, region: end}",
            "  - {type: gravity, acceleration: [0, 0, -9.81 m/s^2]}",
            "run: {integrator: implicit-euler, dt: 10 ms, duration: 0.1 s}",
            "parameters:",
            "  E: {path: bodies.v.material.E, unit: kPa, range: [1, 8], apply: live}",
            "  zoneE: {path: zones.stiff.material.E, unit: kPa, range: [9, 50], apply: live}",
            "  g: {path: \"conditions[1].acceleration[2]\", unit: m/s^2, range: [-20, 0], apply: live}",
            "  cell: {path: bodies.v.cell, unit: mm, range: [4, 10], apply: rebuild}",
            "");

    @TempDir
    Path dir;

    @Test
    void oneControlPerParameterWithItsUnitRangeAndMode() throws IOException {
        ViewScene s = FileViewScene.factory(volume()).create(true);
        List<TunableParameter> ps = s.parameters();
        assertEquals(List.of("E", "zoneE", "g", "cell"), ps.stream().map(TunableParameter::key).toList());
        TunableParameter e = ps.get(0);
        assertEquals("kPa", e.unit());
        assertEquals(1, e.min());
        assertEquals(8, e.max());
        assertEquals(3, e.defaultValue(), 1e-12);
        assertFalse(e.restarts());
        assertTrue(ps.get(3).restarts(), "the cell size rebuilds");
        assertEquals("mm", ps.get(3).unit());
        assertEquals(5, ps.get(3).defaultValue(), 1e-12);
    }

    /**
     * The force is changed live at step 200: the positions and velocities reached are kept, and the very next step
     * sees the new force: on point P (mass 1 kg) the velocity differs from an unchanged run's by dt times the
     * force's change at the step's midpoint (RK2), to the damping's second-order share.
     */
    @Test
    void aLiveForceChangeActsOnTheNextStepFromTheStateReached() {
        SceneFactory f = FileViewScene.factory(CUBE);
        ViewScene changed = f.create(true);
        ViewScene same = f.create(true);
        Simulation a = changed.bodies().get(0).simulation();
        Simulation b = same.bodies().get(0).simulation();
        Simulation ta = changed.bodies().get(1).simulation();
        Simulation tb = same.bodies().get(1).simulation();
        double dt = 1e-3;
        for (int i = 0; i < 200; i++) {
            for (Simulation s : List.of(a, b, ta, tb)) {
                s.step(dt);
            }
        }
        assertArrayEquals(tb.state().x, ta.state().x, 0, "the same run so far");
        double[] x = a.state().x.clone();
        double[] v = a.state().v.clone();
        changed.apply("force", 800);
        assertArrayEquals(x, a.state().x, 0, "positions kept");
        assertArrayEquals(v, a.state().v, 0, "velocities kept");
        assertEquals(800, ((FileViewScene) changed).value("force"));
        double t = a.time();
        for (Simulation s : List.of(a, b, ta, tb)) {
            s.step(dt);
        }
        int node = 13;
        double tm = t + dt / 2;
        // The force on each loaded node: magnitude (400 or 800 N) * sin(2 pi 0.25 Hz t) along the tilted direction.
        double dForceY = -0.9986295347545738 * 400 * Math.sin(2 * Math.PI * 0.25 * tm);
        double dvY = a.state().v[3 * node + 1] - b.state().v[3 * node + 1];
        assertEquals(dt * dForceY, dvY, 0.01 * Math.abs(dt * dForceY), "velocity change of P in one step");
        // The other body (the tensegrity cube) takes the same new force.
        assertNotEquals(tb.state().v[3 * node + 1], ta.state().v[3 * node + 1]);
    }

    @Test
    void liveModuliSetTheRunningSpringsAsAFreshLoadWouldAndKeepTheBuild() throws IOException {
        Path file = volume();
        SceneFactory f = FileViewScene.factory(file);
        ViewScene s = f.create(true);
        Simulation sim = s.bodies().get(0).simulation();
        sim.step(0.01);
        s.apply("E", 6);
        s.apply("zoneE", 30);
        s.apply("g", -3);
        SystemState fresh = SystemState.compile(org.tensim.scene.file.SceneLoader.load(file,
                List.of("E=6", "zoneE=30", "g=-3")).bodies().get("v").topology());
        assertArrayEquals(fresh.springK, sim.state().springK, 0, "every spring as a load at E = 6 kPa, zone 30 kPa");
        assertArrayEquals(fresh.springC, sim.state().springC, 0);
        assertEquals(-3, sim.state().gravity().z(), 0);
        assertTrue(sim.time() > 0, "still the running simulation");
        double before = sim.state().springK[0];
        s.apply("E", 3);
        assertEquals(before / 2, sim.state().springK[0], 1e-12 * before, "spring stiffness proportional to E");
    }

    @Test
    void aRebuildParameterMakesANewSceneFromTheFileAndALiveOneRefusesToRebuild() throws IOException {
        SceneFactory f = FileViewScene.factory(volume());
        ViewScene coarse = f.create(true);
        ViewScene fine = f.create(true, Map.of("cell", 4.0, "E", 5.0));
        int nc = coarse.bodies().get(0).simulation().state().nodeCount;
        int nf = fine.bodies().get(0).simulation().state().nodeCount;
        assertTrue(nf > nc, "a finer lattice: " + nf + " nodes against " + nc);
        assertEquals(5, ((FileViewScene) fine).value("E"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> coarse.apply("cell", 4));
        assertTrue(e.getMessage().contains("applies on rebuild"), e.getMessage());
    }

    @Test
    void aDifferentBuildIsNeverHandedToARunningSimulation() throws IOException {
        SystemState a = FileViewScene.factory(volume()).create(true).bodies().get(0).simulation().state();
        SystemState b = FileViewScene.factory(volume()).create(true, Map.of("cell", 4.0)).bodies().get(0)
                .simulation().state();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> LiveConstants.adopt(a, b, "v"));
        assertTrue(e.getMessage().contains("only a rebuild can do"), e.getMessage());
    }

    private Path volume() throws IOException {
        return Files.writeString(dir.resolve("bar.yaml"), VOLUME);
    }
}
