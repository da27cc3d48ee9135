package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;

/**
 * A body type added from outside the loader: a mesh's vertices as free nodes, read with declared units. The
 * loader, the regions, the conditions and the key checks serve it unchanged, and a mesh in other units than
 * declared is refused.
 */
class BodyTypePluginTest {
    @TempDir
    Path dir;

    static final Path MESH = Path.of("meshes/diaphragm-default.obj").toAbsolutePath();

    /** {@code type: points}: every vertex of {@code mesh} a node of {@code node_mass}, vertex v being node v. */
    static final class Points implements BodyType {
        @Override
        public String name() {
            return "points";
        }

        @Override
        public List<String> keys() {
            return List.of("mesh", "node_mass");
        }

        @Override
        public int[] build(BodyContext ctx, Topology t) {
            MeshCleaner.Result r = ctx.mesh(ctx.keys().required("mesh"), "diaphragm", 0.1, 0.6);
            double m = ctx.keys().positive("node_mass", QuantityKind.MASS, ctx.units(), 1e-3);
            TriangleMesh mesh = r.mesh();
            for (int v = 0; v < mesh.vertexCount(); v++) {
                t.addNode(mesh.coord(v, 0), mesh.coord(v, 1), mesh.coord(v, 2), m);
            }
            return null;
        }
    }

    @BeforeAll
    static void register() {
        BodyTypes.register(new Points());
    }

    /** The other tests see the built-in types only (the schema lists those). */
    @AfterAll
    static void unregister() {
        BodyTypes.unregister("points");
    }

    String scene(String units) {
        return "version: 1\nbodies:\n  d: {type: points, node_mass: 2 g, mesh: {file: " + MESH + ", units: " + units
                + "}}\nregions:\n  low: {box: {min: [0, 0, 0], max: [1, 1, 0.1], frame: relative}}\n"
                + "conditions: [{type: fixed, region: low}]\nrun: {dt: 1 ms, duration: 1 ms}\n";
    }

    @Test
    void aRegisteredTypeIsReadLikeTheBuiltInOnes() {
        Scene s = SceneFiles.load(dir, "p.yaml", scene("mm"));
        SceneBody d = s.bodies().get("d");
        assertEquals("points", d.type());
        assertTrue(d.topology().nodeCount() > 1000, "the mesh's vertices: " + d.topology().nodeCount());
        assertEquals(0.002, d.topology().node(0).mass(), 0);
        double[] b = d.bounds();
        assertTrue(b[3] - b[0] > 0.1 && b[3] - b[0] < 0.6, "read in mm, converted to m: " + (b[3] - b[0]));
        int low = s.regions().get("low").in("d").cardinality();
        assertTrue(low > 0 && low < d.topology().nodeCount());
        assertEquals(low, d.topology().nodes().stream().filter(org.tensim.model.Node::isFixed).count());
        assertNull(d.vertexNodes());
    }

    @Test
    void aMeshInOtherUnitsThanDeclaredIsRefused() {
        SceneException e = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "p.yaml", scene("m")));
        assertTrue(e.getMessage().startsWith("p.yaml:3:43: bodies.d.mesh: "), e.getMessage());
        assertTrue(e.getMessage().contains("the file is probably in millimetres: use units: mm"), e.getMessage());
        SceneException typo = assertThrows(SceneException.class, () -> SceneFiles.load(dir, "p.yaml",
                scene("mm").replace("node_mass", "node_mas")));
        assertTrue(typo.getMessage().contains("did you mean 'node_mass'?"), typo.getMessage());
    }
}
