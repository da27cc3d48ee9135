package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The boundary conditions whose totals do not depend on the mesh: the attachment band (a
 * stiffness per unit area) and the action lines' traction integrated over the muscle's area,
 * against the paper's per-node rules.
 */
class BoundaryConditionsTest {
    private static final BoundaryConditions BAND = BoundaryConditions.defaults();

    /** Scene without abdominal support, so that every spring to an anchor is a band tie. */
    private static DiaphragmScene scene(int rings, BoundaryConditions bc) throws Exception {
        return DiaphragmScene.build(
                TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings))),
                SceneFixture.boxes(), DiaphragmParameters.defaults().withAbdominalSupport(0), BreathingCycle.quiet(),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa(bc.muscleLoad())), null, bc);
    }

    /** Sum of the stiffness of the springs from diaphragm nodes to anchors and to the cage, N/m. */
    private static double bandStiffness(DiaphragmScene s) {
        double sum = 0;
        for (Spring sp : s.topology().springs()) {
            boolean aMesh = sp.a() < s.diaphragmNodes();
            boolean bMesh = sp.b() < s.diaphragmNodes();
            if (aMesh != bMesh) {
                sum += sp.stiffness();
            }
        }
        return sum;
    }

    @Test
    void theBandsTotalStiffnessConvergesWhereThePapersAttachedCountGrows() throws Exception {
        DiaphragmScene coarse = scene(12, BAND);
        DiaphragmScene fine = scene(24, BAND);
        double kc = bandStiffness(coarse);
        double kf = bandStiffness(fine);
        assertTrue(kc > 0 && kf > 0);
        assertEquals(kf, kc, 0.05 * kf, "band stiffness at 12 and 24 rings, N/m");
        // the paper's threshold attaches about four times as many nodes at twice the rings
        DiaphragmScene pc = scene(12, BoundaryConditions.paper());
        DiaphragmScene pf = scene(24, BoundaryConditions.paper());
        assertTrue(pf.attachedNodes() > 3 * pc.attachedNodes(), pc.attachedNodes() + " -> " + pf.attachedNodes());
        // every diaphragm node of the band is free: the ties, not a prescribed motion, hold it
        for (int v = 0; v < fine.diaphragmNodes(); v++) {
            Node n = fine.topology().node(v);
            assertTrue(!n.isDriven() && !n.isFixed(), "node " + v + " is free");
        }
    }

    @Test
    void tiesAreZeroLengthToAnchorsMovingWithTheirRibAtAFrequencyIndependentOfTheMesh() throws Exception {
        DiaphragmParameters p = DiaphragmParameters.defaults();
        for (int rings : new int[] {12, 24}) {
            DiaphragmScene s = scene(rings, BAND);
            Topology t = s.topology();
            double limit = BAND.bandStiffnessPaPerM() / (p.densityKgPerM3() * s.surfaces().thicknessM());
            int ribTies = 0;
            double maxRatio = 0;
            for (Spring sp : t.springs()) {
                if (sp.a() >= s.diaphragmNodes() || sp.b() < s.simulatedNodes()) {
                    continue;
                }
                assertEquals(0, sp.restLength(), 0, "a tie holds the node at its anchor");
                Node anchor = t.node(sp.b());
                assertTrue(anchor.isDriven() || anchor.isFixed());
                assertEquals(0, anchor.position().distance(t.node(sp.a()).position()), 1e-12);
                maxRatio = Math.max(maxRatio, sp.stiffness() / t.node(sp.a()).mass());
                if (anchor.isDriven()) {
                    ribTies++;
                    double[] out = new double[3];
                    anchor.motion().position(s.cycle().inspirationS(), anchor.position(), out, 0);
                    double moved = new Vec3(out[0], out[1], out[2]).distance(anchor.position());
                    assertTrue(moved > 1e-4 && moved < 0.03, "anchor moves with its rib: " + moved + " m");
                }
            }
            assertTrue(ribTies > 0);
            // k_i / m_i = k_b / (rho t) inside the band (taper <= 1; the mass floor only lowers it)
            assertTrue(maxRatio <= limit * (1 + 1e-9), rings + " rings: " + maxRatio + " > " + limit);
            assertTrue(maxRatio > 0.99 * limit, rings + " rings: " + maxRatio + " < " + limit);
        }
    }

    private static double total(double[] w) {
        double s = 0;
        for (double x : w) {
            s += x;
        }
        return s;
    }

    @Test
    void pressureIntegratesTheActionLinesIntensityOverTheMusclesArea() {
        double r = 0.05;
        ActionLines.Line line = new ActionLines.Line(0.013, -0.007, r);
        ActionLines lines = new ActionLines(List.of(line), BreathingCycle.quiet(), new DiaphragmControls(1, 1000));
        // half per face of the integral of cos^2(pi d / 2R) over the disc: pi R^2 (1/4 - 1/pi^2)
        double exact = Math.PI * r * r * (0.25 - 1 / (Math.PI * Math.PI));
        Vec3 up = new Vec3(0, 0, 1);
        for (int n : new int[] {20, 40}) {
            TriangleMesh m = FlatMeshes.square(0.1, n);
            int[] labels = new int[m.vertexCount()];
            double[] area = SurfaceGeometry.vertexAreas(m);
            double pressure = total(MusclePressure.weights(m, lines, BoundaryConditions.MuscleLoad.PRESSURE, up, 1,
                    labels, area));
            assertEquals(exact, pressure, 0.001 * exact, n + " x " + n + " squares (edges of " + 200 / n + " mm)");
            // the tendon plane x >= line.x cuts the disc in half, through the elements
            double half = total(MusclePressure.weights(m, lines, BoundaryConditions.MuscleLoad.PRESSURE,
                    new Vec3(1, 0, 0), line.x(), labels, area));
            assertEquals(exact / 2, half, 0.001 * exact, n + " x " + n + ": half the disc is tendon");
            // the paper's nodes converge too on a regular grid, but a node's label decides for its whole area
            double nodal = total(MusclePressure.weights(m, lines, BoundaryConditions.MuscleLoad.PAPER_NODES, up, 1,
                    labels, area));
            assertEquals(exact, nodal, 0.05 * exact, n + " x " + n + " nodal");
        }
    }

    @Test
    void outOfRangeParametersAreRefusedWithTheirNameAndUnit() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> BAND.withBandStiffness(-1));
        assertTrue(e.getMessage().contains("attachment band stiffness") && e.getMessage().contains("Pa/m"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new BoundaryConditions(
                BoundaryConditions.Attachment.BAND, 1e7, -0.001, BoundaryConditions.MuscleLoad.PRESSURE, true));
        assertTrue(e.getMessage().contains("taper") && e.getMessage().contains("m"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> BoundaryConditions.parse(BoundaryConditions.Attachment.class, "glue"));
        assertTrue(e.getMessage().contains("'glue'") && e.getMessage().contains("paper-threshold, band"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> DiaphragmScene.build(
                TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(6))),
                SceneFixture.boxes(), DiaphragmParameters.defaults().withAttachThreshold(0.004), BreathingCycle.quiet(),
                new DiaphragmControls(1, 2600), null, new BoundaryConditions(BoundaryConditions.Attachment.BAND,
                        BoundaryConditions.DEFAULT_BAND_PA_PER_M, 0.005, BoundaryConditions.MuscleLoad.PRESSURE, true)));
        assertTrue(e.getMessage().contains("taper (5.0 mm)") && e.getMessage().contains("threshold (4.0 mm)"),
                e.getMessage());
    }
}
