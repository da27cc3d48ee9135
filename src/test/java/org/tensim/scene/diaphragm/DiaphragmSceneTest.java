package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.RigidLink;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TissueModel;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/** How the diaphragm scene is built: tissues, rigid links, attachments, masses, forces. */
class DiaphragmSceneTest {
    @Test
    void paperModelLinksTheTendonOnly() throws Exception {
        DiaphragmScene s = SceneFixture.coarse(16, 1, 2000, DiaphragmParameters.defaults().withTissueModel(TissueModel.PAPER));
        assertTrue(s.topology().rigidLinks().size() > 20, "some links: " + s.topology().rigidLinks().size());
        for (RigidLink l : s.topology().rigidLinks()) {
            assertTrue(s.isTendon(l.a()) && s.isTendon(l.b()), "link " + l + " outside the tendon");
        }
    }

    @Test
    void rigidLinksAreDisjointStrutsAcrossTheThickness() throws Exception {
        DiaphragmScene s = SceneFixture.coarse(16, 1, 2000);
        Topology t = s.topology();
        int[] uses = new int[t.nodeCount()];
        double th = s.surfaces().thicknessM();
        // Material model: every column is rigid (Kirchhoff-Love), but never between two immovable nodes.
        assertTrue(t.rigidLinks().size() > s.diaphragmNodes() / 3, "links: " + t.rigidLinks().size());
        for (RigidLink l : t.rigidLinks()) {
            boolean aFree = !t.node(l.a()).isDriven() && !t.node(l.a()).isFixed();
            boolean bFree = !t.node(l.b()).isDriven() && !t.node(l.b()).isFixed();
            assertTrue(aFree || bFree, "link " + l + " between two immovable nodes");
            assertTrue(s.surfaces().isUpper(l.a()) != s.surfaces().isUpper(l.b()), "joins upper to lower");
            assertTrue(l.length() >= 0.3 * th && l.length() <= 2.5 * th);
            uses[l.a()]++;
            uses[l.b()]++;
        }
        for (int u : uses) {
            assertTrue(u <= 1, "struts share no node (discontinuous compression)");
        }
        assertEquals(0.12, s.tendonAreaFraction(), 0.02, "tendon 10-15 % of the area");
        // Disjoint links are projected exactly in one sweep.
        Simulation sim = s.newSimulation();
        for (int i = 0; i < 200; i++) {
            sim.step(s.recommendedTimeStep());
        }
        assertTrue(sim.projection().iterations() <= 1, "sweeps: " + sim.projection().iterations());
        assertTrue(sim.projection().maxRelativeError() < 1e-9);
    }

    @Test
    void massIsDensityTimesVolumeAndAttachedNodesAreNotIntegrated() throws Exception {
        // the paper's attachment drives or fixes the attached nodes (the band's ties: BoundaryConditionsTest)
        DiaphragmScene s = SceneFixture.coarse(16, 1, 2000, BoundaryConditions.paper());
        Topology t = s.topology();
        TriangleMesh m = s.surfaces().mesh();
        double mass = 0;
        for (int v = 0; v < s.diaphragmNodes(); v++) {
            mass += t.node(v).mass();
        }
        double expected = DiaphragmParameters.defaults().densityKgPerM3() * m.totalArea() / 2
                * s.surfaces().thicknessM();
        assertEquals(expected + s.addedMassKg(), mass, 1e-9 * expected);
        assertTrue(s.addedMassKg() < 0.01 * expected, "the mass floor adds little: " + s.addedMassKg());
        assertTrue(mass > 0.1 && mass < 0.4, "an adult diaphragm weighs a few hundred grams, got " + mass);
        assertTrue(s.attachedToRibs() > 0 && s.attachedToCartilage() > 0 && s.attachedToSpine() > 0);
        SystemState st = SystemState.compile(t);
        int driven = 0;
        for (int v = 0; v < s.diaphragmNodes(); v++) {
            Node n = t.node(v);
            if (n.isDriven() || n.isFixed()) {
                assertEquals(0, st.invMass[v], 0);
                driven++;
            }
        }
        assertEquals(s.attachedToRibs() + s.attachedToSpine(), driven);
        Node apex = t.node(s.apexNode());
        assertTrue(!apex.isDriven() && !apex.isFixed() && s.surfaces().isUpper(apex.id()));
    }

    @Test
    void muscleForceIsTheAmplitudeTimesTheWeightedAreaAtEndInspiration() throws Exception {
        // the paper's nodal forces (the integrated pressure: BoundaryConditionsTest)
        double pa = 2000;
        DiaphragmScene s = SceneFixture.coarse(12, 1, pa, BoundaryConditions.paper());
        SystemState st = SystemState.compile(s.topology());
        // Only the external laws: no spring or triangle strained at rest, so forces at rest are the muscle's alone.
        ForceModel fm = new ForceModel(st);
        double[] f = new double[3 * st.nodeCount];
        double ti = s.cycle().inspirationS();
        fm.computeForces(ti, st.x, st.v, f);
        double fz = 0;
        double expected = 0;
        double[] area = SurfaceGeometry.vertexAreas(s.surfaces().mesh());
        for (int v = 0; v < s.diaphragmNodes(); v++) {
            fz += f[3 * v + 2];
            Node n = s.topology().node(v);
            if (!s.isTendon(v) && !n.isDriven() && !n.isFixed()) {
                expected += pa * s.actionLines().weight(n.position().x(), n.position().y()) * area[v] / 2;
            }
        }
        assertTrue(expected > 0);
        assertEquals(-expected, fz, 1e-9 * expected, "downwards, P sum(w A / 2)");
        fm.computeForces(0, st.x, st.v, f);
        double atRest = 0;
        for (int v = 0; v < s.diaphragmNodes(); v++) {
            atRest += Math.abs(f[3 * v + 2]);
        }
        // Zero up to the round-off of the membrane triangles' forces at rest.
        assertEquals(0, atRest, 1e-12 * expected, "no force at end-expiration");
        // Live control: halving the amplitude halves the force at the next pass.
        s.controls().setMuscleAmplitudePa(pa / 2);
        fm.computeForces(ti + s.cycle().periodS(), st.x, st.v, f);
        double half = 0;
        for (int v = 0; v < s.diaphragmNodes(); v++) {
            half += f[3 * v + 2];
        }
        assertEquals(fz / 2, half, 1e-9 * expected);
    }

    @Test
    void membraneSpringsFollowVanGelderAndTheStepIsStableForTheStiffestMode() throws Exception {
        DiaphragmScene s = SceneFixture.coarse(12, 1, 2000);
        DiaphragmParameters p = DiaphragmParameters.defaults();
        double kMax = 0;
        for (Spring sp : s.topology().springs()) {
            kMax = Math.max(kMax, sp.stiffness());
            assertTrue(sp.damping() > 0, "every spring is damped (RK2 needs it)");
        }
        // Equilateral estimate: a node of about 6 membrane springs of sqrt(3)/4 E h each.
        assertTrue(kMax > Math.sqrt(3) / 4 * p.muscleYoungPa() * s.surfaces().thicknessM() / 2);
        double h = s.recommendedTimeStep();
        assertTrue(h * s.omegaMaxBound() > 0.5 && h * s.omegaMaxBound() < 2.5, "w h = " + h * s.omegaMaxBound());
    }

    /** The scene's runs are stopped as diverged when a node goes 0.15 m from rest (DivergenceTest: how). */
    @Test
    void theScenesSimulationsBoundTheMotion() throws Exception {
        assertEquals(DiaphragmScene.MAX_DISPLACEMENT_M, SceneFixture.coarse(16, 1, 2000).newSimulation()
                .displacementLimit());
    }
}
