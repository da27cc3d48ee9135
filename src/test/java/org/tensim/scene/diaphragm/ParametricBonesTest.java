package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.RigidMotion;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.thorax.DistanceGrid;
import org.tensim.scene.thorax.TubeSweep;
import org.tensim.solver.Simulation;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The parametric cage swept into bone surfaces ({@code --cage surfaces}): closed outward tubes around the cage's own
 * lines, moving with the cage's rib laws, and the thorax's attachment at the origins and contact on them. Coarse: 12
 * vertices around a section, and 3 mm distance-grid cells where a whole scene is built (the default 1.5 mm where one
 * bone's sign is checked).
 */
class ParametricBonesTest {
    private static final int AROUND = 12;
    private static final Map<String, double[]> BOXES = ParametricRibCage.adult();

    /** A cage built from the default boxes, its topology, and its bones at the given grid cell. */
    private record Cage(Topology t, RibCage cage, Bones bones) {
        static Cage of(double cellM) {
            Topology t = new Topology();
            RibCage c = RibCage.build(t, new SpringList(), BOXES, DiaphragmParameters.defaults(),
                    BreathingCycle.quiet(), new DiaphragmControls(1, 0));
            double[] sb = BOXES.get("sternum");
            return new Cage(t, c, ParametricBones.of(c, t, sb[3] - sb[0], AROUND,
                    m -> DistanceGrid.build(m, cellM, DistanceGrid.DEFAULT_MARGIN_M)));
        }
    }

    private static Cage coarse;

    private static synchronized Cage coarse() {
        if (coarse == null) {
            coarse = Cage.of(3e-3);
        }
        return coarse;
    }

    @Test
    void everyBoneIsAClosedOutwardSurfaceAroundItsLineNegativeInside() {
        Cage c = Cage.of(DistanceGrid.DEFAULT_CELL_M);
        Bones b = c.bones();
        assertEquals(24, b.of(Bones.Kind.RIB).size());
        assertEquals(2 * 10, b.of(Bones.Kind.CARTILAGE).size(), "cartilages 1-10 on each side; 11-12 float");
        assertEquals(1, b.of(Bones.Kind.XIPHOID).size());
        assertEquals(java.util.List.of(13, 14, 15), b.of(Bones.Kind.VERTEBRA).stream().map(Bones.Bone::index).toList(),
                "L1-L3");
        for (Bones.Bone bone : b.all()) {
            double volume = org.tensim.scene.thorax.TubeSweepTest.closedVolume(bone.mesh());
            assertTrue(volume > 0, bone.name() + ": outward normals, volume " + volume);
        }
        // A rib's volume is its section (12 x 6 mm ellipse, as the inscribed 12-gon) times its line's length.
        int[] line = ParametricBones.line(c.cage(), RibCage.Kind.RIB, "rib-r9");
        double length = 0;
        for (int k = 0; k + 1 < line.length; k++) {
            length += c.t().node(line[k]).position().distance(c.t().node(line[k + 1]).position());
        }
        double section = AROUND / 2.0 * 6e-3 * 3e-3 * Math.sin(2 * Math.PI / AROUND);
        assertEquals(section * length, org.tensim.scene.thorax.TubeSweepTest.closedVolume(
                b.find(Bones.Kind.RIB, Bones.Side.RIGHT, 9).mesh()), 0.03 * section * length, "rib r9's volume");
        // Negative at the line (by the thin half-thickness, 3 mm, within a cell), positive off it across the line.
        double[] g = new double[3];
        Bones.Bone rib = byName(b, "rib-r9");
        int[] l = ParametricBones.line(c.cage(), RibCage.Kind.RIB, "rib-r9");
        for (int k = 1; k + 1 < l.length; k++) {
            Vec3 p = c.t().node(l[k]).position();
            double d = b.field(b.indexOf(rib)).distance(p.x(), p.y(), p.z(), g, 0);
            assertEquals(-3e-3, d, DistanceGrid.DEFAULT_CELL_M, "rib r9 at its line's node " + k);
            // 16 mm off the line along the section's height: 10 mm outside its 6 mm half-height
            Vec3 t = c.t().node(l[k + 1]).position().minus(c.t().node(l[k - 1]).position()).normalized();
            Vec3 u = new Vec3(0, 0, 1).minus(t.times(t.z())).normalized();
            Vec3 q = p.plus(u.times(0.016));
            double off = b.field(b.indexOf(rib)).distance(q.x(), q.y(), q.z(), g, 0);
            assertEquals(0.010, off, DistanceGrid.DEFAULT_CELL_M, "rib r9, 16 mm off node " + k);
            assertTrue(g[0] * u.x() + g[1] * u.y() + g[2] * u.z() > 0.9, "the normal points out there: "
                    + java.util.Arrays.toString(g));
        }
        // The vertebra's axis lies half its depth (17 mm) inside (the scene's 3 mm cells).
        Bones cb = coarse().bones();
        Bones.Bone l1 = byName(cb, "vertebra-L1");
        double[] box = l1.mesh().bounds();
        double d = cb.field(cb.indexOf(l1)).distance(0.5 * (box[0] + box[3]), 0.5 * (box[1] + box[4]),
                0.5 * (box[2] + box[5]), g, 0);
        assertEquals(-17e-3, d, 3e-3, "L1's axis: half its depth inside");
    }

    @Test
    void aRibsSurfaceMovesAsTheLinePointItWasSweptFrom() {
        Cage c = coarse();
        RigidMotion[] motions = ParametricBones.motions(c.bones(), c.cage(), c.t());
        double end = BreathingCycle.quiet().inspirationS();
        double[] node = new double[3];
        double[] surface = new double[3];
        for (String name : new String[] {"rib-r9", "rib-l3"}) {
            Bones.Bone rib = byName(c.bones(), name);
            RigidMotion m = motions[c.bones().indexOf(rib)];
            int[] line = ParametricBones.line(c.cage(), RibCage.Kind.RIB, name);
            double angle = c.cage().motions().get(name).maxAngleRad();
            TriangleMesh mesh = rib.mesh();
            double largest = 0;
            for (int v = 0; v < mesh.vertexCount(); v++) {
                int k = line[TubeSweep.sourcePoint(v, line.length, AROUND)];
                Vec3 x0 = c.t().node(k).position();
                // The line's node is driven by the cage's own law; the surface by the bone's.
                c.t().node(k).motion().position(end, x0, node, 0);
                Vec3 s0 = new Vec3(mesh.coord(v, 0), mesh.coord(v, 1), mesh.coord(v, 2));
                m.position(end, s0, surface, 0);
                Vec3 dn = new Vec3(node[0], node[1], node[2]).minus(x0);
                Vec3 ds = new Vec3(surface[0], surface[1], surface[2]).minus(s0);
                double offset = s0.distance(x0);
                assertEquals(offset, new Vec3(surface[0], surface[1], surface[2]).distance(
                        new Vec3(node[0], node[1], node[2])), 1e-12, name + " vertex " + v + " keeps its place");
                assertTrue(ds.minus(dn).norm() <= angle * offset + 1e-12, name + " vertex " + v + " moved "
                        + ds + ", its line point " + dn);
                largest = Math.max(largest, dn.norm());
            }
            assertTrue(largest > 2e-3, name + " moves: " + largest + " m");
        }
        // A cartilage's surface moves with its rib; the vertebrae stay.
        assertSame(c.cage().motions().get("rib-l8"),
                motions[c.bones().indexOf(byName(c.bones(), "cartilage-l8"))]);
        assertSame(RigidMotion.FIXED, motions[c.bones().indexOf(byName(c.bones(), "vertebra-L2"))]);
    }

    private static DiaphragmScene scene(int rings) {
        DiaphragmSpec d = DiaphragmSpec.defaults();
        DiaphragmSpec spec = d.withMesh(d.mesh().withRings(rings)).withCage(d.cage().withSurfaces(true));
        return DiaphragmScene.build(DiaphragmSetup.generatedSurfaces(rings), spec, BOXES, coarse().bones(), null,
                spec.newControls());
    }

    private static double attachedArea(DiaphragmScene s) {
        return s.attachedPerBone().values().stream().mapToDouble(e -> e[0]).sum();
    }

    @Test
    void theDomeIsAttachedAtItsOriginsOnlyByAnAreaThatDoesNotGrowWithTheMesh() {
        DiaphragmScene s12 = scene(12);
        DiaphragmScene s14 = scene(14);
        for (DiaphragmScene s : new DiaphragmScene[] {s12, s14}) {
            Bones b = s.bones();
            boolean rib = false;
            boolean cartilage = false;
            boolean crus = false;
            for (String name : s.attachedPerBone().keySet()) {
                Bones.Bone bone = byName(b, name);
                assertTrue(bone.origin(), name + " is no origin (ribs 7-12, cartilages 7-10, xiphoid, L1-L3)");
                rib |= bone.kind() == Bones.Kind.RIB;
                cartilage |= bone.kind() == Bones.Kind.CARTILAGE;
                crus |= bone.kind() == Bones.Kind.VERTEBRA;
            }
            assertTrue(rib && cartilage && crus, "costal and lumbar origins: " + s.attachedPerBone().keySet());
            double area = s.surfaces().mesh().totalArea() / 2;
            assertTrue(attachedArea(s) > 0.02 * area && attachedArea(s) < 0.15 * area,
                    "attached " + attachedArea(s) + " of " + area + " m^2");
        }
        double a12 = attachedArea(s12);
        double a14 = attachedArea(s14);
        System.out.printf("parametric cage as surfaces: attached %.0f mm^2 at 12 rings, %.0f at 14%n", a12 * 1e6,
                a14 * 1e6);
        assertEquals(a12, a14, 0.05 * a14, "attached area at 12 and 14 rings, m^2");
        assertTrue(s14.contactPairsPerBone().size() > 0, "the rest may touch the bones");
    }

    @Test
    void aBreathWithContactStaysOutOfTheBonesWithinThePenaltysTolerance() {
        DiaphragmScene s = scene(12);
        Simulation sim = s.newSimulation();
        sim.setIntegrator(new PrefactoredBdf2().setNewtonIterations(PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS)
                .setKrylovIterations(PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS));
        double end = BreathingCycle.quiet().inspirationS();
        double worst = 0;
        int touching = 0;
        for (double t = 0.1; t < end + 1e-9; t += 0.1) {
            sim.runUntil(Math.min(t, end), 0.01);
            var c = sim.state().contacts;
            worst = Math.max(worst, c.maxPenetrationPastGap(sim.time(), sim.state().x)[0]);
            touching = Math.max(touching, c.activeCount(sim.time(), sim.state().x));
        }
        int apex = s.apexNode();
        double descent = sim.state().x0[3 * apex + 2] - sim.state().x[3 * apex + 2];
        System.out.printf("parametric cage as surfaces, 12 rings, bdf2 10 ms: apex descent %.2f mm, deepest %.3f mm"
                + " past rest, %d pairs touching%n", descent * 1e3, worst * 1e3, touching);
        assertTrue(touching > 0, "the muscle lies on the cage somewhere");
        assertTrue(descent > 5e-3, "the dome descends: " + descent + " m");
        // The penalty's penetration is the local pressure over its stiffness: a few tenths of a millimetre.
        assertTrue(worst < 0.5e-3, "deepest past rest " + worst + " m");
    }

    private static Bones.Bone byName(Bones b, String name) {
        for (Bones.Bone bone : b.all()) {
            if (bone.name().equals(name)) {
                return bone;
            }
        }
        throw new AssertionError("no bone " + name);
    }
}
