package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.analysis.FlatMeshes;
import org.tensim.analysis.LinearStatics;
import org.tensim.analysis.ShellStatics;
import org.tensim.analysis.ShellStudy;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.ObjWriter;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.RigidLink;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.TissueModel;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The {@code shell} body type: a flat plate clamped at its rim under a uniform pressure, loaded from a scene file
 * (its rim fixed by a region and a condition), deflects at its centre as Kirchhoff's plate, p a^4 / (64 D), as the
 * project's plate study says the material model does; a pair of boundary surfaces gives the same shell as one
 * surface offset by their gap; a tensegrity zone makes the paper model's columns rigid.
 */
class ShellScenesTest {
    private static final ShellMaterial MUSCLE = new ShellMaterial(40e3, 1.0 / 3, 0.0025, 1060);
    private static final double RADIUS = ShellStudy.PLATE_RADIUS_M;

    @TempDir
    Path dir;

    private Path disc(String name, TriangleMesh m) throws IOException {
        Path f = dir.resolve(name);
        ObjWriter.write(f, m, MeshUnits.M, List.of("a flat disc"), 12);
        return f;
    }

    private Scene load(String yaml) throws IOException {
        Path f = dir.resolve("scene.yaml");
        Files.writeString(f, yaml);
        return SceneLoader.load(f);
    }

    private static String plateScene(String body, String model) {
        return "version: 1\n"
                + "bodies:\n"
                + "  plate:\n"
                + "    type: shell\n"
                + body
                + "    material: {E: 40 kPa, nu: 0.3333333333333333, density: 1060 kg/m^3}\n"
                + "    tissue_model: " + model + "\n"
                + "regions:\n"
                + "  all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}\n"
                + "  inside: {sphere: {centre: [0, 0, -1.25 mm], radius: " + (RADIUS - 1e-3) + " m}}\n"
                + "  rim: {difference: [all, inside]}\n"
                + "  centre: {sphere: {centre: [0, 0, 0], radius: 0.05 m}}\n"
                + "conditions:\n"
                + "  - {type: fixed, region: rim}\n"
                + "run: {dt: 1 ms, duration: 1 ms}\n";
    }

    /** The centre deflection of the scene's plate under p on its upper face, m (ShellStatics' load and solver). */
    private static double centreDeflection(Topology t, TriangleMesh flat, int rings, double pressurePa) {
        int n = t.nodeCount();
        int half = n / 2;
        double[] f = new double[3 * n];
        boolean[] fixed = new boolean[3 * n];
        for (int tr = 0; tr < flat.triangleCount(); tr++) {
            for (int k = 0; k < 3; k++) {
                f[3 * flat.corner(tr, k) + 2] -= pressurePa * flat.area(tr) / 3;
            }
        }
        int rim = 0;
        for (int v = 0; v < n; v++) {
            Node node = t.node(v);
            if (node.isFixed()) {
                rim++;
                fixed[3 * v] = true;
                fixed[3 * v + 1] = true;
                fixed[3 * v + 2] = true;
            }
        }
        assertEquals(2 * 6 * rings, rim, "the rim's nodes on both faces (6 x rings per face) are fixed");
        double[] u = LinearStatics.solve(t, fixed, f, ShellStatics.TOLERANCE).displacementM();
        return -(u[2] + u[3 * half + 2]) / 2;
    }

    @Test
    void aClampedPlateFromASceneFileDeflectsAsKirchhoffsPlate() throws IOException {
        int rings = 20;
        TriangleMesh flat = FlatMeshes.disc(rings, RADIUS);
        disc("disc.obj", flat);
        Scene s = load(plateScene("    surface: {file: disc.obj, units: m}\n    thickness: 2.5 mm\n", "material"));
        Topology t = s.bodies().get("plate").topology();
        assertEquals(2 * flat.vertexCount(), t.nodeCount());
        double w0 = centreDeflection(t, flat, rings, 1);
        ShellStatics.Case study = ShellStatics.plate(MUSCLE, TissueModel.MATERIAL, rings, RADIUS, 1);
        double kirchhoff = 1 * Math.pow(RADIUS, 4) / (64 * MUSCLE.bendingRigidityNm());
        assertEquals(kirchhoff, study.exact(), 1e-12 * kirchhoff);
        assertEquals(kirchhoff, w0, 0.01 * kirchhoff, "20 rings against Kirchhoff's p a^4 / (64 D)");
        // The same shell as the plate study builds in code (the file's coordinates carry 12 decimals).
        assertEquals(study.measured(), w0, 1e-6 * w0, "the body is the study's shell");
    }

    @Test
    void twoBoundarySurfacesGiveTheShellOfOneSurfaceOffsetByTheirGap() throws IOException {
        TriangleMesh flat = FlatMeshes.disc(6, RADIUS);
        TwoSurfaces offset = TwoSurfaces.offset(flat, MUSCLE.thicknessM());
        int nv = flat.vertexCount();
        double[] lowerXyz = java.util.Arrays.copyOfRange(offset.mesh().coordinates(), 3 * nv, 6 * nv);
        disc("upper.obj", flat);
        disc("lower.obj", new TriangleMesh(lowerXyz, flat.triangles()));
        for (String model : List.of("material", "paper")) {
            Scene a = load(plateScene("    surface: {file: upper.obj, units: m}\n    thickness: 2.5 mm\n", model));
            Scene b = load(plateScene("    upper: {file: upper.obj, units: m}\n    lower: {file: lower.obj, units:"
                    + " m}\n", model));
            Topology ta = a.bodies().get("plate").topology();
            Topology tb = b.bodies().get("plate").topology();
            assertEquals(ta.nodeCount(), tb.nodeCount());
            for (int v = 0; v < ta.nodeCount(); v++) {
                assertEquals(ta.node(v).position(), tb.node(v).position(), model + ": node " + v);
                assertEquals(ta.node(v).mass(), tb.node(v).mass(), 1e-12 * ta.node(v).mass(), model + ": mass " + v);
            }
            assertEquals(ta.springs().size(), tb.springs().size(), model + ": springs");
            for (int i = 0; i < ta.springs().size(); i++) {
                Spring x = ta.springs().get(i);
                Spring y = tb.springs().get(i);
                assertArrayEquals(new int[] {x.a(), x.b()}, new int[] {y.a(), y.b()}, model + ": spring " + i);
                assertEquals(x.stiffness(), y.stiffness(), 1e-9 * x.stiffness(), model + ": spring " + i);
                assertEquals(x.restLength(), y.restLength(), 1e-12, model + ": spring " + i);
            }
            assertEquals(ta.triangles().size(), tb.triangles().size(), model + ": membrane triangles");
            assertEquals(ta.shears().size(), tb.shears().size(), model + ": shear elements");
            assertEquals(links(ta), links(tb), model + ": rigid links");
            assertEquals(model.equals("material") ? nv : 0, ta.rigidLinks().size(), model + ": columns");
        }
    }

    private static List<List<Integer>> links(Topology t) {
        return t.rigidLinks().stream().map(l -> List.of(l.a(), l.b())).toList();
    }

    @Test
    void aTensegrityZoneMakesThePaperModelsColumnsRigidAsTheDiaphragmsTendon() throws IOException {
        TriangleMesh flat = FlatMeshes.disc(6, RADIUS);
        disc("disc.obj", flat);
        String zoned = plateScene("    surface: {file: disc.obj, units: m}\n    thickness: 2.5 mm\n", "paper")
                .replace("run:", "zones:\n  tendon: {region: centre, model: tensegrity}\nrun:");
        Topology t = load(zoned).bodies().get("plate").topology();
        int nv = flat.vertexCount();
        int inside = 0;
        for (int v = 0; v < nv; v++) {
            if (Math.hypot(flat.coord(v, 0), flat.coord(v, 1)) < 0.05 - 1.25e-3) {
                inside++;
            }
        }
        assertTrue(inside > 10, "the zone holds " + inside + " columns");
        assertEquals(inside, t.rigidLinks().size(), "one strut per column in the zone, disjoint");
        for (RigidLink l : t.rigidLinks()) {
            assertEquals(nv, Math.abs(l.b() - l.a()), "a column: a vertex and its offset copy");
            assertEquals(2.5e-3, l.length(), 1e-12, "across the thickness");
        }
        SceneException e = assertThrows(SceneException.class, () -> load(zoned.replace("tissue_model: paper",
                "tissue_model: material")));
        assertTrue(e.getMessage().contains("needs tissue_model: paper"), e.getMessage());
    }
}
