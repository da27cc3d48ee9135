package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.MidpointSubdivision;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The BodyParts3D diaphragm in the shared thorax of bone surfaces: attached at its origins only, the
 * attached area the same at two resolutions, the rest free to slide on the bones; skipped, naming the
 * file, where {@code ../shared} is absent.
 */
class ThoraxSceneTest {
    static final Path THORAX = org.tensim.testsupport.SharedData.THORAX;
    static final Path MESH = org.tensim.testsupport.SharedData.BODYPARTS3D_DIAPHRAGM;
    static Bones bones;
    static TwoSurfaces full;

    @BeforeAll
    static void load() throws Exception {
        assumeTrue(Files.isRegularFile(THORAX.resolve("parts.json")), THORAX.resolve("parts.json") + " not found");
        assumeTrue(Files.isRegularFile(MESH), MESH + " not found");
        bones = ThoraxBones.load(THORAX);
        full = DiaphragmSetup.loadSurfaces(MESH, MeshUnits.parse("mm"), 0.0025).surfaces();
    }

    private static DiaphragmScene scene(TwoSurfaces s) {
        DiaphragmSpec spec = DiaphragmSpec.defaults().withCage(DiaphragmSpec.Cage.defaults().withThorax(THORAX));
        return DiaphragmScene.build(s, spec, Map.of(), bones, null, spec.newControls());
    }

    private static double attachedArea(DiaphragmScene s) {
        return s.attachedPerBone().values().stream().mapToDouble(e -> e[0]).sum();
    }

    @Test
    void theDiaphragmIsAttachedAtItsOriginsOnlyAndTheRestMayTouchTheBones() {
        DiaphragmScene s = scene(full);
        double area = attachedArea(s);
        double total = full.mesh().totalArea() / 2;
        System.out.println("BodyParts3D in the thorax: attached " + s.attachedNodes() + " of " + s.diaphragmNodes()
                + " nodes, " + Math.round(area * 1e6) + " of " + Math.round(total * 1e6) + " mm^2; per bone "
                + s.attachedPerBone().keySet() + "; contact pairs " + s.topology().contacts().size());
        for (String bone : s.attachedPerBone().keySet()) {
            Bones.Bone b = bones.all().stream().filter(x -> x.name().equals(bone)).findFirst().orElseThrow();
            assertTrue(b.origin(), bone + " is not one of the diaphragm's origins");
        }
        assertTrue(area < 0.25 * total, "attached " + area + " of " + total + " m^2: more than the origins");
        assertTrue(area > 0.02 * total, "attached " + area + " of " + total + " m^2: the origins are missing");
        assertTrue(s.topology().contacts().size() > 0, "no node may touch a bone");
        for (org.tensim.model.ContactPair c : s.topology().contacts()) {
            Node n = s.topology().node(c.node());
            assertTrue(!s.isAttached(c.node()) && !n.isDriven() && !n.isFixed(), "node " + c.node()
                    + " is attached and in contact");
        }
    }

    /**
     * Where the registered bones lie in the sheet's thickness (a node that starts inside a bone: a hard pair of
     * negative gap), the muscle's column through that node is a spring, not a rigid link: the contact may put the
     * column's two ends out on opposite faces of the bone, farther apart than a rigid column's length (rib 11 on
     * the full thorax, docs/lungs.md). The muscle's other columns stay rigid.
     */
    @Test
    void aColumnWithAnEndInsideABoneIsASpring() {
        DiaphragmScene s = scene(full);
        org.tensim.model.Topology t = s.topology();
        boolean[] inside = new boolean[s.diaphragmNodes()];
        int count = 0;
        for (org.tensim.model.ContactPair c : t.contacts()) {
            if (c.node() < inside.length && c.gapM() < 0 && t.contactBodies().get(c.body()).hard()) {
                count += inside[c.node()] ? 0 : 1;
                inside[c.node()] = true;
            }
        }
        assertTrue(count > 0, "some nodes start inside a bone");
        int muscleColumns = 0;
        for (org.tensim.model.RigidLink l : t.rigidLinks()) {
            assertTrue(!(l.a() < inside.length && inside[l.a()]) && !(l.b() < inside.length && inside[l.b()]),
                    "a rigid column " + l.a() + "-" + l.b() + " has an end inside a bone");
            muscleColumns += l.a() < inside.length && s.labels()[l.a()] == DiaphragmScene.MUSCLE ? 1 : 0;
        }
        System.out.println("BodyParts3D in the thorax: " + count + " nodes start inside a bone; " + muscleColumns
                + " rigid muscle columns");
        assertTrue(muscleColumns > 0, "the muscle's other columns stay rigid");
    }

    /**
     * The liver is the compliant support under the right dome, not a bone: its pairs hold free lower-surface nodes
     * only, each at its rest distance (resting on it at end-expiration) with the liver's stiffness per unit area
     * times the node's area (K A_i / 2), and they lie mostly under the right half; the penetration figures leave it
     * out.
     */
    @Test
    void theLiverSupportsTheRightDomesLowerSurfaceFromRest() {
        DiaphragmScene s = scene(full);
        double k = DiaphragmSpec.Cage.DEFAULT_LIVER_PA_PER_M;
        double[] area = s.nodeAreasM2();
        double[] b = full.mesh().bounds();
        double midX = 0.5 * (b[0] + b[3]);
        int liver = 0;
        int right = 0;
        double[] g = new double[3];
        for (org.tensim.model.ContactPair c : s.topology().contacts()) {
            org.tensim.model.ContactBody body = s.topology().contactBodies().get(c.body());
            boolean isLiver = body.name().startsWith("liver");
            assertEquals(!isLiver, s.isBoneContact(c.body()), body.name());
            if (!isLiver) {
                continue;
            }
            liver++;
            int v = c.node();
            assertTrue(!full.isUpper(v), "node " + v + " of the upper surface rests on the liver");
            Vec3 x = s.topology().node(v).position();
            assertEquals(body.surface().distance(x.x(), x.y(), x.z(), g, 0), c.gapM(), 1e-12,
                    "node " + v + " rests on the liver at its rest distance");
            assertTrue(c.gapM() < BoneContact.LIVER_RANGE_M);
            assertEquals(k * area[v], c.stiffnessNPerM(), 1e-9 * c.stiffnessNPerM(), "K A_i / 2 at node " + v);
            if (x.x() < midX) {
                right++;
            }
        }
        assertTrue(liver > 100, "the liver supports " + liver + " nodes");
        // Mostly under the right dome (1,219 of 1,900 nodes); the left lobe reaches under the left dome's medial part.
        assertTrue(right > 0.6 * liver, right + " of the " + liver + " nodes on the liver lie on the right");
        DiaphragmSpec off = DiaphragmSpec.defaults().withCage(DiaphragmSpec.Cage.defaults().withThorax(THORAX)
                .withLiverSupport(0));
        DiaphragmScene none = DiaphragmScene.build(full, off, Map.of(), bones, null, off.newControls());
        assertEquals(s.topology().contacts().size() - liver, none.topology().contacts().size(), "0 turns it off");
    }

    /**
     * The costal origin runs all round: the right ribs 11-12 hold the posterior costal margin as the left ones do.
     * The right crus hangs 40 mm below that margin in the same azimuths; taken as the margin, it left the right
     * posterior costal origin free (12.6 and 226 mm^2 on ribs 11 and 12, against 364 and 406 on the left).
     */
    @Test
    void thePosteriorCostalOriginIsAttachedOnBothSides() {
        Map<String, double[]> per = scene(full).attachedPerBone();
        double right = area(per, "rib-r11") + area(per, "rib-r12");
        double left = area(per, "rib-l11") + area(per, "rib-l12");
        System.out.println("attached on ribs 11-12: right " + Math.round(right * 1e6) + " mm^2, left "
                + Math.round(left * 1e6) + " mm^2");
        assertTrue(right > 0.6 * left && left > 0.6 * right, "ribs 11-12 attached: right " + right * 1e6
                + " mm^2, left " + left * 1e6 + " mm^2");
    }

    private static double area(Map<String, double[]> perBone, String bone) {
        double[] e = perBone.get(bone);
        return e == null ? 0 : e[0];
    }

    @Test
    void theAttachedAreaDoesNotDependOnTheMesh() {
        // The same surface at twice the resolution: every triangle split in four (the geometry unchanged).
        TriangleMesh fineMesh = MidpointSubdivision.refine(full.mesh(), 1);
        TwoSurfaces refined = DiaphragmSetup.surfaces(fineMesh, 0.0025).surfaces();
        double given = attachedArea(scene(full));
        double fine = attachedArea(scene(refined));
        System.out.println("attached area: " + Math.round(given * 1e6) + " mm^2 (" + full.mesh().vertexCount()
                + " vertices), " + Math.round(fine * 1e6) + " mm^2 (" + refined.mesh().vertexCount() + " vertices)");
        assertEquals(fine, given, 0.05 * fine, "attached area at two resolutions");
    }

    @Test
    void theZoneOfAppositionIsAPartOfTheLowerFaceAndTheSameAtEveryResolution() {
        DiaphragmScene given = scene(full);
        double zone = given.appositionAreaM2();
        double lower = 0;
        double[] area = SurfaceGeometry.vertexAreas(full.mesh());
        for (int v = 0; v < full.mesh().vertexCount(); v++) {
            lower += full.isUpper(v) ? 0 : area[v];
        }
        double fine = scene(DiaphragmSetup.surfaces(MidpointSubdivision.refine(full.mesh(), 1), 0.0025).surfaces())
                .appositionAreaM2();
        double half = scene(full.decimated(0.0045)).appositionAreaM2();
        System.out.println("zone of apposition: " + Math.round(zone * 1e6) + " of " + Math.round(lower * 1e6)
                + " mm^2 of the lower face; refined " + Math.round(fine * 1e6) + ", decimated at 4.5 mm "
                + Math.round(half * 1e6));
        assertTrue(zone > 0.1 * lower && zone < 0.8 * lower, "the zone is a part of the lower face: " + zone + " of "
                + lower + " m^2");
        // Its edge moves by up to an edge's length with the vertices: half an edge (2-3 mm) along an edge some 1.5 m
        // long is about 5 % of the zone.
        assertEquals(fine, zone, 0.05 * fine, "the zone at two resolutions");
        assertEquals(zone, half, 0.05 * zone, "the zone, full and decimated to half the triangles");
        DiaphragmSpec off = DiaphragmSpec.defaults().withCage(DiaphragmSpec.Cage.defaults().withThorax(THORAX)
                .withAppositionPressure(0));
        assertEquals(0, DiaphragmScene.build(full, off, Map.of(), bones, null, off.newControls()).appositionAreaM2(),
                0, "0 Pa: no zone pressed");
    }

    @Test
    void theAttachedAreaDoesNotGrowWhenTheResolutionStudyDecimates() {
        // the study's coarsest model in the thorax: 6 mm cells, 40 % of the triangles (docs/thorax.md)
        TwoSurfaces coarse = full.decimated(0.006);
        double given = attachedArea(scene(full));
        double decimated = attachedArea(scene(coarse));
        System.out.println("attached area: " + Math.round(given * 1e6) + " mm^2 (" + full.mesh().triangleCount()
                + " triangles), " + Math.round(decimated * 1e6) + " mm^2 decimated at 6 mm ("
                + coarse.mesh().triangleCount() + " triangles)");
        assertEquals(given, decimated, 0.05 * given, "attached area, full and decimated");
    }
}
