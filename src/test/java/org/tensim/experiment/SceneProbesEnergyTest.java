package org.tensim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.BitSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Node;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The energy probes read {@code sum 1/2 k (l - l0)^2} over a region's springs and {@code sum 1/2 m v^2} over its
 * free nodes, and the pose probe a rigid body's translation and rotation vector.
 */
class SceneProbesEnergyTest {
    @TempDir
    Path dir;

    private Scene load(String text) throws IOException {
        return SceneLoader.load(Files.writeString(dir.resolve("s.yaml"), text));
    }

    @Test
    void energyProbesAreTheSpringsAndTheNodesSums() throws IOException {
        Scene s = load("""
                version: 1
                units: {length: mm}
                bodies:
                  block: {type: volume, box: [10, 10, 20], cell: 5, material: {E: 1 kPa}}
                regions:
                  base: {box: {min: [0, 0, 0], max: [1, 1, 0], frame: relative}}
                  top: {box: {min: [0, 0, 0.5], max: [1, 1, 1], frame: relative}}
                laws:
                  wave: {type: sine, frequency: 5 Hz}
                conditions:
                  - {type: fixed, region: base}
                  - {type: force, region: top, direction: [1, 0.3, 0], magnitude: 0.02 mN, law: wave}
                probes:
                  all: {body: block, quantity: energy}
                  upper: {region: top, quantity: energy}
                run: {integrator: symplectic-euler, dt: 0.5 ms, duration: 0.1 s}
                """);
        SceneBody b = s.bodies().get("block");
        Topology t = b.topology();
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create("symplectic-euler"));
        for (int i = 0; i < 90; i++) {
            sim.step(0.5e-3);
        }
        SystemState st = sim.state();
        BitSet top = s.regions().get("top").in("block");
        double springsAll = 0;
        double springsTop = 0;
        int inTop = 0;
        for (Spring sp : t.springs()) {
            double l = 0;
            for (int a = 0; a < 3; a++) {
                double d = st.position(sp.b(), a) - st.position(sp.a(), a);
                l += d * d;
            }
            double e = 0.5 * sp.stiffness() * Math.pow(Math.sqrt(l) - sp.restLength(), 2);
            springsAll += e;
            if (top.get(sp.a()) && top.get(sp.b())) {
                springsTop += e;
                inTop++;
            }
        }
        double kineticAll = 0;
        double kineticTop = 0;
        for (Node n : t.nodes()) {
            double v2 = 0;
            for (int a = 0; a < 3; a++) {
                v2 += st.v[3 * n.id() + a] * st.v[3 * n.id() + a];
            }
            double e = n.isFixed() ? 0 : 0.5 * n.mass() * v2;
            kineticAll += e;
            kineticTop += top.get(n.id()) ? e : 0;
        }
        SceneProbe all = s.probes().get(0);
        SceneProbe upper = s.probes().get(1);
        assertEquals(List.of("all_elastic_J", "all_kinetic_J"), all.columns());
        double eAll = SceneRunner.elasticEnergy(st, SceneRunner.springsWithin(st, all.nodes()));
        double eTop = SceneRunner.elasticEnergy(st, SceneRunner.springsWithin(st, upper.nodes()));
        System.out.printf("energy probes: body %.6g J elastic, %.6g J kinetic; region %.6g J, %.6g J (%d springs)%n",
                eAll, SceneRunner.kineticEnergy(st, all.nodes()), eTop, SceneRunner.kineticEnergy(st, upper.nodes()),
                inTop);
        assertTrue(springsAll > 1e-12 && kineticAll > 1e-12, "the load has set the block moving");
        assertTrue(inTop > 0 && inTop < t.springs().size());
        assertEquals(springsAll, eAll, 1e-12 * springsAll);
        assertEquals(sim.forces().springEnergy(st.x), eAll, 1e-12 * springsAll, "the solver's spring energy");
        assertEquals(springsTop, eTop, 1e-12 * springsAll);
        assertEquals(kineticAll, SceneRunner.kineticEnergy(st, all.nodes()), 1e-12 * kineticAll);
        assertEquals(sim.forces().kineticEnergy(), SceneRunner.kineticEnergy(st, all.nodes()), 1e-12 * kineticAll);
        assertEquals(kineticTop, SceneRunner.kineticEnergy(st, upper.nodes()), 1e-12 * kineticAll);
    }

    @Test
    void thePoseProbeIsTheTranslationAndTheRotationVector() throws IOException {
        Scene s = load("""
                version: 1
                units: {length: mm}
                bodies:
                  block: {type: volume, box: [10, 10, 10], cell: 5, material: {E: 1 kPa}}
                  arm:
                    type: rigid
                    sphere: {centre: [0, 50, 0], radius: 5}
                    motion: {type: rotation, axis: [1, 2, 2], centre: [0, 40, 0], angle: 0.6 rad, law: go}
                  rib:
                    type: rigid
                    box: {min: [0, 60, 0], max: [5, 65, 5]}
                    motion: {type: helical, axis: [0, 0, 1], point: [0, 0, 0], angle: 0.1 rad, translation: 2,
                             law: breath}
                laws:
                  go: {type: ramp, start: 0 s, duration: 1 s, from: 0, to: 1}
                  breath: {type: breathing, period: 3 s, inspiration: 0.5, amplitude: 0.5}
                probes:
                  arm: {rigid: arm}
                  rib: {rigid: rib}
                run: {dt: 1 ms, duration: 0.01 s}
                """);
        double[] p = new double[6];
        SceneRunner.pose(s.rigids().get("arm"), 0.5, p, 0);
        // Half the ramp: 0.3 rad about (1, 2, 2) / 3.
        assertEquals(0.1, p[3], 1e-12);
        assertEquals(0.2, p[4], 1e-12);
        assertEquals(0.2, p[5], 1e-12);
        // The axis passes through (0, 40, 0) mm, which stays put: c = p - R p.
        double[] r = new double[9];
        double[] c = new double[3];
        s.rigids().get("arm").motion().pose(0.5, r, 0, c, 0);
        assertEquals(0.040, r[3] * 0 + r[4] * 0.040 + r[5] * 0 + c[1], 1e-15);
        assertEquals(p[1], c[1], 0);
        // The rib at end-inspiration (1.5 s): half the 0.1 rad about z, and half the 2 mm along it.
        SceneRunner.pose(s.rigids().get("rib"), 1.5, p, 0);
        assertEquals(0, p[3], 1e-15);
        assertEquals(0, p[4], 1e-15);
        assertEquals(0.05, p[5], 1e-12);
        assertEquals(0.001, p[2], 1e-15);
        assertEquals(List.of("rib_cx_m", "rib_cy_m", "rib_cz_m", "rib_rx_rad", "rib_ry_rad", "rib_rz_rad"),
                s.probes().get(1).columns());
    }

    @Test
    void theContactProbeReadsTheDeepestPenetrationAndTheWidestSeparation() throws IOException {
        Scene s = load("""
                version: 1
                units: {length: mm}
                bodies:
                  block: {type: volume, box: [10, 10, 10], cell: 5, material: {E: 1 kPa}}
                  floor: {type: rigid, plane: {point: [0, 0, 0], normal: [0, 1, 0]}}
                  wall: {type: rigid, box: {min: [-40, 0, -40], max: [50, 10, 50]}, cavity: true}
                regions:
                  base: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}
                  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}
                conditions:
                  - {type: contact, region: base, with: floor, stiffness: 10 N/m}
                  - {type: sliding, region: top, with: wall, stiffness: 10 N/m}
                probes:
                  base: {body: block, with: floor}
                  top: {body: block, with: wall}
                run: {dt: 1 ms, duration: 0.01 s}
                """);
        SceneBody b = s.bodies().get("block");
        SystemState st = SystemState.compile(b.topology());
        BitSet base = s.regions().get("base").in("block");
        BitSet top = s.regions().get("top").in("block");
        SceneProbe pb = s.probes().get(0);
        SceneProbe pt = s.probes().get(1);
        assertEquals(base.cardinality(), pb.nodes().length, "one pair a base node");
        assertEquals(top.cardinality(), pt.nodes().length, "the sliding's pairs on the wall, not its complement's");
        assertEquals(List.of("base_penetration_m", "base_separation_m"), pb.columns());
        int a = base.nextSetBit(0);
        int c = base.nextSetBit(a + 1);
        st.x[3 * a + 1] = -0.001;
        st.x[3 * c + 1] = 0.002;
        int u = top.nextSetBit(0);
        int w = top.nextSetBit(u + 1);
        st.x[3 * u + 1] = 0.0107;
        st.x[3 * w + 1] = 0.0096;
        double[] out = new double[4];
        SceneRunner.contact(s.rigids().get("floor"), pb, st, 0, out, 0);
        SceneRunner.contact(s.rigids().get("wall"), pt, st, 0, out, 2);
        assertEquals(0.001, out[0], 1e-15, "the base node 1 mm into the floor");
        assertEquals(0.002, out[1], 1e-15, "the base node 2 mm above it");
        assertEquals(0.0007, out[2], 1e-15, "the top node 0.7 mm into the wall's ceiling");
        assertEquals(0.0004, out[3], 1e-15, "the top node 0.4 mm off it");
    }
}
