package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * {@code part:} regions on a diaphragm (6 rings, the parametric cage): each part is what the scene was built with,
 * checked against the scene's own figures: the tendon's nodes carry the tendon's share of the upper surface's area,
 * the attached nodes are the attachment's count per bone summed, the apex is the highest upper node, and the parts
 * split the diaphragm's nodes (tendon + muscle, upper + lower, attached + free). A shell's {@code upper} and
 * {@code lower} parts are its two surfaces' nodes, one offset from the other by the thickness.
 */
class BodyPartsTest {
    @TempDir
    Path dir;

    @Test
    void aDiaphragmsPartsAreItsTendonMuscleSurfacesAttachmentAndApex() {
        StringBuilder regions = new StringBuilder("regions:\n");
        for (String p : org.tensim.scene.diaphragm.DiaphragmRegions.NAMES) {
            if (!p.equals("apposition")) { // the parametric cage has no bone surfaces: no apposition zone
                regions.append("  ").append(p).append(": {part: ").append(p).append("}\n");
            }
        }
        Scene s = SceneFiles.load(dir, "d.yaml", "version: 1\nbodies:\n  d: {type: diaphragm, rings: 6}\n" + regions
                + "run: {dt: auto, duration: 10 ms}\n");
        DiaphragmScene scene = ((DiaphragmSetup.Built) s.bodies().get("d").built()).scene();
        int n = scene.diaphragmNodes();
        BitSet tendon = s.regions().get("tendon").in("d");
        BitSet muscle = s.regions().get("muscle").in("d");
        BitSet upper = s.regions().get("upper").in("d");
        BitSet lower = s.regions().get("lower").in("d");
        BitSet attached = s.regions().get("attached").in("d");
        BitSet free = s.regions().get("free").in("d");
        int tendonCount = 0;
        for (int v = 0; v < n; v++) {
            tendonCount += scene.labels()[v] == DiaphragmScene.TENDON ? 1 : 0;
        }
        assertEquals(tendonCount, tendon.cardinality(), "the tendon part is the diaphragm's tendon");
        assertEquals(n, tendon.cardinality() + muscle.cardinality());
        assertTrue(!tendon.intersects(muscle));
        assertEquals(n, upper.cardinality() + lower.cardinality());
        assertEquals(scene.surfaces().upperCount(), upper.cardinality());
        assertEquals(scene.attachedNodes(), attached.cardinality(), "ribs + cartilage + spine");
        assertEquals(n, attached.cardinality() + free.cardinality());
        // The tendon's share of the upper surface's area, by the nodes' areas: the builder's own figure.
        double[] area = scene.nodeAreasM2();
        double tendonArea = 0;
        double upperArea = 0;
        for (int v = upper.nextSetBit(0); v >= 0; v = upper.nextSetBit(v + 1)) {
            upperArea += area[v];
            tendonArea += tendon.get(v) ? area[v] : 0;
        }
        System.out.printf("6 rings: %d nodes, tendon %d (%.4f of the upper area; the scene's %.4f), attached %d%n", n,
                tendon.cardinality(), tendonArea / upperArea, scene.tendonAreaFraction(), attached.cardinality());
        assertEquals(scene.tendonAreaFraction(), tendonArea / upperArea, 1e-12);
        BitSet apex = s.regions().get("apex").in("d");
        assertEquals(1, apex.cardinality());
        TwoSurfaces surf = scene.surfaces();
        int a = apex.nextSetBit(0);
        for (int v = upper.nextSetBit(0); v >= 0; v = upper.nextSetBit(v + 1)) {
            assertTrue(surf.mesh().coord(v, 2) <= surf.mesh().coord(a, 2), "the apex is the highest upper node");
        }
        assertTrue(upper.get(a));
    }

    @Test
    void aShellsPartsAreItsTwoSurfaces() throws java.io.IOException {
        org.tensim.io.mesh.TriangleMesh flat = org.tensim.analysis.FlatMeshes.disc(4, 0.05);
        org.tensim.io.mesh.ObjWriter.write(dir.resolve("disc.obj"), flat, org.tensim.io.mesh.MeshUnits.M,
                java.util.List.of("a disc"), 12);
        Scene s = SceneFiles.load(dir, "s.yaml", "version: 1\nbodies:\n  s: {type: shell, surface: {file: disc.obj,"
                + " units: m}, thickness: 2 mm, material: {E: 40 kPa}}\nregions:\n  up: {part: upper}\n"
                + "  down: {part: lower}\nrun: {dt: 1 ms, duration: 1 ms}\n");
        BitSet up = s.regions().get("up").in("s");
        BitSet down = s.regions().get("down").in("s");
        int nv = flat.vertexCount();
        assertEquals(nv, up.cardinality());
        assertEquals(nv, down.cardinality());
        org.tensim.model.Topology t = s.bodies().get("s").topology();
        for (int v = 0; v < nv; v++) {
            assertTrue(up.get(v) && down.get(v + nv), "node v is vertex v, the upper surface's first");
            assertEquals(0, t.node(v).position().z(), 1e-12, "the upper surface is the file's");
            assertEquals(-0.002, t.node(v + nv).position().z(), 1e-9, "the lower one offset by the thickness");
        }
    }
}
