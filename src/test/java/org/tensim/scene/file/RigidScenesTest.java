package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * Rigid bodies and the conditions that tie a volume to them, as physics: a block resting on a plane under gravity
 * (contact: the penalty carries the weight), a face attached to a moving plate (it follows it exactly), a pressure
 * (its resultant is p times the projected area, zero on a closed surface).
 */
class RigidScenesTest {
    @TempDir
    Path dir;

    /** A 15 mm block of 3 cells, its base on the plane y = 0, under gravity; {@code contact} is the condition. */
    private Scene blockOnPlane(String contact, String integrator) {
        return SceneFiles.load(dir, "rest.yaml", """
                version: 1
                units: {length: mm}
                bodies:
                  block:
                    type: volume
                    box: [15, 15, 15]
                    cell: 5
                    material: {E: 2 kPa, nu: 0.25, density: 1000 kg/m^3, damping_time: 20 ms}
                  floor: {type: rigid, plane: {point: [0, 0, 0], normal: [0, 1, 0]}}
                regions:
                  base: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}
                conditions:
                  - {type: gravity, acceleration: [0, -9.81, 0]}
                  - %s
                run: {integrator: %s, dt: 0.01 s, duration: 2 s}
                """.formatted(contact, integrator));
    }

    private static Simulation run(Scene s, SceneBody b) {
        Simulation sim = new Simulation(SystemState.compile(b.topology()), Integrators.create(s.run().integrator()));
        for (long i = 0; i < s.run().steps(); i++) {
            sim.step(s.run().dtS());
        }
        return sim;
    }

    @Test
    void aBlockOnAPlaneRestsOnThePenaltyWithPenetrationOfItsLoadOverTheStiffness() {
        double k = 20;
        Scene s = blockOnPlane("{type: contact, region: base, with: floor, stiffness: " + k + " N/m}",
                "implicit-euler");
        SceneBody b = s.bodies().get("block");
        BitSet base = s.regions().get("base").in("block");
        assertEquals(16, base.cardinality());
        assertEquals(16, b.topology().contacts().size(), "one pair a base node");
        SystemState st = run(s, b).state();
        double weight = b.topology().totalMass() * 9.81;
        double carried = 0;
        double deepest = 0;
        for (int n = base.nextSetBit(0); n >= 0; n = base.nextSetBit(n + 1)) {
            double p = Math.max(0, -st.position(n, 1));
            carried += k * p;
            deepest = Math.max(deepest, p);
        }
        double lowest = Double.POSITIVE_INFINITY;
        for (int n = 0; n < st.nodeCount; n++) {
            lowest = Math.min(lowest, st.position(n, 1));
        }
        System.out.printf("block on a plane: weight %.6g N, carried by the penalty %.6g N, deepest %.4g mm,"
                + " load / k %.4g mm%n", weight, carried, deepest * 1e3, weight / k * 1e3);
        // At rest the penalty springs carry the weight (the block's damping has taken its bounce), so the
        // penetrations are the nodes' loads over k: none deeper than the whole load over k, their sum k * p the
        // weight, and no node below the base's.
        assertEquals(weight, carried, 0.01 * weight, "the penalty carries the weight");
        assertTrue(deepest <= weight / k, "penetration " + deepest + " m within load / k " + weight / k + " m");
        assertTrue(deepest > 0.5 * weight / k / base.cardinality(), "the penalty gives: " + deepest);
        assertEquals(-deepest, lowest, 1e-12, "the base is the lowest");
    }

    @Test
    void aFloorReadFromAnObjFileCarriesTheBlockAsTheExactPlaneDoes() throws java.io.IOException {
        // The floor as a closed box surface in an OBJ file, in mm: its top face is the plane y = 0. Its distance is
        // sampled on a 1 mm grid (the bones' DistanceGrid), linear across the flat face, so the block rests as on
        // the exact plane.
        org.tensim.io.mesh.TriangleMesh floor = org.tensim.scene.rigid.RigidMeshes.box(
                new double[] {-0.02, -0.01, -0.02}, new double[] {0.035, 0, 0.035});
        org.tensim.io.mesh.ObjWriter.write(dir.resolve("floor.obj"), floor, org.tensim.io.mesh.MeshUnits.MM,
                java.util.List.of("a floor"), 6);
        double k = 20;
        String contact = "{type: contact, region: base, with: floor, stiffness: " + k + " N/m}";
        Scene plane = blockOnPlane(contact, "implicit-euler");
        // The same file (written by blockOnPlane as rest.yaml) with the floor read from the OBJ file.
        Scene mesh = SceneFiles.load(dir, "mesh.yaml", java.nio.file.Files.readString(dir.resolve("rest.yaml"))
                        .replace("floor: {type: rigid, plane: {point: [0, 0, 0], normal: [0, 1, 0]}}",
                                "floor: {type: rigid, mesh: {file: floor.obj, units: mm}, cell: 1}"));
        assertEquals("mesh", mesh.rigids().get("floor").shape());
        double deepPlane = deepest(run(plane, plane.bodies().get("block")).state());
        double deepMesh = deepest(run(mesh, mesh.bodies().get("block")).state());
        System.out.printf("block on a floor from an OBJ file: deepest %.6g mm (exact plane %.6g mm)%n",
                deepMesh * 1e3, deepPlane * 1e3);
        assertEquals(deepPlane, deepMesh, 1e-3 * deepPlane, "the grid is exact across a flat face");
    }

    private static double deepest(SystemState st) {
        double lowest = 0;
        for (int n = 0; n < st.nodeCount; n++) {
            lowest = Math.min(lowest, st.position(n, 1));
        }
        return -lowest;
    }

    @Test
    void aHardContactKeepsTheBlockOnThePlaneToRoundOff() {
        // The contact integrator (BDF2 with the contacts in its Newton matrix): implicit Euler followed by the
        // projection lets this block fold through its own base within a second (docs/scenes.md).
        Scene s = blockOnPlane("{type: contact, region: base, with: floor, stiffness: 20 N/m, hard: true}",
                "bdf2-contact");
        SceneBody b = s.bodies().get("block");
        SystemState st = run(s, b).state();
        double lowest = Double.POSITIVE_INFINITY;
        for (int n = 0; n < st.nodeCount; n++) {
            lowest = Math.min(lowest, st.position(n, 1));
        }
        System.out.printf("block on a hard plane: lowest node at %.3g m%n", lowest);
        assertTrue(lowest >= -1e-12, "hard contact: the base projected back on the plane, lowest " + lowest);
        assertTrue(lowest <= 1e-9, "and resting on it, not above: " + lowest);
    }

    @Test
    void anAttachedFaceFollowsATranslatingAndRotatingPlateExactly() {
        Scene s = SceneFiles.load(dir, "attach.yaml", """
                version: 1
                units: {length: mm}
                bodies:
                  block: {type: volume, box: [10, 10, 10], cell: 5, material: {E: 1 kPa}}
                  plate:
                    type: rigid
                    box: {min: [-5, 10, -5], max: [15, 12, 15]}
                    motion: {type: rotation, axis: [0, 0, 1], centre: [5, 11, 5], angle: 0.2 rad, law: go}
                  slide:
                    type: rigid
                    box: {min: [-5, -2, -5], max: [15, 0, 15]}
                    motion: {type: translation, displacement: [3, -1, 2], law: go}
                laws:
                  go: {type: ramp, start: 0 s, duration: 0.5 s, from: 0, to: 1}
                regions:
                  all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}
                conditions:
                  - {type: attachment, region: all, with: plate, threshold: 0.1}
                  - {type: attachment, region: all, with: slide, threshold: 0.1}
                run: {integrator: symplectic-euler, dt: 1 ms, duration: 0.6 s}
                """);
        SceneBody b = s.bodies().get("block");
        Topology t = b.topology();
        long driven = t.nodes().stream().filter(Node::isDriven).count();
        assertEquals(18, driven, "the top and bottom faces (9 nodes each) are within 0.1 mm of the plates");
        SystemState st = run(s, b).state();
        double c = Math.cos(0.2);
        double sn = Math.sin(0.2);
        double worst = 0;
        for (Node n : t.nodes()) {
            double x = n.position().x();
            double y = n.position().y();
            double z = n.position().z();
            double[] want;
            if (y > 0.009) {
                // Rotated by 0.2 rad about z through (5, 11, 5) mm.
                double rx = x - 0.005;
                double ry = y - 0.011;
                want = new double[] {0.005 + c * rx - sn * ry, 0.011 + sn * rx + c * ry, z};
            } else if (y < 0.001) {
                want = new double[] {x + 0.003, y - 0.001, z + 0.002};
            } else {
                assertTrue(!n.isDriven(), "a middle node is free");
                continue;
            }
            for (int a = 0; a < 3; a++) {
                worst = Math.max(worst, Math.abs(st.position(n.id(), a) - want[a]));
            }
        }
        System.out.printf("attachment: largest distance from the plates' motion %.3g m%n", worst);
        assertTrue(worst < 1e-15, "attached nodes move with their plate exactly: " + worst);
    }

    /** A 20 x 10 x 30 mm block under a pressure on {@code region} (a region of the file below). */
    private Scene pressed(String region) {
        return SceneFiles.load(dir, "press.yaml", """
                version: 1
                units: {length: mm}
                bodies:
                  block: {type: volume, box: [20, 10, 30], cell: 5, material: {E: 1 kPa}}
                regions:
                  skin: {surface: block}
                  top_box: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}
                  top: {intersection: [skin, top_box]}
                  slant: {plane: {point: [0, 1, 0], normal: [0, 1, 1], frame: relative}}
                  cut: {intersection: [skin, slant]}
                conditions:
                  - {type: pressure, region: %s, pressure: 250 Pa}
                run: {dt: 1 ms, duration: 0.01 s}
                """.formatted(region));
    }

    private static double[] resultant(Topology t) {
        double[] f = new double[3];
        for (Topology.NodalForce nf : t.forces()) {
            nf.law().addTo(0.3, f, 0);
        }
        return f;
    }

    @Test
    void aPressureOnAFaceIsPTimesItsProjectedAreaAndOnAClosedSurfaceZero() {
        double p = 250;
        double[] top = resultant(pressed("top").bodies().get("block").topology());
        double area = 0.020 * 0.030;
        System.out.printf("pressure on the top face: resultant (%.6g, %.6g, %.6g) N, -p A = %.6g N%n", top[0], top[1],
                top[2], -p * area);
        assertEquals(-p * area, top[1], 1e-12 * p * area, "p A into the body along -y");
        assertEquals(0, top[0], 1e-12 * p * area);
        assertEquals(0, top[2], 1e-12 * p * area);
        double[] closed = resultant(pressed("skin").bodies().get("block").topology());
        for (int a = 0; a < 3; a++) {
            assertEquals(0, closed[a], 1e-12 * p * area, "a closed surface under uniform pressure: no net force");
        }
        // A part of the surface across two faces (the top and the front, z = 30 mm, as far as y + z >= 40 mm):
        // the resultant is p times its faces' area projected on each axis, whatever their shape.
        Scene s = pressed("cut");
        SceneBody b = s.bodies().get("block");
        BitSet faces = SurfaceFaces.faces(b.surface(), s.regions().get("cut").in("block"));
        double[] projected = SurfaceFaces.vectorArea(b.surface(), faces);
        double[] cut = resultant(b.topology());
        assertTrue(projected[1] > 0 && projected[2] > 0, "the part faces up and forward");
        for (int a = 0; a < 3; a++) {
            assertEquals(-p * projected[a], cut[a], 1e-12 * p * area, "axis " + a);
        }
    }

    @Test
    void theBreathingLawIsTheDiaphragmsCycle() {
        Scene s = SceneFiles.load(dir, "breath.yaml", """
                version: 1
                bodies:
                  c: {type: cube}
                laws:
                  quiet: {type: breathing}
                  deep: {type: breathing, period: 5 s, inspiration: 0.4, amplitude: 2}
                  plain: {type: breathing, pause: 0}
                run: {dt: 1 ms, duration: 0.01 s}
                """);
        org.tensim.scene.diaphragm.BreathingCycle quiet = org.tensim.scene.diaphragm.BreathingCycle.quiet();
        // A file's breathing law ends its expiration in the quiet law's pause unless it says otherwise.
        org.tensim.scene.diaphragm.BreathingCycle deep = new org.tensim.scene.diaphragm.BreathingCycle(5, 1.5,
                org.tensim.scene.diaphragm.BreathingCycle.QUIET_PAUSE_SHARE);
        org.tensim.scene.diaphragm.BreathingCycle plain = new org.tensim.scene.diaphragm.BreathingCycle(4, 2);
        for (int i = 0; i <= 200; i++) {
            double t = i * 0.0731;
            assertEquals(quiet.level(t), s.laws().get("quiet").value(t), 1e-15, "t = " + t);
            assertEquals(2 * deep.level(t), s.laws().get("deep").value(t), 1e-15, "t = " + t);
            assertEquals(plain.level(t), s.laws().get("plain").value(t), 1e-15, "t = " + t);
        }
        assertEquals(2, s.laws().get("deep").value(2), 1e-12, "end-inspiration at 0.4 T");
        SceneException e = org.junit.jupiter.api.Assertions.assertThrows(SceneException.class, () -> SceneFiles.load(
                dir, "pause.yaml", """
                version: 1
                bodies:
                  c: {type: cube}
                laws:
                  held: {type: breathing, pause: 1}
                run: {dt: 1 ms, duration: 0.01 s}
                """));
        assertTrue(e.getMessage().contains("pause.yaml:5:34: laws.held.pause") && e.getMessage().contains("end-expiratory pause")
                && e.getMessage().contains("[0, 1)"), e.getMessage());
    }
}
