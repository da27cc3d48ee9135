package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.Integrators;

/**
 * The abdominal pressure's rise on the lower face ({@link AbdominalPressure}): on a flat shell the forces sum to
 * the pressure times the loaded area, across the thickness towards the upper face, following the breathing level;
 * on the double dome it holds the dome up, as a pressure under it must.
 */
class AbdominalPressureTest {
    private static double[] total(Topology t, double time) {
        double[] f = new double[3 * t.nodeCount()];
        for (Topology.NodalForce nf : t.forces()) {
            nf.law().addTo(time, f, 3 * nf.node());
        }
        double[] sum = new double[3];
        for (int v = 0; v < t.nodeCount(); v++) {
            for (int c = 0; c < 3; c++) {
                sum[c] += f[3 * v + c];
            }
        }
        return sum;
    }

    /** A topology of the mesh's vertices, 1 g each, no springs. */
    private static Topology nodesOf(TriangleMesh m) {
        Topology t = new Topology();
        for (int v = 0; v < m.vertexCount(); v++) {
            t.addNode(m.coord(v, 0), m.coord(v, 1), m.coord(v, 2), 1e-3);
        }
        return t;
    }

    @Test
    void theForcesSumToThePressureTimesTheFreeLowerAreaUpwardsAndFollowTheBreath() {
        double halfSide = 0.04;
        // A flat 8 x 8 square at z = 0, offset 3 mm down into a shell.
        TwoSurfaces s = TwoSurfaces.offset(FlatMeshes.square(halfSide, 8), 0.003);
        TriangleMesh m = s.mesh();
        Topology t = nodesOf(m);
        int fixedLower = -1;
        for (int v = 0; v < m.vertexCount() && fixedLower < 0; v++) {
            if (!s.isUpper(v)) {
                fixedLower = v;
            }
        }
        t.node(fixedLower).fix();
        double[] area = SurfaceGeometry.vertexAreas(m);
        BreathingCycle cycle = BreathingCycle.quiet();
        double p = 300;
        double loaded = AbdominalPressure.add(t, s, area, cycle, p, null);
        double lowerArea = 4 * halfSide * halfSide;
        assertEquals(lowerArea - area[fixedLower], loaded, 1e-12, "every lower node but the fixed one, no upper node");
        double expected = p * (lowerArea - area[fixedLower]);
        double[] atPeak = total(t, cycle.inspirationS());
        assertEquals(expected, atPeak[2], 1e-9 * expected, "towards the upper face, the pressure times the area");
        assertEquals(0, atPeak[0], 1e-9 * expected);
        assertEquals(0, atPeak[1], 1e-9 * expected);
        assertEquals(0, total(t, 0)[2], 1e-12, "none at end-expiration");
        double half = cycle.inspirationS() / 2;
        assertEquals(expected * cycle.level(half), total(t, half)[2], 1e-9 * expected, "it follows the level");
    }

    @Test
    void onAZoneItPressesTheZonesLowerNodesOnly() {
        // The same flat shell; the zone is the lower face's half with x > 0 (and the upper nodes, which never count).
        TwoSurfaces s = TwoSurfaces.offset(FlatMeshes.square(0.04, 8), 0.003);
        TriangleMesh m = s.mesh();
        Topology t = nodesOf(m);
        boolean[] zone = new boolean[m.vertexCount()];
        double[] area = SurfaceGeometry.vertexAreas(m);
        double inZone = 0;
        for (int v = 0; v < m.vertexCount(); v++) {
            zone[v] = m.coord(v, 0) > 1e-9 || s.isUpper(v);
            inZone += zone[v] && !s.isUpper(v) ? area[v] : 0;
        }
        BreathingCycle cycle = BreathingCycle.quiet();
        double loaded = AbdominalPressure.add(t, s, area, cycle, 500, zone);
        assertEquals(inZone, loaded, 1e-15, "the zone's lower area");
        assertTrue(inZone > 0.3 * 0.0064 && inZone < 0.5 * 0.0064, "about a half of the face: " + inZone);
        assertEquals(500 * inZone, total(t, cycle.inspirationS())[2], 1e-9 * 500 * inZone);
        for (Topology.NodalForce nf : t.forces()) {
            assertTrue(zone[nf.node()] && !s.isUpper(nf.node()), "a force on node " + nf.node() + " outside the zone");
        }
    }

    @Test
    void onTheZoneItFollowsTheMusclesLiveAction() {
        TwoSurfaces s = TwoSurfaces.offset(FlatMeshes.square(0.04, 8), 0.003);
        TriangleMesh m = s.mesh();
        Topology t = nodesOf(m);
        double[] area = SurfaceGeometry.vertexAreas(m);
        BreathingCycle cycle = BreathingCycle.quiet();
        DiaphragmControls controls = new DiaphragmControls(1, 19000);
        double loaded = AbdominalPressure.add(t, s, area, cycle, 300, null, controls, 19000);
        double peak = cycle.inspirationS();
        assertEquals(300 * loaded, total(t, peak)[2], 1e-9 * 300 * loaded, "at the reference action, P");
        controls.setMuscleAmplitudePa(9500);
        assertEquals(150 * loaded, total(t, peak)[2], 1e-9 * 300 * loaded, "half the action, half the rise");
        controls.setMuscleAmplitudePa(0);
        assertEquals(0, total(t, peak)[2], 1e-12, "the muscle off: no rise");
    }

    @Test
    void onTheDoubleDomeAPressureUnderItHoldsTheDomeUp() throws Exception {
        double[] descent = new double[2];
        double[] pressures = {0, 1000};
        for (int i = 0; i < 2; i++) {
            DiaphragmSpec spec = DiaphragmSpec.defaults().withMesh(DiaphragmSpec.Mesh.defaults().withRings(10))
                    .withBreathing(DiaphragmSpec.Breathing.defaults().withAbdominalPressure(pressures[i]));
            DiaphragmScene scene = DiaphragmSetup.build(spec).scene();
            Simulation sim = scene.newSimulation();
            sim.setIntegrator(Integrators.create("bdf2"));
            sim.runUntil(spec.breathing().cycle().inspirationS(), 0.02);
            int a = scene.apexNode();
            descent[i] = sim.state().x0[3 * a + 2] - sim.state().x[3 * a + 2];
        }
        assertTrue(descent[0] > 0.005, "the dome descends without the pressure: " + descent[0] + " m");
        assertTrue(descent[1] > 0 && descent[1] < descent[0] - 0.001,
                "1 kPa under it holds it up: " + descent[1] + " m against " + descent[0] + " m");
    }

    @Test
    void aPressureOutsideItsRangeIsRefusedWithItsValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DiaphragmSpec.Breathing.defaults().withAbdominalPressure(-1));
        assertTrue(e.getMessage().contains("-1") && e.getMessage().contains("Pa"), e.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> DiaphragmSpec.Breathing.defaults().withAbdominalPressure(Double.NaN));
    }
}
