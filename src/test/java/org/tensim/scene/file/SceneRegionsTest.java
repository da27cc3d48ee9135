package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.CubeScene;

/** Each kind of region on the cube's 20 nodes, against the same selection made directly on the node positions. */
class SceneRegionsTest {
    @TempDir
    Path dir;

    static final String HEAD = "version: 1\nunits: {length: m}\nbodies:\n  c: {type: cube}\n"
            + "run: {dt: 1 ms, duration: 1 ms}\n";

    /** The nodes of the cube (side 10 m, with its element) whose initial position passes {@code p}. */
    static BitSet where(Predicate<Vec3> p) {
        Topology t = new Topology();
        CubeScene.addStructure(t, 10, 1, 100, 2, true, true);
        BitSet s = new BitSet();
        for (Node n : t.nodes()) {
            if (p.test(n.position())) {
                s.set(n.id());
            }
        }
        return s;
    }

    BitSet region(String regions, String name) {
        Scene s = SceneFiles.load(dir, "r.yaml", HEAD + "regions:\n" + regions);
        return s.regions().get(name).in("c");
    }

    @Test
    void boxesAbsoluteAndRelative() {
        BitSet bottom = where(q -> Math.abs(q.y()) < 1e-9);
        assertEquals(6, bottom.cardinality());
        assertEquals(bottom, region("  r: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}\n", "r"));
        assertEquals(bottom, region("  r: {box: {min: [-1 m, -1 mm, -1 m], max: [11 m, 1 mm, 11 m]}}\n", "r"));
        BitSet part = where(q -> q.x() <= 5 + 1e-9 && q.y() >= 5 - 1e-9);
        assertTrue(part.cardinality() > 4 && part.cardinality() < 20);
        assertEquals(part, region("  r: {box: {min: [0, 0.5, 0], max: [0.5, 1, 1], frame: relative}}\n", "r"));
        // The element's nodes all lie on the cube's faces: a box strictly inside selects nothing, and is refused.
        SceneException e = org.junit.jupiter.api.Assertions.assertThrows(SceneException.class, () -> region(
                "  r: {box: {min: [0.2, 0.2, 0.2], max: [0.8, 0.8, 0.8], frame: relative}}\n", "r"));
        assertTrue(e.getMessage().contains("selects no node"), e.getMessage());
    }

    @Test
    void spheres() {
        // Centre of the cube, radius 5 m: the element's 12 nodes are 5.59 m away (sqrt(5^2 + 2.5^2)), not inside.
        BitSet near = where(q -> q.distance(new Vec3(5, 10, 5)) <= 3);
        assertEquals(near, region("  r: {sphere: {centre: [5, 10, 5], radius: 3 m}}\n", "r"));
        double diag = Math.sqrt(300);
        BitSet corner = where(q -> q.distance(new Vec3(0, 0, 0)) <= 0.5 * diag + 1e-6);
        assertEquals(corner, region("  r: {sphere: {centre: [0, 0, 0], radius: 0.5, frame: relative}}\n", "r"));
        assertTrue(corner.cardinality() > 1 && corner.cardinality() < 20);
    }

    @Test
    void halfSpaces() {
        BitSet upper = where(q -> q.y() >= 5 - 1e-9);
        assertEquals(upper, region("  r: {plane: {point: [0, 5 m, 0], normal: [0, 1, 0]}}\n", "r"));
        BitSet tilted = where(q -> q.x() + q.z() >= 10 - 1e-6);
        assertEquals(tilted, region("  r: {plane: {point: [0.5, 0, 0.5], normal: [1, 0, 1], frame: relative}}\n",
                "r"));
    }

    @Test
    void indicesAndLabelFiles() throws Exception {
        BitSet some = new BitSet();
        some.set(0);
        some.set(13);
        some.set(19);
        assertEquals(some, region("  r: {indices: [19, 0, 13]}\n", "r"));
        VertexLabel[] labels = new VertexLabel[20];
        java.util.Arrays.fill(labels, VertexLabel.MUSCLE);
        labels[3] = VertexLabel.TENDON;
        labels[8] = VertexLabel.TENDON;
        VertexLabelsFile.write(dir.resolve("c.labels"), labels);
        BitSet tendon = new BitSet();
        tendon.set(3);
        tendon.set(8);
        assertEquals(tendon, region("  r: {labels: {file: c.labels, label: tendon}}\n", "r"));
    }

    @Test
    void unionsIntersectionsAndDifferences() {
        String base = "  low: {plane: {point: [0, 0.5, 0], normal: [0, -1, 0], frame: relative}}\n"
                + "  left: {plane: {point: [0.5, 0, 0], normal: [-1, 0, 0], frame: relative}}\n";
        BitSet low = where(q -> q.y() <= 5 + 1e-9);
        BitSet left = where(q -> q.x() <= 5 + 1e-9);
        BitSet union = (BitSet) low.clone();
        union.or(left);
        BitSet both = (BitSet) low.clone();
        both.and(left);
        BitSet lowOnly = (BitSet) low.clone();
        lowOnly.andNot(left);
        assertEquals(union, region(base + "  r: {union: [low, left]}\n", "r"));
        assertEquals(both, region(base + "  r: {intersection: [low, left]}\n", "r"));
        assertEquals(lowOnly, region(base + "  r: {difference: [low, left]}\n", "r"));
        // Regions may be named before they are defined.
        assertEquals(both, region("  r: {intersection: [low, left]}\n" + base, "r"));
    }

    @Test
    void checkReportsEachRegionsCountAndBox() {
        Scene s = SceneFiles.load(dir, "r.yaml", HEAD
                + "regions:\n  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}\n");
        String report = String.join("\n", SceneCheck.report(s));
        assertTrue(report.contains("body c (cube): 20 nodes, 84 springs, 6 rigid links"), report);
        assertTrue(report.contains("region top on c: 6 nodes in [0.00000, 10.0000, 0.00000]-[10.0000, 10.0000,"
                + " 10.0000] m"), report);
    }
}
