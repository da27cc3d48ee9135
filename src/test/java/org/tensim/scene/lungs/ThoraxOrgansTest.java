package org.tensim.scene.lungs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.scene.diaphragm.Bones;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.scene.thorax.TriangleTree;
import org.tensim.solver.Simulation;
import org.tensim.solver.SurfaceSliding;
import org.tensim.testsupport.SharedData;

/**
 * The shared thorax's lungs and liver built into the BodyParts3D diaphragm's state (decimated at 10 mm to keep the
 * build short): the pleura's carriers by kind, the followers, the rest relation held exactly at t = 0, a few RK2
 * steps' cost with and without the organs, and how far pleura.obj lies from the lungs' own surfaces.
 */
class ThoraxOrgansTest {
    @Test
    void theSharedThoraxOrgansBuildIntoTheDiaphragmState() throws Exception {
        Path thoraxDir = SharedData.THORAX;
        Path mesh = SharedData.BODYPARTS3D_DIAPHRAGM;
        for (Path f : new Path[] {thoraxDir.resolve("parts.json"), thoraxDir.resolve("pleura.obj"), mesh}) {
            assumeTrue(Files.isRegularFile(f), f.toAbsolutePath() + " not found");
        }
        DiaphragmSpec spec = DiaphragmSpec.defaults().withCage(DiaphragmSpec.Cage.defaults().withThorax(thoraxDir));
        spec = spec.withMesh(spec.mesh().withFile(mesh, MeshUnits.parse("mm")));
        DiaphragmSetup.Inputs in = DiaphragmSetup.read(spec);
        Bones bones = in.bones();
        TwoSurfaces s = in.surfaces().surfaces().decimated(0.010);
        DiaphragmScene plain = DiaphragmScene.build(s, spec, Map.of(), bones, null, spec.newControls());
        DiaphragmScene scene = DiaphragmScene.build(s, spec, Map.of(), bones, null, spec.newControls());
        Thorax thorax = ThoraxLoader.load(thoraxDir, EnumSet.of(Group.LUNG, Group.LIVER, Group.PLEURA));
        List<TriangleMesh> lungs = LungVolumes.surfaces(thorax);
        TriangleMesh liver = thorax.group(Group.LIVER).get(0).mesh();
        long t0 = System.nanoTime();
        int before = scene.topology().nodeCount();
        ThoraxOrgans organs = ThoraxOrgans.build(scene, lungs, liver, ThoraxOrgans.Options.defaults().withLiver());
        List<SurfaceSliding> terms = organs.install(scene);
        double build = (System.nanoTime() - t0) * 1e-9;
        for (int i = 0; i < 2; i++) {
            PleuraCarriers.Built p = organs.pleurae().get(i);
            System.out.printf("%s pleura: %d vertices: diaphragm %d, rib %d, intercostal %d, fixed %d; lung nodes %d,"
                    + " followers %d%n", i == 0 ? "right" : "left", p.surface().vertexCount(),
                    p.count(PleuraCarriers.Carrier.DIAPHRAGM), p.count(PleuraCarriers.Carrier.RIB),
                    p.count(PleuraCarriers.Carrier.INTERCOSTAL), p.count(PleuraCarriers.Carrier.FIXED),
                    organs.lungs().get(i).body().nodeCount(), terms.get(i).pairCount());
            for (PleuraCarriers.Carrier c : PleuraCarriers.Carrier.values()) {
                assertTrue(p.count(c) > 0, "pleura vertices carried by " + c);
            }
            assertTrue(terms.get(i).pairCount() > 200, "followers of a lung: " + terms.get(i).pairCount());
        }
        System.out.printf("organs: %d nodes after the diaphragm scene's %d; liver %d nodes, %d followers, %d held;"
                + " built in %.1f s%n", scene.topology().nodeCount() - before, before, organs.liver().nodeCount(),
                terms.get(2).pairCount(), organs.liverHeld().length, build);
        assertTrue(organs.liverHeld().length > 10, "liver nodes held at the bare area");
        assertAbdomenUnderTheLiver(scene, organs, terms.get(2).pairCount());
        Simulation sim = scene.newSimulation();
        // At rest every follower is at its gap from the triangle it was paired with; the read-out walks from there
        // and may settle on a neighbour at the same closest distance whose plane differs by a hair: 1 um allowed.
        for (SurfaceSliding term : terms) {
            assertEquals(0, term.maxPenetrationM(sim.state().x), 1e-6, term + " at rest");
            assertEquals(0, term.maxSeparationM(sim.state().x), 1e-6, term + " at rest");
        }
        double dt = scene.recommendedTimeStep();
        assertEquals(plain.recommendedTimeStep(), dt, 0, "the organs do not change the diaphragm's step");
        Simulation bare = plain.newSimulation();
        double[] ms = {stepMs(bare, dt, 20), stepMs(sim, dt, 20)};
        System.out.printf("RK2 at %.3g s: %.2f ms a step without the organs (%d nodes), %.2f ms with (%d nodes);"
                + " load %.1f%n", dt, ms[0], plain.topology().nodeCount(), ms[1], scene.topology().nodeCount(),
                java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        // pleura.obj against the lungs' surfaces: distance of each lung vertex to it.
        TriangleMesh pleura = thorax.group(Group.PLEURA).get(0).mesh();
        TriangleTree tree = new TriangleTree(pleura.coordinates(), pleura.triangles(), 3);
        int[] stack = tree.newStack();
        for (int i = 0; i < 2; i++) {
            TriangleMesh l = lungs.get(i);
            double[] d = new double[l.vertexCount()];
            for (int v = 0; v < d.length; v++) {
                d[v] = tree.distance(l.coord(v, 0), l.coord(v, 1), l.coord(v, 2), stack);
            }
            Arrays.sort(d);
            System.out.printf("%s lung's vertices to pleura.obj: median %.1f mm, 90th percentile %.1f mm, max %.1f"
                    + " mm%n", i == 0 ? "right" : "left", 1e3 * d[d.length / 2], 1e3 * d[(int) (0.9 * d.length)],
                    1e3 * d[d.length - 1]);
        }
    }

    /**
     * The abdomen's support: liver nodes of its lower half only, none held at the bare area, each tied by one
     * zero-length spring of K h^2 to a fixed anchor at its own rest point (so it pushes back K h^2 d when moved d).
     */
    private static void assertAbdomenUnderTheLiver(DiaphragmScene scene, ThoraxOrgans organs, int followers) {
        int[] below = organs.liverSupported();
        System.out.printf("liver: %d nodes on the abdomen, %d held, %d followers%n", below.length,
                organs.liverHeld().length, followers);
        assertTrue(below.length > 10, "liver nodes on the abdomen: " + below.length);
        java.util.Set<Integer> held = new java.util.HashSet<>();
        for (int id : organs.liverHeld()) {
            held.add(id);
        }
        double[] b = organs.liver().surface().bounds();
        double zMid = 0.5 * (b[2] + b[5]);
        double h = ThoraxOrgans.LIVER.cellSizeM();
        double k = ThoraxOrgans.Options.ABDOMEN_PA_PER_M * h * h;
        java.util.Map<Integer, List<org.tensim.model.Spring>> byNode = new java.util.HashMap<>();
        for (org.tensim.model.Spring sp : scene.topology().springs()) {
            byNode.computeIfAbsent(sp.a(), x -> new java.util.ArrayList<>()).add(sp);
        }
        for (int id : below) {
            assertFalse(held.contains(id), "node " + id + " both held at the bare area and on the abdomen");
            var p = scene.topology().node(id).position();
            assertTrue(p.z() < zMid, "node " + id + " on the abdomen at z " + p.z()
                    + " m, above the liver's middle");
            List<org.tensim.model.Spring> ties = byNode.getOrDefault(id, List.of()).stream()
                    .filter(sp -> scene.topology().node(sp.b()).isFixed()).toList();
            assertEquals(1, ties.size(), "node " + id + "'s ties to fixed anchors");
            org.tensim.model.Spring tie = ties.get(0);
            assertEquals(k, tie.stiffness(), 1e-9 * k, "K h^2");
            assertEquals(0, tie.restLength(), 0);
            assertEquals(0, p.distance(scene.topology().node(tie.b()).position()), 1e-12, "anchor at rest point");
        }
        ThoraxOrgans.Options none = ThoraxOrgans.Options.defaults().withLiver().withAbdomen(0);
        assertEquals(0, none.liverBelowPaPerM(), 0);
        assertThrows(IllegalArgumentException.class, () -> ThoraxOrgans.Options.defaults().withAbdomen(-1));
    }

    private static double stepMs(Simulation sim, double dt, int n) {
        sim.step(dt);
        long t0 = System.nanoTime();
        for (int i = 0; i < n; i++) {
            sim.step(dt);
        }
        return (System.nanoTime() - t0) * 1e-6 / n;
    }
}
